/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "acoustic.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace riemannSolvers
{
    defineTypeNameAndDebug(acoustic, 0);
    addToRunTimeSelectionTable(riemannSolver, acoustic, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::riemannSolvers::acoustic::acoustic
(
    const dictionary& dict,
    const mechanicalLaw& law
)
:
    riemannSolver(dict, law),
    // The first material's (the only one of a single law; the face loops
    // of several materials take interfaceFlux with each side's own)
    Up_(law.materialUp(0)),
    Us_(law.materialUs(0)),
    invUp_(1/Up_),
    invUs_(1/Us_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::riemannSolvers::acoustic::flux
(
    const vector& pL,
    const vector& tL,
    const vector& pR,
    const vector& tR,
    const vector& n,
    vector& pC,
    vector& tC
) const
{
    // Split the jumps into normal and tangential parts instead of forming
    // the two upwinding tensors: fewer operations per face
    const vector dp(pR - pL);
    const vector dt(tR - tL);
    const vector dpn((n & dp)*n);
    const vector dtn((n & dt)*n);

    tC = 0.5*(tL + tR) + 0.5*(Up_*dpn + Us_*(dp - dpn));
    pC = 0.5*(pL + pR) + 0.5*(invUp_*dtn + invUs_*(dt - dtn));
}


Foam::vector Foam::riemannSolvers::acoustic::upwindTraction
(
    const vector& dp,
    const vector& n
) const
{
    const vector dpn((n & dp)*n);

    return 0.5*(Up_*dpn + Us_*(dp - dpn));
}


// ************************************************************************* //
