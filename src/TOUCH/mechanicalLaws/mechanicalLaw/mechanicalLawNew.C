/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "mechanicalLaw.H"
#include "declaredEntry.H"
#include "modelCoeffs.H"
#include "fvMesh.H"
#include "zoned.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> modelEntry
    (
        "constant/mechanicalProperties", "model", "the constitutive law",
        "-", word("neoHookean"),
        entryLimits::selectedFrom(&entryLimits::tableNames<mechanicalLaw>),
        declaredEntry<word>::required
    );
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::mechanicalLaw> Foam::mechanicalLaw::New
(
    const fvMesh& mesh
)
{
    // Read once, unregistered, only to find the model's name
    const IOdictionary dict
    (
        IOobject
        (
            "mechanicalProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    return New(mesh, dict);
}


Foam::autoPtr<Foam::mechanicalLaw> Foam::mechanicalLaw::New
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    // One law per cellZone: the single law's entries beside it are refused
    // (which would win is not for the reader to guess); other top-level
    // entries (variables for $-expansion, #include'd options) stay allowed
    if (dict.found(mechanicalLaws::zoned::materialsKeyword()))
    {
        wordList flat;
        for (const entry& e : dict)
        {
            const word& key = e.keyword();
            if
            (
                key == modelEntry.name() || key == "rho" || key == "E"
             || key == "nu" || key.endsWith("Coeffs")
            )
            {
                flat.append(key);
            }
        }
        if (flat.size())
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << mechanicalLaws::zoned::materialsKeyword()
                << "' (one law per cellZone) given with the single law's"
                << " entries " << flat << ": use one form, the flat one ("
                << modelEntry.name() << ", rho, E, nu, <model>Coeffs) for"
                << " one material, or '"
                << mechanicalLaws::zoned::materialsKeyword()
                << "' with these entries inside each zone's sub-dictionary"
                << exit(FatalIOError);
        }

        Info<< "Selecting mechanical law " << mechanicalLaws::zoned::typeName
            << " (one law per cellZone)" << endl;

        return autoPtr<mechanicalLaw>(new mechanicalLaws::zoned(mesh, dict));
    }

    const word modelType(modelEntry.read(dict));

    Info<< "Selecting mechanical law " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "model",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    // Every entry is one of the laws' or the selected model's own
    // sub-dictionary: an entry another model reads (yieldStress under
    // neoHookean) would otherwise be silently ignored
    const string where("constant/mechanicalProperties");
    wordList also;
    if (entryDeclaration::subDictionaries(where).found(modelCoeffsName(modelType)))
    {
        also.append(modelCoeffsName(modelType));
    }
    entryDeclaration::checkEntries(dict, where, also);

    return autoPtr<mechanicalLaw>(cstrIter()(mesh, dict));
}


// ************************************************************************* //
