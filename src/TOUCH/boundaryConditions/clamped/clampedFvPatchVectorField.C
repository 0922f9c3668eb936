/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "clampedFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidFluxConditions::clamped::flux
(
    const solidFluxFvPatchVectorField::interiorState& s,
    vectorField& pC,
    vectorField& tC
)
{
    solidFluxFvPatchVectorField::momentumFlux
    (
        s,
        vectorField(pC.size(), Zero),
        pC,
        tC
    );
}


void Foam::solidFluxConditions::clamped::constraint
(
    const solidFluxFvPatchVectorField::interiorState&,
    tensorField& free,
    vectorField& velocity
)
{
    // Every direction fixed, at rest
    free = Zero;
    velocity = Zero;
}

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makeSolidFluxCondition(clamped);
}

// ************************************************************************* //
