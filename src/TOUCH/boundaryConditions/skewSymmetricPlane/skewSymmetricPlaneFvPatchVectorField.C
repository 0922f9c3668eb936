/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "skewSymmetricPlaneFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::skewSymmetricPlaneFvPatchVectorField::skewSymmetricPlaneFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF)
{}


Foam::skewSymmetricPlaneFvPatchVectorField::skewSymmetricPlaneFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    solidFluxFvPatchVectorField(p, iF, dict)
{}


Foam::skewSymmetricPlaneFvPatchVectorField::skewSymmetricPlaneFvPatchVectorField
(
    const skewSymmetricPlaneFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    solidFluxFvPatchVectorField(ptf, p, iF, mapper)
{}


Foam::skewSymmetricPlaneFvPatchVectorField::skewSymmetricPlaneFvPatchVectorField
(
    const skewSymmetricPlaneFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::skewSymmetricPlaneFvPatchVectorField::flux
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

        pC[facei] = nn & (s.p[facei] - s.t[facei]/s.Up);
        tC[facei] = (tensor::I - nn) & (s.t[facei] - s.Us*s.p[facei]);
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, skewSymmetricPlaneFvPatchVectorField);
}

// ************************************************************************* //
