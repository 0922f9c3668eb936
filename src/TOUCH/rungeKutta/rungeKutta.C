/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "rungeKutta.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> timeSchemeEntry
    (
        "system/fvSolution TOUCH", "timeScheme",
        "strong-stability-preserving Runge-Kutta scheme: RK2 (two-stage"
        " TVD) or RK3 (three-stage, Shu and Osher)",
        "-", word("RK2"), entryLimits::oneOf({"RK2", "RK3"})
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalarList Foam::rungeKutta::weights
(
    const dictionary& controls,
    const word& name
)
{
    if (name == "RK2")
    {
        return scalarList({0, 0.5});
    }
    if (name == "RK3")
    {
        return scalarList({0, 0.75, 1.0/3.0});
    }

    FatalIOErrorInFunction(controls)
        << "Entry 'timeScheme' = " << name << " in " << controls.name()
        << " is not a Runge-Kutta scheme" << nl
        << "Valid timeScheme names: 2(RK2 RK3)" << nl
        << exit(FatalIOError);

    return scalarList();
}


Foam::scalarList Foam::rungeKutta::stageTimes(const scalarList& alpha)
{
    scalarList c(alpha.size(), Zero);
    for (label k = 1; k < alpha.size(); ++k)
    {
        c[k] = (1 - alpha[k - 1])*(c[k - 1] + 1);
    }
    return c;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rungeKutta::rungeKutta(const dictionary& controls)
:
    name_(timeSchemeEntry.read(controls)),
    alpha_(weights(controls, name_)),
    c_(stageTimes(alpha_))
{}


// ************************************************************************* //
