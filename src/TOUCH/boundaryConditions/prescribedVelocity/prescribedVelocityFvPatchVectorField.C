/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "prescribedVelocityFvPatchVectorField.H"
#include "declaredEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "ConstantField.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const describedEntry prescribedVelocityEntry
    (
        "0/U (or 0/lm) boundaryField, type prescribedVelocity", "velocity",
        "the patch's velocity, a PatchFunction1 of time (uniform, nonuniform,"
        " constant, table, tableFile, csvFile, polynomial, sine, square,"
        " ...)",
        "m/s", "", "table ((0 (0 0 0)) (1e-4 (0.1 0 0)))"
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF),
    velocity_
    (
        new PatchFunction1Types::ConstantField<vector>
        (
            p.patch(), "velocity", true, Zero, vectorField(p.size(), Zero)
        )
    )
{}


Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    solidFluxFvPatchVectorField
    (
        p, iF, dict, wordList({"velocity", "velocityCoeffs"})
    ),
    velocity_
    (
        PatchFunction1<vector>::New
        (
            p.patch(), prescribedVelocityEntry.name(), dict
        )
    )
{}


Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const prescribedVelocityFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    solidFluxFvPatchVectorField(ptf, p, iF, mapper),
    velocity_(ptf.velocity_.clone(p.patch()))
{
    velocity_->autoMap(mapper);
}


Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const prescribedVelocityFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF),
    velocity_(ptf.velocity_.clone(this->patch().patch()))
{}


Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const prescribedVelocityFvPatchVectorField& ptf
)
:
    solidFluxFvPatchVectorField(ptf),
    velocity_(ptf.velocity_.clone(this->patch().patch()))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::prescribedVelocityFvPatchVectorField::flux
(
    const interiorState& s,
    vectorField& pC,
    vectorField& tC
) const
{
    momentumFlux(s, s.rho*velocity_->value(s.time), pC, tC);
}



void Foam::prescribedVelocityFvPatchVectorField::constraint
(
    const interiorState& s,
    tensorField& free,
    vectorField& velocity
) const
{
    free = Zero;
    velocity = velocity_->value(s.time);
}

void Foam::prescribedVelocityFvPatchVectorField::autoMap(const fvPatchFieldMapper& m)
{
    solidFluxFvPatchVectorField::autoMap(m);
    velocity_->autoMap(m);
}


void Foam::prescribedVelocityFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    solidFluxFvPatchVectorField::rmap(ptf, addr);

    const prescribedVelocityFvPatchVectorField& tiptf = refCast<const prescribedVelocityFvPatchVectorField>(ptf);

    velocity_->rmap(tiptf.velocity_(), addr);
}


void Foam::prescribedVelocityFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    velocity_->writeData(os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, prescribedVelocityFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addPrescribedVelocitySolidFluxType(prescribedVelocityFvPatchVectorField::typeName_());
}

// ************************************************************************* //
