/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "entryDeclaration.H"
#include "OStringStream.H"
#include "IOstreams.H"
#include "FlatOutput.H"
#include <algorithm>
#include <cctype>

// * * * * * * * * * * * * * * * entryLimits  * * * * * * * * * * * * * * * //

Foam::entryLimits::entryLimits
(
    const scalar lower,
    const scalar upper,
    const bool includeLower,
    const bool includeUpper,
    const wordList& choices,
    const choicesFunction function
)
:
    lower_(lower),
    upper_(upper),
    includeLower_(includeLower),
    includeUpper_(includeUpper),
    choices_(choices),
    choicesFunction_(function)
{}


Foam::entryLimits Foam::entryLimits::any()
{
    return entryLimits(-GREAT, GREAT, true, true, wordList(), nullptr);
}


Foam::entryLimits Foam::entryLimits::between
(
    const scalar lower,
    const scalar upper,
    const bool includeLower,
    const bool includeUpper
)
{
    return entryLimits
    (
        lower, upper, includeLower, includeUpper, wordList(), nullptr
    );
}


Foam::entryLimits Foam::entryLimits::above
(
    const scalar lower,
    const bool include
)
{
    return entryLimits(lower, GREAT, include, false, wordList(), nullptr);
}


Foam::entryLimits Foam::entryLimits::oneOf(const wordList& choices)
{
    return entryLimits(-GREAT, GREAT, true, true, choices, nullptr);
}


Foam::entryLimits Foam::entryLimits::selectedFrom
(
    const choicesFunction function
)
{
    return entryLimits(-GREAT, GREAT, true, true, wordList(), function);
}


bool Foam::entryLimits::bounded() const
{
    return lower_ > -GREAT || upper_ < GREAT;
}


bool Foam::entryLimits::contains(const scalar value) const
{
    const bool aboveLower = includeLower_ ? value >= lower_ : value > lower_;
    const bool belowUpper = includeUpper_ ? value <= upper_ : value < upper_;

    // A NaN is in no range
    return aboveLower && belowUpper;
}


Foam::wordList Foam::entryLimits::choices() const
{
    return choicesFunction_ ? choicesFunction_() : choices_;
}


Foam::string Foam::entryLimits::describe(const word& name) const
{
    OStringStream os;

    const wordList words(choices());
    if (words.size())
    {
        forAll(words, i)
        {
            os  << (i ? " | " : "") << words[i];
        }
    }
    else if (bounded())
    {
        if (lower_ > -GREAT)
        {
            os  << lower_ << (includeLower_ ? " <= " : " < ");
        }
        os  << name;
        if (upper_ < GREAT)
        {
            os  << (includeUpper_ ? " <= " : " < ") << upper_;
        }
    }

    return os.str();
}


// * * * * * * * * * * * * * * * entryDeclaration  * * * * * * * * * * * * * //

Foam::DynamicList<const Foam::entryDeclaration*>&
Foam::entryDeclaration::table()
{
    // Built on first use: declarations are static objects of several
    // translation units, constructed in an order C++ does not fix
    static DynamicList<const entryDeclaration*> declarations;
    return declarations;
}


Foam::entryDeclaration::entryDeclaration
(
    const string& where,
    const word& name,
    const string& meaning,
    const string& unit,
    const entryLimits& limits
)
:
    where_(where),
    name_(name),
    meaning_(meaning),
    unit_(unit),
    limits_(limits)
{
    table().append(this);
}


Foam::entryDeclaration::~entryDeclaration()
{
    DynamicList<const entryDeclaration*>& declarations = table();
    const label index = declarations.find(this);
    if (index >= 0)
    {
        declarations.remove(index);
    }
}


void Foam::entryDeclaration::outOfRange
(
    const dictionary& dict,
    const string& value
) const
{
    const bool range = limits_.choices().empty();

    FatalIOErrorInFunction(dict)
        << "Entry '" << name_ << "' = " << value.c_str() << " in "
        << dict.name() << (range ? " is out of range: valid values satisfy "
                                 : " is not valid: valid choices are ")
        << limits_.describe(name_).c_str() << nl
        << "    (" << name_ << ": " << meaning_.c_str() << ')' << nl
        << exit(FatalIOError);
}


void Foam::entryDeclaration::check
(
    const dictionary& dict,
    const scalar value
) const
{
    if (limits_.bounded() && !limits_.contains(value))
    {
        OStringStream os;
        os  << value;
        outOfRange(dict, os.str());
    }
}


void Foam::entryDeclaration::check
(
    const dictionary& dict,
    const word& value
) const
{
    const wordList words(limits_.choices());
    if (words.size() && !words.found(value))
    {
        outOfRange(dict, value);
    }
}


bool Foam::entryDeclaration::declared(const string& where, const word& name)
{
    for (const entryDeclaration* declaration : table())
    {
        if (declaration->where_ == where && declaration->name_ == name)
        {
            return true;
        }
    }

    return false;
}


Foam::wordList Foam::entryDeclaration::names(const string& where)
{
    DynamicList<word> found;
    for (const entryDeclaration* declaration : table())
    {
        if (declaration->where_ == where && !found.found(declaration->name_))
        {
            found.append(declaration->name_);
        }
    }

    wordList result(std::move(found));
    Foam::sort(result);
    return result;
}


Foam::wordList Foam::entryDeclaration::subDictionaries(const string& where)
{
    DynamicList<word> found;
    for (const entryDeclaration* declaration : table())
    {
        const string& w = declaration->where_;
        if
        (
            w.size() > where.size() + 1
         && w.compare(0, where.size(), where) == 0
         && (w[where.size()] == '/' || w[where.size()] == ' ')
        )
        {
            const word name(w.substr(where.size() + 1));
            if (!found.found(name))
            {
                found.append(name);
            }
        }
    }

    wordList result(std::move(found));
    Foam::sort(result);
    return result;
}


Foam::word Foam::entryDeclaration::nearest
(
    const word& name,
    const wordList& candidates
)
{
    // Levenshtein distance with one row, letters compared without case
    auto distance = [](const word& a, const word& b)
    {
        labelList row(b.size() + 1);
        forAll(row, j)
        {
            row[j] = j;
        }
        for (label i = 1; i <= label(a.size()); ++i)
        {
            label diagonal = row[0];
            row[0] = i;
            for (label j = 1; j <= label(b.size()); ++j)
            {
                const label above = row[j];
                const bool same =
                    std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
                row[j] =
                    min(min(row[j] + 1, row[j - 1] + 1), diagonal + !same);
                diagonal = above;
            }
        }
        return row[b.size()];
    };

    word best;
    label bestDistance = labelMax;
    for (const word& candidate : candidates)
    {
        const label d = distance(name, candidate);
        if (d < bestDistance)
        {
            best = candidate;
            bestDistance = d;
        }
    }

    // Near enough to be a misspelling: at most a third of the letters
    // differ (at least one)
    if (bestDistance > max(label(1), label(name.size())/3))
    {
        return word::null;
    }

    return best;
}


void Foam::entryDeclaration::checkEntries
(
    const dictionary& dict,
    const string& where,
    const wordList& also,
    const bool fatal
)
{
    wordList valid(names(where));
    for (const word& name : also)
    {
        if (!valid.found(name))
        {
            valid.append(name);
        }
    }

    for (const entry& e : dict)
    {
        const word key(e.keyword());
        if (valid.found(key))
        {
            continue;
        }

        // Where an entry of that name (or a sub-dictionary) is read
        DynamicList<string> elsewhere;
        for (const entryDeclaration* d : table())
        {
            const string& w = d->where_;
            const bool isSubDict =
                w.size() > key.size()
             && w.compare(w.size() - key.size(), key.size(), key) == 0
             && (w[w.size() - key.size() - 1] == ' '
              || w[w.size() - key.size() - 1] == '/');

            if ((d->name_ == key && w != where) || isSubDict)
            {
                const string place
                (
                    isSubDict ? string(w) : string(w + " (" + key + ')')
                );
                if (!elsewhere.found(place))
                {
                    elsewhere.append(place);
                }
            }
        }

        OStringStream os;
        os  << "Unknown entry '" << key << "' in " << dict.name().c_str();
        const word near(nearest(key, valid));
        if (!near.empty())
        {
            os  << ": did you mean '" << near << "'?";
        }
        os  << nl;
        if (elsewhere.size())
        {
            os  << "    '" << key << "' is read in another place or by"
                << " another model only:";
            for (const string& place : elsewhere)
            {
                os  << ' ' << place.c_str() << ';';
            }
            os  << nl;
        }
        os  << "    Valid entries here (" << where.c_str() << "): "
            << flatOutput(valid);

        if (fatal)
        {
            FatalIOErrorInFunction(dict)
                << os.str().c_str() << nl << exit(FatalIOError);
        }
        else
        {
            IOWarningInFunction(dict)
                << os.str().c_str() << nl
                << "    The entry is ignored" << endl;
        }
    }
}


Foam::List<const Foam::entryDeclaration*> Foam::entryDeclaration::sorted()
{
    List<const entryDeclaration*> declarations(table());

    std::stable_sort
    (
        declarations.begin(),
        declarations.end(),
        [](const entryDeclaration* a, const entryDeclaration* b)
        {
            return
                a->where_ < b->where_
             || (a->where_ == b->where_ && a->name_ < b->name_);
        }
    );

    return declarations;
}


void Foam::entryDeclaration::writeText(Ostream& os)
{
    string where;
    for (const entryDeclaration* d : sorted())
    {
        if (d->where_ != where)
        {
            where = d->where_;
            os  << nl << where.c_str() << nl;
        }

        const string defaultValue(d->defaultText());
        os  << "    " << d->name_.c_str()
            << "  [" << d->unit_.c_str() << "]  "
            << (defaultValue.empty() ? "required" : "default: ")
            << defaultValue.c_str();
        if (defaultValue.empty())
        {
            os  << " (example: " << d->exampleText().c_str() << ')';
        }

        const string valid(d->limits_.describe(d->name_));
        if (!valid.empty())
        {
            os  << "  valid: " << valid.c_str();
        }
        os  << nl << "        " << d->meaning_.c_str() << nl;
    }
}


void Foam::entryDeclaration::writeMarkdown(Ostream& os)
{
    os  << "# Entries touchFoam reads" << nl << nl
        << "Generated by `touchFoam -listEntries -markdown` from the"
        << " declarations in the source" << nl
        << "(`src/TOUCH/entries`): every entry the solver, its laws,"
        << " boundary conditions" << nl
        << "and function objects read, with its default (`required`"
        << " when it has none)." << nl
        << "Do not edit: regenerate it (`test/cases/entryDeclarations.py`"
        << " fails when it is stale)." << nl;

    string where;
    for (const entryDeclaration* d : sorted())
    {
        if (d->where_ != where)
        {
            where = d->where_;
            os  << nl << "## " << where.c_str() << nl << nl
                << "| Entry | Meaning | Unit | Default | Valid values"
                << " | Example |" << nl
                << "|---|---|---|---|---|---|" << nl;
        }

        const string defaultValue(d->defaultText());
        os  << "| `" << d->name_.c_str() << "` | " << d->meaning_.c_str()
            << " | " << d->unit_.c_str() << " | "
            << (defaultValue.empty() ? "required" : defaultValue.c_str())
            << " | " << d->limits_.describe(d->name_).c_str()
            << " | `" << d->name_.c_str() << ' '
            << d->exampleText().c_str() << ";` |" << nl;
    }
}


// ************************************************************************* //
