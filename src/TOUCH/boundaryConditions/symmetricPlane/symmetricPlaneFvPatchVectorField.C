/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "symmetricPlaneFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidFluxConditions::symmetricPlane::flux
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

        pC[facei] = (tensor::I - nn) & (s.p[facei] - s.t[facei]/s.Us[facei]);
        tC[facei] = nn & (s.t[facei] - s.Up[facei]*s.p[facei]);
    }
}


void Foam::solidFluxConditions::symmetricPlane::constraint
(
    const solidFluxFvPatchVectorField::interiorState& s,
    tensorField& free,
    vectorField& velocity
)
{
    // The normal velocity is zero, the tangential one free
    forAll(free, facei)
    {
        free[facei] = tensor::I - sqr(s.n[facei]);
    }
    velocity = Zero;
}

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makeSolidFluxCondition(symmetricPlane);
}

// ************************************************************************* //
