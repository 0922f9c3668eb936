/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "vonMisesPlastic.H"
#include "symmetricEigen.H"
#include <cstring>
#include "zeroGradientFvPatchFields.H"
#include "addToRunTimeSelectionTable.H"
#include "declaredEntry.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(vonMisesPlastic, 0);
    addToRunTimeSelectionTable(mechanicalLaw, vonMisesPlastic, dictionary);
}
}


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<scalar> yieldStressEntry
    (
        "constant/mechanicalProperties vonMisesPlasticCoeffs", "yieldStress",
        "initial yield stress", "Pa", 0.4e9,
        entryLimits::above(0, false), declaredEntry<scalar>::required
    );

    static const declaredEntry<scalar> hardeningModulusEntry
    (
        "constant/mechanicalProperties vonMisesPlasticCoeffs",
        "hardeningModulus", "linear isotropic hardening modulus", "Pa",
        0.1e9, entryLimits::above(0, true), declaredEntry<scalar>::required
    );

    static const declaredEntry<word> yieldStressMeasureEntry
    (
        "constant/mechanicalProperties vonMisesPlasticCoeffs",
        "yieldStressMeasure",
        "the stress the yield stress bounds: the Kirchhoff stress (the seed"
        " paper's) or the Cauchy stress (CalculiX's)",
        "-", word("Kirchhoff"), entryLimits::oneOf({"Kirchhoff", "Cauchy"})
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::mechanicalLaws::vonMisesPlastic::readYieldStressMeasure() const
{
    return yieldStressMeasureEntry.read(coeffs_) == "Cauchy";
}


Foam::scalar Foam::mechanicalLaws::vonMisesPlastic::elasticEnergy
(
    const symmTensor& tau,
    const scalar J
) const
{
    // tau' = 2 mu dev(ln V_e): mu |dev ln V_e|^2 = |tau'|^2/(4 mu)
    return magSqr(dev(tau))/(4*mu_) + 0.5*kappa_*sqr(Foam::log(J));
}


void Foam::mechanicalLaws::vonMisesPlastic::returnMapPresent
(
    const tensorField& F
) const
{
    // Bit for bit (Tensor's == allows VSMALL): the reuse must give exactly
    // what evaluating again would
    if
    (
        presentValid_
     && F.size() == presentF_.size()
     && std::memcmp(F.cdata(), presentF_.cdata(), F.byteSize()) == 0
    )
    {
        return;
    }

    const symmTensorField& CpInv = CpInv_.primitiveField();
    const scalarField& epsilonP = epsilonP_.primitiveField();
    presentF_ = F;

    forAll(F, celli)
    {
        returnMapping
        (
            F[celli], CpInv[celli], epsilonP[celli],
            presentTau_[celli], CpInvTrial_[celli], epsilonPTrial_[celli]
        );
    }

    presentValid_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaws::vonMisesPlastic::vonMisesPlastic
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mechanicalLaw(mesh, dict),
    coeffs_
    (
        modelCoeffs
        (
            *this,
            typeName,
            {
                &yieldStressEntry,
                &hardeningModulusEntry,
                &yieldStressMeasureEntry
            }
        )
    ),
    yieldStress_(yieldStressEntry.read(coeffs_)),
    hardeningModulus_(hardeningModulusEntry.read(coeffs_)),
    yieldOnCauchy_(readYieldStressMeasure()),
    CpInv_
    (
        IOobject
        (
            stateFieldName("CpInv"),
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedSymmTensor("I", dimless, symmTensor::I),
        zeroGradientFvPatchSymmTensorField::typeName
    ),
    epsilonP_
    (
        IOobject
        (
            stateFieldName("epsilonP"),
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("0", dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    CpInv0_(CpInv_.primitiveField()),
    epsilonP0_(epsilonP_.primitiveField()),
    CpInvBase_(CpInv_.primitiveField()),
    epsilonPBase_(epsilonP_.primitiveField()),
    CpInvTrial_(CpInv_.primitiveField()),
    epsilonPTrial_(epsilonP_.primitiveField()),
    firstStage_(true),
    presentTau_(mesh.nCells()),
    presentF_(mesh.nCells()),
    presentValid_(false),
    plasticWork_(mesh.nCells(), Zero)
{
    CpInv_.correctBoundaryConditions();
    epsilonP_.correctBoundaryConditions();

    Info<< "vonMisesPlastic: yield stress " << yieldStress_
        << " (on the " << (yieldOnCauchy_ ? "Cauchy" : "Kirchhoff")
        << " stress), hardening modulus " << hardeningModulus_
        << ", max equivalent plastic strain " << gMax(epsilonP_) << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


void Foam::mechanicalLaws::vonMisesPlastic::writeConstants(Ostream& os) const
{
    mechanicalLaw::writeConstants(os);
    os  << ", yieldStress " << yieldStress_ << ", hardeningModulus "
        << hardeningModulus_ << ", yieldStressMeasure "
        << (yieldOnCauchy_ ? "Cauchy" : "Kirchhoff");
}

void Foam::mechanicalLaws::vonMisesPlastic::elasticTrial
(
    const tensor& F,
    const symmTensor& CpInv,
    vector& lnLambda,
    vector& tauDev,
    tensor& n
) const
{
    // Elastic left Cauchy-Green tensor and its principal stretches
    vector lambdaSqr;
    symmetricEigen(transform(F, CpInv), lambdaSqr, n);

    lnLambda = vector
    (
        0.5*Foam::log(lambdaSqr.x()),
        0.5*Foam::log(lambdaSqr.y()),
        0.5*Foam::log(lambdaSqr.z())
    );

    // The deviator of the logarithmic stretches: traceless whatever
    // det Cp^-1 is (= ln lambda_i - ln J/3 when det Cp^-1 = 1)
    tauDev = 2*mu_*(lnLambda - (cmptSum(lnLambda)/3)*vector::one);
}


Foam::symmTensor Foam::mechanicalLaws::vonMisesPlastic::kirchhoff
(
    const vector& tauDev,
    const tensor& n,
    const tensor& F
) const
{
    return
        tauDev.x()*sqr(n.x()) + tauDev.y()*sqr(n.y()) + tauDev.z()*sqr(n.z())
      + kappa_*Foam::log(det(F))*symmTensor::I;
}


bool Foam::mechanicalLaws::vonMisesPlastic::returnMapping
(
    const tensor& F,
    const symmTensor& CpInv,
    const scalar epsilonP,
    symmTensor& tau,
    symmTensor& CpInvNew,
    scalar& epsilonPNew
) const
{
    vector lnLambda, tauDev;
    tensor n;
    elasticTrial(F, CpInv, lnLambda, tauDev, n);

    // A yield stress on the Cauchy stress tau/J bounds tau by J times it
    // (J = det F: the plastic flow is isochoric)
    const scalar scale = yieldOnCauchy_ ? det(F) : 1;
    const scalar tauEq = Foam::sqrt(1.5)*mag(tauDev);
    const scalar f =
        tauEq - scale*(yieldStress_ + hardeningModulus_*epsilonP);
    const bool plastic = (f > 0);

    if (plastic)
    {
        // Radial return along nu = sqrt(3/2) tau'/|tau'| = (3/2) tau'/tauEq
        const scalar dgamma = f/(3*mu_ + scale*hardeningModulus_);
        const vector lnLambdaE(lnLambda - (1.5*dgamma/tauEq)*tauDev);

        tauDev *= 1 - 3*mu_*dgamma/tauEq;
        epsilonPNew = epsilonP + dgamma;

        const symmTensor beNew
        (
            Foam::exp(2*lnLambdaE.x())*sqr(n.x())
          + Foam::exp(2*lnLambdaE.y())*sqr(n.y())
          + Foam::exp(2*lnLambdaE.z())*sqr(n.z())
        );
        // Isochoric to rounding; made unimodular so that rounding does not
        // accumulate over many plastic steps
        CpInvNew = transform(inv(F), beNew);
        CpInvNew /= Foam::cbrt(det(CpInvNew));
    }
    else
    {
        CpInvNew = CpInv;
        epsilonPNew = epsilonP;
    }

    tau = kirchhoff(tauDev, n, F);

    return plastic;
}


Foam::tensor Foam::mechanicalLaws::vonMisesPlastic::P(const tensor& F) const
{
    vector lnLambda, tauDev;
    tensor n;
    elasticTrial(F, symmTensor::I, lnLambda, tauDev, n);

    return kirchhoff(tauDev, n, F) & inv(F).T();
}


Foam::scalar Foam::mechanicalLaws::vonMisesPlastic::strainEnergy
(
    const tensor& F
) const
{
    vector lnLambda, tauDev;
    tensor n;
    elasticTrial(F, symmTensor::I, lnLambda, tauDev, n);

    return elasticEnergy(kirchhoff(tauDev, n, F), det(F));
}


void Foam::mechanicalLaws::vonMisesPlastic::stress
(
    const tensorField& F,
    tensorField& P
) const
{
    const symmTensorField& CpInv = CpInv_.primitiveField();
    const scalarField& epsilonP = epsilonP_.primitiveField();
    symmTensor tau, CpInvNew;
    scalar epsilonPNew;

    forAll(F, celli)
    {
        returnMapping
        (
            F[celli], CpInv[celli], epsilonP[celli], tau, CpInvNew, epsilonPNew
        );
        P[celli] = tau & inv(F[celli]).T();
    }
}


void Foam::mechanicalLaws::vonMisesPlastic::correct
(
    const volTensorField& F,
    volTensorField& P
)
{
    // The first stage of a step return-maps the present state to F^n; the
    // later stages return-map that state (the base) to their own F
    const tensorField& Fi = F.primitiveField();
    tensorField& Pi = P.primitiveFieldRef();

    if (firstStage_)
    {
        returnMapPresent(Fi);

        forAll(Fi, celli)
        {
            Pi[celli] = presentTau_[celli] & inv(Fi[celli]).T();
        }

        CpInvBase_ = CpInvTrial_;
        epsilonPBase_ = epsilonPTrial_;
        firstStage_ = false;
    }
    else
    {
        presentValid_ = false;
        symmTensor tau;

        forAll(Fi, celli)
        {
            returnMapping
            (
                Fi[celli], CpInvBase_[celli], epsilonPBase_[celli],
                tau, CpInvTrial_[celli], epsilonPTrial_[celli]
            );
            Pi[celli] = tau & inv(Fi[celli]).T();
        }
    }

    P.correctBoundaryConditions();
}


Foam::scalar Foam::mechanicalLaws::vonMisesPlastic::totalStrainEnergy
(
    const volTensorField& F
) const
{
    const scalarField& V = mesh_.V();
    const tensorField& Fi = F.primitiveField();
    scalar energy = 0;

    returnMapPresent(Fi);

    forAll(V, celli)
    {
        energy += V[celli]*elasticEnergy(presentTau_[celli], det(Fi[celli]));
    }

    return returnReduce(energy, sumOp<scalar>());
}


void Foam::mechanicalLaws::vonMisesPlastic::cellStrainEnergy
(
    const volTensorField& F,
    scalarField& energy
) const
{
    const scalarField& V = mesh_.V();
    const tensorField& Fi = F.primitiveField();

    returnMapPresent(Fi);

    forAll(V, celli)
    {
        energy[celli] =
            V[celli]*elasticEnergy(presentTau_[celli], det(Fi[celli]));
    }
}


void Foam::mechanicalLaws::vonMisesPlastic::storeOldTime()
{
    CpInv0_ = CpInv_.primitiveField();
    epsilonP0_ = epsilonP_.primitiveField();
    firstStage_ = true;
}


void Foam::mechanicalLaws::vonMisesPlastic::advanceStage(const scalar)
{
    // The state of the stage's return mapping, not alpha s^n + (1 - alpha)
    // s~: see the class description
    CpInv_.primitiveFieldRef() = CpInvTrial_;
    epsilonP_.primitiveFieldRef() = epsilonPTrial_;
    presentValid_ = false;
    CpInv_.correctBoundaryConditions();
    epsilonP_.correctBoundaryConditions();
}


void Foam::mechanicalLaws::vonMisesPlastic::commitStep
(
    const volTensorField& F
)
{
    const tensorField& Fi = F.primitiveField();
    symmTensorField& CpInv = CpInv_.primitiveFieldRef();
    scalarField& epsilonP = epsilonP_.primitiveFieldRef();
    symmTensor tau;

    forAll(Fi, celli)
    {
        returnMapping
        (
            Fi[celli], CpInvBase_[celli], epsilonPBase_[celli],
            tau, CpInv[celli], epsilonP[celli]
        );

        // The work of the step's flow (the class description)
        const scalar increment = epsilonP[celli] - epsilonP0_[celli];
        if (increment > 0)
        {
            plasticWork_[celli] +=
                (yieldOnCauchy_ ? det(Fi[celli]) : 1)
               *(
                    yieldStress_
                  + 0.5*hardeningModulus_
                   *(epsilonP0_[celli] + epsilonP[celli])
                )
               *increment;
        }
    }

    presentValid_ = false;
    CpInv_.correctBoundaryConditions();
    epsilonP_.correctBoundaryConditions();
    firstStage_ = true;
}


void Foam::mechanicalLaws::vonMisesPlastic::restoreOldTime()
{
    CpInv_.primitiveFieldRef() = CpInv0_;
    epsilonP_.primitiveFieldRef() = epsilonP0_;
    presentValid_ = false;
    CpInv_.correctBoundaryConditions();
    epsilonP_.correctBoundaryConditions();
    firstStage_ = true;
}


// ************************************************************************* //
