/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "gradientLimiter.H"
#include "declaredEntry.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gradientLimiter, 0);
    defineRunTimeSelectionTable(gradientLimiter, dictionary);
}


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> limiterEntry
    (
        "system/fvSolution TOUCH/limitedLinearCoeffs", "limiter",
        "the gradient limiter",
        "-", word("BarthJespersen"),
        entryLimits::selectedFrom(&entryLimits::tableNames<gradientLimiter>),
        declaredEntry<word>::required
    );
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::gradientLimiter> Foam::gradientLimiter::New
(
    const dictionary& controls
)
{
    // The limiter belongs to the reconstruction limitedLinear
    const dictionary dict
    (
        modelCoeffs(controls, "limitedLinear", {&limiterEntry})
    );

    const word limiterType(limiterEntry.read(dict));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(limiterType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "limiter",
            limiterType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<gradientLimiter>(cstrIter()(dict));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gradientLimiter::factors(scalar* r, const label n) const
{
    for (label i = 0; i < n; ++i)
    {
        r[i] = min(scalar(1), limiter(r[i]));
    }
}


// ************************************************************************* //
