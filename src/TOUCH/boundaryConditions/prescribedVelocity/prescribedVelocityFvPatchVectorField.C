/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "prescribedVelocityFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF),
    velocity_(p.size(), Zero)
{}


Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    solidFluxFvPatchVectorField(p, iF, dict, wordList({"velocity"})),
    velocity_("velocity", dict, p.size())
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
    velocity_(ptf.velocity_, mapper)
{}


Foam::prescribedVelocityFvPatchVectorField::prescribedVelocityFvPatchVectorField
(
    const prescribedVelocityFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF),
    velocity_(ptf.velocity_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::prescribedVelocityFvPatchVectorField::flux
(
    const interiorState& s,
    vectorField& pC,
    vectorField& tC
) const
{
    momentumFlux(s, s.rho*velocity_, pC, tC);
}



void Foam::prescribedVelocityFvPatchVectorField::constraint
(
    const interiorState&,
    tensorField& free,
    vectorField& velocity
) const
{
    free = Zero;
    velocity = velocity_;
}

void Foam::prescribedVelocityFvPatchVectorField::autoMap(const fvPatchFieldMapper& m)
{
    solidFluxFvPatchVectorField::autoMap(m);
    velocity_.autoMap(m);
}


void Foam::prescribedVelocityFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    solidFluxFvPatchVectorField::rmap(ptf, addr);

    const prescribedVelocityFvPatchVectorField& tiptf = refCast<const prescribedVelocityFvPatchVectorField>(ptf);

    velocity_.rmap(tiptf.velocity_, addr);
}


void Foam::prescribedVelocityFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    velocity_.writeEntry("velocity", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, prescribedVelocityFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addPrescribedVelocitySolidFluxType(prescribedVelocityFvPatchVectorField::typeName_());
}

// ************************************************************************* //
