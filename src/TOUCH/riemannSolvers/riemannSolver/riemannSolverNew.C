/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "riemannSolver.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> riemannSolverEntry
    (
        "system/fvSolution TOUCH", "riemannSolver",
        "the face flux: contact momentum and traction from the two states",
        "-", word("acoustic"),
        entryLimits::selectedFrom(&entryLimits::tableNames<riemannSolver>),
        declaredEntry<word>::required
    );
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::riemannSolver> Foam::riemannSolver::New
(
    const dictionary& dict,
    const mechanicalLaw& law
)
{
    const word solverType(riemannSolverEntry.read(dict));

    Info<< "Selecting Riemann solver " << solverType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(solverType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "riemannSolver",
            solverType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<riemannSolver>(cstrIter()(dict, law));
}


// ************************************************************************* //
