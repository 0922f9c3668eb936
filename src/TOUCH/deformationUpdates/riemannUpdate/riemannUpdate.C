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
    const vectorField& Sf = faces_.mesh().faceAreas();
    const vectorField& Cf = faces_.mesh().faceCentres();

    faces_.forAllCoupled
    (
        [&]
        (
            const label facei,
            const label own,
            const label nei,
            const solidFaces::cellValues& left,
            const solidFaces::cellValues& right
        )
        {
            const scalar magSf = mag(Sf[facei]);
            const vector N(Sf[facei]/magSf);
            const vector rL(Cf[facei] - left.X);
            const vector rR(Cf[facei] - right.X);
            const vector n
            (
                solidFaces::spatialNormal(0.5*(left.F + right.F), N)
            );

            vector pC;
            vector tC;
            riemann_.flux
            (
                left.p(rL), left.t(rL, N), right.p(rR), right.t(rR, N),
                n, pC, tC
            );

            tC *= magSf;
            faceVelocity_[facei] = pC/rho;

            lmRate[own] += tC;
            if (nei >= 0)
            {
                lmRate[nei] -= tC;
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
