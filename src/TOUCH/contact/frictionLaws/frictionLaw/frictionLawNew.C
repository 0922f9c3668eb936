/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "frictionLaw.H"
#include "declaredEntry.H"
#include "frictionless.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const describedEntry frictionEntry
    (
        "0/U (or 0/lm) boundaryField, contact condition"
        " (rigidWall, bodyContact)",
        "friction",
        "the friction law of the contact, a sub-dictionary (absent:"
        " frictionless)",
        "-", "frictionless", "{ type coulomb; muStatic 0.3; muKinetic 0.25; }"
    );

    static const declaredEntry<word> frictionTypeEntry
    (
        frictionLaw::where, "type",
        "the friction law of the contact (no 'friction' sub-dictionary:"
        " frictionless)",
        "-", word("coulomb"),
        entryLimits::selectedFrom(&entryLimits::tableNames<frictionLaw>),
        declaredEntry<word>::required
    );
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::frictionLaw> Foam::frictionLaw::New
(
    const dictionary& conditionDict
)
{
    const entry* ePtr = conditionDict.findEntry(frictionEntry.name(), keyType::LITERAL);

    if (!ePtr)
    {
        return autoPtr<frictionLaw>
        (
            new frictionLaws::frictionless(dictionary())
        );
    }

    if (!ePtr->isDict())
    {
        FatalIOErrorInFunction(conditionDict)
            << "Entry 'friction' in " << conditionDict.name()
            << " is not a sub-dictionary: give"
            << " friction { type <law>; ... } with a law of "
            << entryLimits::tableNames<frictionLaw>() << nl
            << exit(FatalIOError);
    }

    const dictionary& dict = ePtr->dict();
    const word lawType(frictionTypeEntry.read(dict));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "friction law",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    // The entries of the selected law and 'type', nothing else: a
    // coefficient of another law or a misspelt one is refused
    entryDeclaration::checkEntries
    (
        dict,
        string(where) + ", type " + lawType,
        wordList({frictionTypeEntry.name()})
    );

    return autoPtr<frictionLaw>(cstrIter()(dict));
}


// ************************************************************************* //
