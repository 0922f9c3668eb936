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


Foam::scalar Foam::deformationUpdates::constrained::stableCFL
(
    const word& timeScheme
) const
{
    // Twisting column 4 x 24 x 4, nu 0.45, RK2: the energy grows by at
    // most 4.4e-4 E0 in a step up to CFL 0.6, 9.5e-4 at 0.7, 1.6e-3 at
    // 0.8 and 5.3 E0 at 0.9, the former limit
    // (validation/stabilityMap/FINDINGS.md 12); RK3 runs to 0.3 s at 1.0
    return timeScheme == "RK3" ? 1.0 : 0.6;
}


// ************************************************************************* //
