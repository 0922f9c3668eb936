/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "riemannUpdate.H"

// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::deformationUpdates::riemannUpdate::momentumRates
(
    const label stage,
    vectorField& lmRate,
    vectorField& pointV,
    vector& torque
)
{
    const scalar rho = law_.rho();
    faces_.forAllCoupled
    (
        [&](const solidFaces::coupledFace& face)
        {
            vector pC;
            vector tC;
            riemann_.flux
            (
                face.pL(), face.tL(), face.pR(), face.tR(), face.n(), pC, tC
            );

            tC *= face.magSf;
            faceVelocity_[face.facei] = pC/rho;

            lmRate[face.owner] += tC;
            if (face.neighbour >= 0)
            {
                lmRate[face.neighbour] -= tC;
            }
        }
    );

    faces_.forAllSolidPatches
    (
        law_,
        stage,
        [&]
        (
            const fvPatch& patch,
            solidFluxFvPatchVectorField& condition,
            const solidFluxFvPatchVectorField::interiorState& state,
            const solidFluxFvPatchVectorField::interiorState&
        )
        {
            boundaryFlux(patch, condition, state, torque);

            const vectorField& pC = pC_[patch.index()];
            const vectorField& tC = tC_[patch.index()];
            const scalarField& magSf = patch.magSf();
            const labelUList& faceCells = patch.faceCells();

            forAll(faceCells, i)
            {
                faceVelocity_[patch.start() + i] = pC[i]/rho;
                lmRate[faceCells[i]] += tC[i]*magSf[i];
            }
        }
    );

    pointFit_.interpolate
    (
        faces_.lm().primitiveField(),
        1/rho,
        faceVelocity_,
        pointV
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdates::riemannUpdate::riemannUpdate
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    deformationUpdate(controls, faces, law, riemann, reconstruction),
    faceVelocity_(faces.mesh().nFaces(), Zero),
    pointFit_(faces.mesh())
{}


// ************************************************************************* //
