/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "historyElastic.H"
#include "zeroGradientFvPatchFields.H"
#include "addToRunTimeSelectionTable.H"
#include "declaredEntry.H"

#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(historyElastic, 0);
    addToRunTimeSelectionTable(mechanicalLaw, historyElastic, dictionary);
}

    //- Declared, so that mechanicalProperties may hold it while this test
    //  library is loaded (an undeclared entry is refused)
    static const declaredEntry<scalar> failAfterEntry
    (
        "constant/mechanicalProperties", "failAfter",
        "test law historyElastic: time after which the stress is NaN", "s",
        VGREAT
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaws::historyElastic::historyElastic
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    neoHookean(mesh, dict),
    failAfter_(failAfterEntry.read(dict)),
    maxStretch_
    (
        IOobject
        (
            "maxStretch",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("0", dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    maxStretch0_(maxStretch_.primitiveField()),
    maxStretchTrial_(maxStretch_.primitiveField())
{
    maxStretch_.correctBoundaryConditions();

    if (failAfter_ < VGREAT)
    {
        Info<< "historyElastic (test law): non-finite stress after time "
            << failAfter_ << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mechanicalLaws::historyElastic::stress
(
    const tensorField& F,
    tensorField& P
) const
{
    const scalarField& s = maxStretch_.primitiveField();

    forAll(F, celli)
    {
        P[celli] =
            softening(seen(s[celli], F[celli]))*neoHookean::P(F[celli]);
    }
}


void Foam::mechanicalLaws::historyElastic::correct
(
    const volTensorField& F,
    volTensorField& P
)
{
    const scalarField& s = maxStretch_.primitiveField();
    const tensorField& Fi = F.primitiveField();
    tensorField& Pi = P.primitiveFieldRef();

    forAll(Fi, celli)
    {
        maxStretchTrial_[celli] = seen(s[celli], Fi[celli]);
        Pi[celli] = softening(maxStretchTrial_[celli])*neoHookean::P(Fi[celli]);
    }

    if (mesh_.time().value() > failAfter_)
    {
        Info<< "historyElastic: time " << mesh_.time().value()
            << " > failAfter " << failAfter_ << ": non-finite stress" << endl;

        Pi = tensor::uniform(std::numeric_limits<scalar>::quiet_NaN());
    }

    P.correctBoundaryConditions();
}


Foam::scalar Foam::mechanicalLaws::historyElastic::totalStrainEnergy
(
    const volTensorField& F
) const
{
    const scalarField& V = mesh_.V();
    const scalarField& s = maxStretch_.primitiveField();
    scalar energy = 0;

    forAll(V, celli)
    {
        energy +=
            V[celli]*softening(seen(s[celli], F[celli]))
           *strainEnergy(F[celli]);
    }

    return returnReduce(energy, sumOp<scalar>());
}


void Foam::mechanicalLaws::historyElastic::storeOldTime()
{
    maxStretch0_ = maxStretch_.primitiveField();
}


void Foam::mechanicalLaws::historyElastic::advanceStage(const scalar alpha)
{
    scalarField& s = maxStretch_.primitiveFieldRef();

    forAll(s, celli)
    {
        s[celli] =
            alpha*maxStretch0_[celli] + (1 - alpha)*maxStretchTrial_[celli];
    }

    maxStretch_.correctBoundaryConditions();
}


void Foam::mechanicalLaws::historyElastic::commitStep
(
    const volTensorField&
)
{
    scalarField& s = maxStretch_.primitiveFieldRef();

    forAll(s, celli)
    {
        s[celli] = max(s[celli], maxStretch0_[celli]);
    }

    maxStretch_.correctBoundaryConditions();
}


void Foam::mechanicalLaws::historyElastic::restoreOldTime()
{
    maxStretch_.primitiveFieldRef() = maxStretch0_;
    maxStretch_.correctBoundaryConditions();
}


// ************************************************************************* //
