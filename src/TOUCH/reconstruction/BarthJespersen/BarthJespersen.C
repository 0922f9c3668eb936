/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "BarthJespersen.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace gradientLimiters
{
    defineTypeNameAndDebug(BarthJespersen, 0);
    addToRunTimeSelectionTable(gradientLimiter, BarthJespersen, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gradientLimiters::BarthJespersen::limiter(const scalar r) const
{
    return min(scalar(1), r);
}


void Foam::gradientLimiters::BarthJespersen::factors
(
    scalar* r,
    const label n
) const
{
    for (label i = 0; i < n; ++i)
    {
        r[i] = min(scalar(1), r[i]);
    }
}


// ************************************************************************* //
