/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "skewSymmetricPlaneFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidFluxConditions::skewSymmetricPlane::flux
(
    const solidFluxFvPatchVectorField::interiorState& s,
    vectorField& pC,
    vectorField& tC
)
{
    forAll(pC, facei)
    {
        const vector& n = s.n[facei];
        const tensor nn(sqr(n));

        pC[facei] = nn & (s.p[facei] - s.t[facei]/s.Up[facei]);
        tC[facei] = (tensor::I - nn) & (s.t[facei] - s.Us[facei]*s.p[facei]);
    }
}


void Foam::solidFluxConditions::skewSymmetricPlane::constraint
(
    const solidFluxFvPatchVectorField::interiorState& s,
    tensorField& free,
    vectorField& velocity
)
{
    // The tangential velocity is zero, the normal one free
    forAll(free, facei)
    {
        free[facei] = sqr(s.n[facei]);
    }
    velocity = Zero;
}

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makeSolidFluxCondition(skewSymmetricPlane);
}

// ************************************************************************* //
