/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "solidFluxFvPatchVectorField.H"
#include "entryDeclaration.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(solidFluxFvPatchVectorField, 0);

    //- The registered names; a function-local list, so that registration
    //  from other translation units never precedes its construction
    static DynamicList<word>& solidFluxTypes()
    {
        static DynamicList<word> names;
        return names;
    }
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::solidFluxFvPatchVectorField::addType::addType(const word& name)
{
    solidFluxTypes().append(name);
}


Foam::wordList Foam::solidFluxFvPatchVectorField::types()
{
    wordList names(solidFluxTypes());
    Foam::sort(names);
    return names;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::solidFluxFvPatchVectorField::tractionFlux
(
    const interiorState& s,
    const vectorField& tStar,
    vectorField& pC,
    vectorField& tC
)
{
    forAll(pC, facei)
    {
        const tensor nn(sqr(s.n[facei]));
        const tensor St(nn/s.Up[facei] + (tensor::I - nn)/s.Us[facei]);

        pC[facei] = s.p[facei] + (St & (tStar[facei] - s.t[facei]));
        tC[facei] = tStar[facei];
    }
}


void Foam::solidFluxFvPatchVectorField::momentumFlux
(
    const interiorState& s,
    const vectorField& pStar,
    vectorField& pC,
    vectorField& tC
)
{
    forAll(pC, facei)
    {
        const tensor nn(sqr(s.n[facei]));
        const tensor Sp(s.Up[facei]*nn + s.Us[facei]*(tensor::I - nn));

        pC[facei] = pStar[facei];
        tC[facei] = s.t[facei] + (Sp & (pStar[facei] - s.p[facei]));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidFluxFvPatchVectorField::solidFluxFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    fvPatchVectorField(p, iF)
{}


Foam::solidFluxFvPatchVectorField::solidFluxFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict,
    const wordList& conditionKeywords
)
:
    fvPatchVectorField(p, iF, dict, false)
{
    wordList valid({"type", "value", "patchType"});
    valid.append(conditionKeywords);

    for (const entry& e : dict)
    {
        if (!valid.found(e.keyword()))
        {
            const word near(entryDeclaration::nearest(e.keyword(), valid));

            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' in the entry of"
                << " patch " << p.name() << " in " << dict.name()
                << (near.empty() ? "" : ": did you mean '") << near
                << (near.empty() ? "" : "'?") << nl
                << "Valid keywords for type '"
                << dict.getOrDefault<word>("type", word::null) << "': "
                << valid << nl
                << exit(FatalIOError);
        }
    }

    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(patchInternalField());
    }
}


Foam::solidFluxFvPatchVectorField::solidFluxFvPatchVectorField
(
    const solidFluxFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fvPatchVectorField(ptf, p, iF, mapper)
{}


Foam::solidFluxFvPatchVectorField::solidFluxFvPatchVectorField
(
    const solidFluxFvPatchVectorField& ptf
)
:
    fvPatchVectorField(ptf)
{}


Foam::solidFluxFvPatchVectorField::solidFluxFvPatchVectorField
(
    const solidFluxFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fvPatchVectorField(ptf, iF)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidFluxFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    writeEntry("value", os);
}


// ************************************************************************* //
