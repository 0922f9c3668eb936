/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "deformationUpdate.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> FUpdateEntry
    (
        "system/fvSolution TOUCH", "FUpdate",
        "how F and the momentum rate are formed: from the point motion"
        " (compatible) or from the faces' Riemann velocities (constrained,"
        " plain)",
        "-", word("compatible"),
        entryLimits::selectedFrom(&entryLimits::tableNames<deformationUpdate>)
    );
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::deformationUpdate> Foam::deformationUpdate::New
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
{
    const word updateType(FUpdateEntry.read(controls));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(updateType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            controls,
            "FUpdate",
            updateType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<deformationUpdate>
    (
        cstrIter()(controls, faces, law, riemann, reconstruction)
    );
}


// ************************************************************************* //
