/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "mechanicalLaw.H"
#include "zoned.H"
#include "fvMesh.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mechanicalLaw, 0);
    defineRunTimeSelectionTable(mechanicalLaw, dictionary);
}


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<scalar> rhoEntry
    (
        "constant/mechanicalProperties", "rho", "reference density", "kg/m^3", 1100,
        entryLimits::above(0, false), declaredEntry<scalar>::required
    );

    static const declaredEntry<scalar> EEntry
    (
        "constant/mechanicalProperties", "E", "Young's modulus", "Pa", 17e6,
        entryLimits::above(0, false), declaredEntry<scalar>::required
    );

    static const declaredEntry<scalar> nuEntry
    (
        "constant/mechanicalProperties", "nu", "Poisson's ratio", "-", 0.45,
        entryLimits::between(-1, 0.5, false, false),
        declaredEntry<scalar>::required
    );
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The law's entries under the name of constant/mechanicalProperties, so
//  that an error names the file also for a dictionary made in code (unit
//  tests), which has none
static dictionary asMechanicalProperties
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    dictionary named(dict);
    if (named.name().empty())
    {
        named.name() = mesh.time().constant()/"mechanicalProperties";
    }
    return named;
}


//- The cellZone whose material dict is (its keyword inside 'materials',
//  zoned), or empty for the law of the whole mesh
static word zoneOf(const dictionary& dict)
{
    const dictionary& parent = dict.parent();

    if
    (
        &parent != &dictionary::null
     && parent.dictName() == mechanicalLaws::zoned::materialsKeyword()
    )
    {
        return dict.dictName();
    }
    return word::null;
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaw::mechanicalLaw
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    IOdictionary
    (
        IOobject
        (
            "mechanicalProperties",
            mesh.time().constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        asMechanicalProperties(mesh, dict)
    ),
    mesh_(mesh),
    rho_(rhoEntry.read(*this)),
    E_(EEntry.read(*this)),
    nu_(nuEntry.read(*this)),
    mu_(E_/(2*(1 + nu_))),
    lambda_(E_*nu_/((1 + nu_)*(1 - 2*nu_))),
    kappa_(lambda_ + 2*mu_/3),
    Up_(Foam::sqrt((lambda_ + 2*mu_)/rho_)),
    Us_(Foam::sqrt(mu_/rho_)),
    cellMaterial_(),
    materialRho_(1, rho_),
    materialUp_(1, Up_),
    materialUs_(1, Us_),
    zoneName_(zoneOf(dict))
{}


Foam::mechanicalLaw::mechanicalLaw
(
    const fvMesh& mesh,
    const dictionary& dict,
    const scalar rho,
    const scalar E,
    const scalar nu
)
:
    IOdictionary
    (
        IOobject
        (
            "mechanicalProperties",
            mesh.time().constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        asMechanicalProperties(mesh, dict)
    ),
    mesh_(mesh),
    rho_(rho),
    E_(E),
    nu_(nu),
    mu_(E_/(2*(1 + nu_))),
    lambda_(E_*nu_/((1 + nu_)*(1 - 2*nu_))),
    kappa_(lambda_ + 2*mu_/3),
    Up_(Foam::sqrt((lambda_ + 2*mu_)/rho_)),
    Us_(Foam::sqrt(mu_/rho_)),
    zoneName_()
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::word Foam::mechanicalLaw::stateFieldName(const word& name) const
{
    return zoneName_.empty() ? name : word(name + '.' + zoneName_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


void Foam::mechanicalLaw::writeConstants(Ostream& os) const
{
    os  << type() << ": rho " << rho_ << ", E " << E_ << ", nu " << nu_;
}

void Foam::mechanicalLaw::checkUniform(const char* what) const
{
    if (!cellMaterial_.empty())
    {
        FatalErrorInFunction
            << "The law of several materials has no single " << what
            << ": the caller must take the cell's (" << what << "(celli))"
            << abort(FatalError);
    }
}


Foam::tmp<Foam::scalarField> Foam::mechanicalLaw::cellRho() const
{
    if (cellMaterial_.empty())
    {
        return tmp<scalarField>::New(mesh_.nCells(), rho_);
    }

    auto tRho = tmp<scalarField>::New(mesh_.nCells());
    scalarField& rho = tRho.ref();
    forAll(rho, celli)
    {
        rho[celli] = materialRho_[cellMaterial_[celli]];
    }
    return tRho;
}


void Foam::mechanicalLaw::stress(const tensorField& F, tensorField& P) const
{
    forAll(F, celli)
    {
        P[celli] = this->P(F[celli]);
    }
}


void Foam::mechanicalLaw::correct(const volTensorField& F, volTensorField& P)
{
    stress(F.primitiveField(), P.primitiveFieldRef());

    // Non-coupled boundary values are not used by the scheme; the processor
    // values must be exchanged so neighbours see the same stress as in serial
    P.correctBoundaryConditions();
}


void Foam::mechanicalLaw::stress
(
    const tensorField& F,
    const tensorField& gradD,
    tensorField& P
) const
{
    if (hasState())
    {
        stress(F, P);
        return;
    }

    forAll(F, celli)
    {
        P[celli] = this->P(F[celli], gradD[celli]);
    }
}


void Foam::mechanicalLaw::correct
(
    const volTensorField& F,
    const tensorField& gradD,
    volTensorField& P
)
{
    if (hasState())
    {
        correct(F, P);
        return;
    }

    stress(F.primitiveField(), gradD, P.primitiveFieldRef());
    P.correctBoundaryConditions();
}


Foam::scalar Foam::mechanicalLaw::volumetricEnergy(const scalar) const
{
    FatalErrorInFunction
        << "Model " << type() << " has no volumetric part of J alone"
        << exit(FatalError);

    return 0;
}


Foam::scalar Foam::mechanicalLaw::volumetricStress(const scalar) const
{
    FatalErrorInFunction
        << "Model " << type() << " has no volumetric part of J alone"
        << exit(FatalError);

    return 0;
}


Foam::scalar Foam::mechanicalLaw::totalStrainEnergy
(
    const volTensorField& F
) const
{
    const scalarField& V = mesh_.V();
    scalar energy = 0;

    forAll(V, celli)
    {
        energy += V[celli]*strainEnergy(F[celli]);
    }

    return returnReduce(energy, sumOp<scalar>());
}


void Foam::mechanicalLaw::cellStrainEnergy
(
    const volTensorField& F,
    scalarField& energy
) const
{
    const scalarField& V = mesh_.V();

    forAll(V, celli)
    {
        energy[celli] = V[celli]*strainEnergy(F[celli]);
    }
}


Foam::scalar Foam::mechanicalLaw::totalStrainEnergy
(
    const volTensorField& F,
    const tensorField& gradD
) const
{
    if (hasState())
    {
        return totalStrainEnergy(F);
    }

    const scalarField& V = mesh_.V();
    scalar energy = 0;

    forAll(V, celli)
    {
        energy += V[celli]*strainEnergy(F[celli], gradD[celli]);
    }

    return returnReduce(energy, sumOp<scalar>());
}


void Foam::mechanicalLaw::cellStrainEnergy
(
    const volTensorField& F,
    const tensorField& gradD,
    scalarField& energy
) const
{
    if (hasState())
    {
        cellStrainEnergy(F, energy);
        return;
    }

    const scalarField& V = mesh_.V();

    forAll(V, celli)
    {
        energy[celli] = V[celli]*strainEnergy(F[celli], gradD[celli]);
    }
}


// ************************************************************************* //
