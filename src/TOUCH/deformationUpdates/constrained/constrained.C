/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "constrained.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace deformationUpdates
{
    defineTypeNameAndDebug(constrained, 0);
    addToRunTimeSelectionTable(deformationUpdate, constrained, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdates::constrained::constrained
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    riemannUpdate(controls, faces, law, riemann, reconstruction)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformationUpdates::constrained::rates
(
    const label stage,
    vectorField& lmRate,
    tensorField& FRate,
    vectorField& pointV,
    vector& torque
)
{
    momentumRates(stage, lmRate, pointV, torque);
    addFaceMeanFRate(pointV, FRate);
}


// ************************************************************************* //
