/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "modelCoeffs.H"
#include "OStringStream.H"
#include "FlatOutput.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The names of the sub-dictionaries modelCoeffs has read
static wordHashSet& coeffsRead()
{
    static wordHashSet names;
    return names;
}

} // End namespace Foam

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::word Foam::modelCoeffsName(const word& model)
{
    return model + "Coeffs";
}


Foam::dictionary Foam::modelCoeffs
(
    const dictionary& dict,
    const word& model,
    std::initializer_list<const entryDeclaration*> entries
)
{
    const word coeffsName(modelCoeffsName(model));

    // An entry left flat (its place before 2026-12-04) would be ignored
    for (const entryDeclaration* e : entries)
    {
        if (dict.found(e->name(), keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << e->name() << "' of " << model
                << " is read from its sub-dictionary " << coeffsName
                << ", not from " << dict.name().c_str()
                << " itself (its place before 2026-12-04): move it"
                << nl << nl << "    " << coeffsName << nl << "    {" << nl
                << "        " << e->name() << " ...;" << nl << "    }" << nl
                << exit(FatalIOError);
        }
    }

    const entry* eptr = dict.findEntry(coeffsName, keyType::LITERAL);

    coeffsRead().insert(coeffsName);

    if (eptr && eptr->isDict())
    {
        // Every entry is one of the model's: a misspelt optional one would
        // otherwise be ignored
        wordList names;
        string where;
        for (const entryDeclaration* e : entries)
        {
            names.append(e->name());
            where = e->where();
        }
        entryDeclaration::checkEntries(eptr->dict(), where, names);

        return eptr->dict();
    }

    if (eptr)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << coeffsName << "' in " << dict.name().c_str()
            << " is not a sub-dictionary: it holds the entries of "
            << model << nl << exit(FatalIOError);
    }

    wordList required;
    for (const entryDeclaration* e : entries)
    {
        if (e->defaultText().empty())
        {
            required.append(e->name());
        }
    }

    if (required.size())
    {
        OStringStream example;
        for (const entryDeclaration* e : entries)
        {
            example
                << "        " << e->name() << ' '
                << e->exampleText().c_str() << ';' << nl;
        }

        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary " << coeffsName << " in "
            << dict.name().c_str() << ": " << model << " reads its required"
            << " entries " << flatOutput(required) << " from it, e.g."
            << nl << nl << "    " << coeffsName << nl << "    {" << nl
            << example.str().c_str() << "    }" << nl
            << exit(FatalIOError);
    }

    // Optional entries only: the defaults, in a dictionary named as the
    // sub-dictionary would be (errors name it)
    return dictionary(dict, dictionary(fileName(coeffsName)));
}


void Foam::checkUnusedCoeffs
(
    const dictionary& dict,
    const string& where,
    const string& selectedBy
)
{
    const string prefix(where + '/');
    for (const entryDeclaration* d : entryDeclaration::sorted())
    {
        if (d->where().compare(0, prefix.size(), prefix) != 0)
        {
            continue;
        }
        const word coeffsName(d->where().substr(prefix.size()));
        if (dict.isDict(coeffsName) && !coeffsRead().found(coeffsName))
        {
            coeffsRead().insert(coeffsName);
            // A note, not a warning: the tutorials keep the entries of
            // the models they can switch to
            Info<< "Note: sub-dictionary " << coeffsName << " in "
                << dict.name().c_str() << " is not read: its model ("
                << word(coeffsName.substr(0, coeffsName.size() - 6))
                << ") is not selected by " << selectedBy.c_str()
                << "; its entries are not checked" << endl;
        }
    }
}


// ************************************************************************* //
