/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "Venkatakrishnan.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace gradientLimiters
{
    defineTypeNameAndDebug(Venkatakrishnan, 0);
    addToRunTimeSelectionTable(gradientLimiter, Venkatakrishnan, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gradientLimiters::Venkatakrishnan::limiter(const scalar r) const
{
    // The form in 1/r for r > 1 stays finite as r grows without bound
    if (r > 1)
    {
        const scalar s = 1/r;
        return (1 + 2*s)/(1 + s + 2*sqr(s));
    }

    return (sqr(r) + 2*r)/(sqr(r) + r + 2);
}


// ************************************************************************* //
