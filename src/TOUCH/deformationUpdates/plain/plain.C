/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "plain.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace deformationUpdates
{
    defineTypeNameAndDebug(plain, 0);
    addToRunTimeSelectionTable(deformationUpdate, plain, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdates::plain::plain
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

void Foam::deformationUpdates::plain::rates
(
    const label stage,
    vectorField& lmRate,
    tensorField& FRate,
    vectorField& pointV,
    vector& torque
)
{
    momentumRates(stage, lmRate, pointV, torque);

    const vectorField& Sf = faces_.mesh().faceAreas();

    faces_.forAllFaces
    (
        [&](const label facei, const label own, const label nei)
        {
            const tensor flux(faceVelocity_[facei]*Sf[facei]);
            FRate[own] += flux;
            if (nei >= 0)
            {
                FRate[nei] -= flux;
            }
        }
    );
}


// ************************************************************************* //
