/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "tractionFvPatchVectorField.H"
#include "declaredEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "ConstantField.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const describedEntry tractionEntry
    (
        "0/U (or 0/lm) boundaryField, type traction", "traction",
        "traction per reference area, a PatchFunction1 of time (uniform,"
        " nonuniform, constant, table, tableFile, csvFile, polynomial, sine,"
        " square, ...)",
        "Pa", "uniform (0 0 0)", "table ((0 (0 0 0)) (1e-4 (1e5 0 0)))"
    );

    static const describedEntry pressureEntry
    (
        "0/U (or 0/lm) boundaryField, type traction", "pressure",
        "pressure on the current surface (positive pushes into the solid), a"
        " PatchFunction1 of time",
        "Pa", "uniform 0", "table ((0 0) (1e-4 1.4e5))"
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::autoPtr<Foam::PatchFunction1<Type>>
Foam::tractionFvPatchVectorField::readOrZero
(
    const fvPatch& p,
    const word& entryName,
    const dictionary& dict
)
{
    if (dict.found(entryName, keyType::LITERAL))
    {
        return PatchFunction1<Type>::New(p.patch(), entryName, dict);
    }

    return autoPtr<PatchFunction1<Type>>
    (
        new PatchFunction1Types::ConstantField<Type>
        (
            p.patch(), entryName, true, Zero, Field<Type>(p.size(), Zero)
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF),
    traction_(readOrZero<vector>(p, tractionEntry.name(), dictionary::null)),
    pressure_(readOrZero<scalar>(p, pressureEntry.name(), dictionary::null))
{}


Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    solidFluxFvPatchVectorField
    (
        p, iF, dict,
        wordList
        ({
            "traction", "tractionCoeffs", "pressure", "pressureCoeffs"
        })
    ),
    traction_(readOrZero<vector>(p, tractionEntry.name(), dict)),
    pressure_(readOrZero<scalar>(p, pressureEntry.name(), dict))
{}


Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const tractionFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    solidFluxFvPatchVectorField(ptf, p, iF, mapper),
    traction_(ptf.traction_.clone(p.patch())),
    pressure_(ptf.pressure_.clone(p.patch()))
{
    traction_->autoMap(mapper);
    pressure_->autoMap(mapper);
}


Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const tractionFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF),
    traction_(ptf.traction_.clone(this->patch().patch())),
    pressure_(ptf.pressure_.clone(this->patch().patch()))
{}


Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const tractionFvPatchVectorField& ptf
)
:
    solidFluxFvPatchVectorField(ptf),
    traction_(ptf.traction_.clone(this->patch().patch())),
    pressure_(ptf.pressure_.clone(this->patch().patch()))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tractionFvPatchVectorField::flux
(
    const interiorState& s,
    vectorField& pC,
    vectorField& tC
) const
{
    tractionFlux
    (
        s,
        traction_->value(s.time) - pressure_->value(s.time)*s.n,
        pC,
        tC
    );
}



void Foam::tractionFvPatchVectorField::constraint
(
    const interiorState&,
    tensorField& free,
    vectorField& velocity
) const
{
    free = tensor::I;
    velocity = Zero;
}

void Foam::tractionFvPatchVectorField::autoMap(const fvPatchFieldMapper& m)
{
    solidFluxFvPatchVectorField::autoMap(m);
    traction_->autoMap(m);
    pressure_->autoMap(m);
}


void Foam::tractionFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    solidFluxFvPatchVectorField::rmap(ptf, addr);

    const tractionFvPatchVectorField& tiptf = refCast<const tractionFvPatchVectorField>(ptf);

    traction_->rmap(tiptf.traction_(), addr);
    pressure_->rmap(tiptf.pressure_(), addr);
}


void Foam::tractionFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    traction_->writeData(os);
    pressure_->writeData(os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, tractionFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addTractionSolidFluxType(tractionFvPatchVectorField::typeName_());
}

// ************************************************************************* //
