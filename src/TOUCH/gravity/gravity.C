/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

\*---------------------------------------------------------------------------*/

#include "gravity.H"
#include "uniformDimensionedFields.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * * Entry declarations  * * * * * * * * * * * * //

namespace Foam
{
    static const describedEntry gravityEntry
    (
        "constant/g", "value",
        "the acceleration of gravity, a uniformDimensionedVectorField with"
        " dimensions [0 1 -2 0 0 0 0] as OpenFOAM's solvers read it (no"
        " file: no gravity)",
        "m/s^2", "", "(0 -9.81 0)"
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gravity::gravity
(
    const fvMesh& mesh,
    const vector& g,
    const scalarField& rho
)
:
    g_(g),
    weight_(rho*mesh.V().field()*g)
{}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::gravity> Foam::gravity::New
(
    const fvMesh& mesh,
    const scalarField& rho
)
{
    IOobject io
    (
        "g",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (!io.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        return nullptr;
    }

    // Read as OpenFOAM's solvers read it; the dimensions are checked
    const uniformDimensionedVectorField g(io);
    if (g.dimensions() != dimAcceleration)
    {
        FatalErrorInFunction
            << "The gravity '" << gravityEntry.name() << "' in "
            << g.objectPath() << " has dimensions " << g.dimensions()
            << "; an acceleration, " << dimAcceleration
            << " [m/s^2], is expected" << exit(FatalError);
    }

    return autoPtr<gravity>::New(mesh, g.value(), rho);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gravity::addRates
(
    const vectorField& x,
    vectorField& lmRate,
    vector& torque
) const
{
    forAll(lmRate, celli)
    {
        lmRate[celli] += weight_[celli];
        torque += x[celli] ^ weight_[celli];
    }
}


Foam::scalar Foam::gravity::potentialEnergy(const vectorField& x) const
{
    scalar sum = 0;
    forAll(x, celli)
    {
        sum -= weight_[celli] & x[celli];
    }
    return returnReduce(sum, sumOp<scalar>());
}


void Foam::gravity::writeSummary(Ostream& os) const
{
    os  << "    gravity         g " << g_ << " m/s^2 (constant/g)" << nl;
}


// ************************************************************************* //
