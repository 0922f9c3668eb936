/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "tractionFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF),
    traction_(p.size(), Zero),
    pressure_(p.size(), Zero)
{}


Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    solidFluxFvPatchVectorField(p, iF, dict, wordList({"traction", "pressure"})),
    traction_
    (
        dict.found("traction")
      ? vectorField("traction", dict, p.size())
      : vectorField(p.size(), Zero)
    ),
    pressure_
    (
        dict.found("pressure")
      ? scalarField("pressure", dict, p.size())
      : scalarField(p.size(), Zero)
    )
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
    traction_(ptf.traction_, mapper),
    pressure_(ptf.pressure_, mapper)
{}


Foam::tractionFvPatchVectorField::tractionFvPatchVectorField
(
    const tractionFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF),
    traction_(ptf.traction_),
    pressure_(ptf.pressure_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tractionFvPatchVectorField::flux
(
    const interiorState& s,
    vectorField& pC,
    vectorField& tC
) const
{
    tractionFlux(s, traction_ - pressure_*s.n, pC, tC);
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
    traction_.autoMap(m);
    pressure_.autoMap(m);
}


void Foam::tractionFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    solidFluxFvPatchVectorField::rmap(ptf, addr);

    const tractionFvPatchVectorField& tiptf = refCast<const tractionFvPatchVectorField>(ptf);

    traction_.rmap(tiptf.traction_, addr);
    pressure_.rmap(tiptf.pressure_, addr);
}


void Foam::tractionFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    traction_.writeEntry("traction", os);
    pressure_.writeEntry("pressure", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, tractionFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addTractionSolidFluxType(tractionFvPatchVectorField::typeName_());
}

// ************************************************************************* //
