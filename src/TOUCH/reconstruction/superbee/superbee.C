/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "superbee.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace gradientLimiters
{
    defineTypeNameAndDebug(superbee, 0);
    addToRunTimeSelectionTable(gradientLimiter, superbee, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gradientLimiters::superbee::limiter(const scalar r) const
{
    return min(scalar(1), r);
}


void Foam::gradientLimiters::superbee::factors
(
    scalar* r,
    const scalar* R,
    const label n
) const
{
    for (label i = 0; i < n; ++i)
    {
        // R/2 is at most 2 in 1D (the larger one-sided difference over
        // their mean); the cap keeps a component whose increment is
        // barely above the tolerance from being steepened to its bounds.
        // Where nothing is asked both ratios are GREAT and the factor is 1
        r[i] =
            r[i] < 0.5*GREAT
          ? min(r[i], max(scalar(1), min(0.5*R[i], scalar(2))))
          : scalar(1);
    }
}


// ************************************************************************* //
