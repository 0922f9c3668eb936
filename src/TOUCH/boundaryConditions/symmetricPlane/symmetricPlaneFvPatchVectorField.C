/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "symmetricPlaneFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::symmetricPlaneFvPatchVectorField::symmetricPlaneFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF)
{}


Foam::symmetricPlaneFvPatchVectorField::symmetricPlaneFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    solidFluxFvPatchVectorField(p, iF, dict)
{}


Foam::symmetricPlaneFvPatchVectorField::symmetricPlaneFvPatchVectorField
(
    const symmetricPlaneFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    solidFluxFvPatchVectorField(ptf, p, iF, mapper)
{}


Foam::symmetricPlaneFvPatchVectorField::symmetricPlaneFvPatchVectorField
(
    const symmetricPlaneFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::symmetricPlaneFvPatchVectorField::flux
(
    const interiorState& s,
    vectorField& pC,
    vectorField& tC
) const
{
    forAll(pC, facei)
    {
        const vector& n = s.n[facei];
        const tensor nn(sqr(n));

        pC[facei] = (tensor::I - nn) & (s.p[facei] - s.t[facei]/s.Us);
        tC[facei] = nn & (s.t[facei] - s.Up*s.p[facei]);
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, symmetricPlaneFvPatchVectorField);
}

// ************************************************************************* //
