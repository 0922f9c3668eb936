/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "syncTools.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace deformationUpdates
{
    defineTypeNameAndDebug(compatible, 0);
    addToRunTimeSelectionTable(deformationUpdate, compatible, dictionary);
}
}


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- The share in [0, 1] of a cell jump that the reconstructed jump keeps
//  along it: upwinding phi (cell jump) damps like the reconstructed jump in
//  smooth regions (phi = O(h)) yet can never feed energy, which the
//  reconstructed jump itself does where it opposes the cell jump (least-
//  squares gradients on tetrahedra)
static inline scalar jumpShare(const vector& reconstructed, const vector& cell)
{
    const scalar cellSqr = magSqr(cell);

    if (cellSqr < VSMALL)
    {
        return 0;
    }

    return min(max((reconstructed & cell)/cellSqr, scalar(0)), scalar(1));
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::addUpwindRate
(
    vectorField& lmRate
) const
{
    faces_.forAllCoupled
    (
        [&](const solidFaces::coupledFace& face)
        {
            // The central traction is the point coupling's; the upwind
            // part damps the share of the cell jump the reconstruction
            // keeps: the flux of the jump alone
            const vector jump(face.right.lm - face.left.lm);
            vector pC;
            vector tC;
            riemann_.flux
            (
                Zero, Zero, jumpShare(face.pR() - face.pL(), jump)*jump, Zero,
                face.n(), pC, tC
            );

            tC *= face.magSf;
            lmRate[face.owner] += tC;
            if (face.neighbour >= 0)
            {
                lmRate[face.neighbour] -= tC;
            }
        }
    );
}


void Foam::deformationUpdates::compatible::addBoundaryRate
(
    const label stage,
    vectorField& lmRate,
    vector& torque
)
{
    const vectorField& lm = faces_.lm().primitiveField();

    faces_.forAllSolidPatches
    (
        law_,
        stage,
        [&]
        (
            const fvPatch& patch,
            solidFluxFvPatchVectorField& condition,
            const solidFluxFvPatchVectorField::interiorState& state,
            const solidFluxFvPatchVectorField::interiorState& reference
        )
        {
            const label patchi = patch.index();
            const labelUList& faceCells = patch.faceCells();
            const tensorField& free = faceFree_[patchi];

            // Declared with the reference normals: the constraints of a
            // plane are then the same at all its faces, so every processor
            // combines them alike
            condition.constraint
            (
                reference, faceFree_[patchi], faceVelocity_[patchi]
            );
            constraints_.add(patch, free, faceVelocity_[patchi]);

            // The fixed directions are damped with the share of the cell's
            // momentum that the reconstruction keeps there, which can never
            // feed energy
            vectorField& pM = faces_.interiorMomentum(patchi);
            forAll(faceCells, i)
            {
                const tensor fixed(tensor::I - free[i]);
                const vector cellFixed(fixed & lm[faceCells[i]]);
                pM[i] =
                    (free[i] & pM[i])
                  + jumpShare(fixed & pM[i], cellFixed)*cellFixed;
            }

            boundaryFlux(patch, condition, state, torque);

            // The prescribed traction of the free directions, and the
            // upwind damping of the fixed ones; their central traction is
            // the constraint's reaction
            const vectorField& tC = tC_[patchi];
            const scalarField& magSf = patch.magSf();
            forAll(faceCells, i)
            {
                const tensor fixed(tensor::I - free[i]);
                lmRate[faceCells[i]] +=
                    (tC[i] - (fixed & state.t[i]))*magSf[i];
            }
        }
    );
}


void Foam::deformationUpdates::compatible::addTransposeRate
(
    vectorField& lmRate
)
{
    const faceList& faces = faces_.mesh().faces();
    const vectorField& Sf = faces_.mesh().faceAreas();
    const tensorField& P = faces_.P().primitiveField();

    // Nodal forces f_a = sum over the faces at a of P C/n_f, for which the
    // stress power sum_e P_e : V_e dF_e/dt of the point motion is
    // sum_a f_a . v_a
    pointForce_ = Zero;

    faces_.forAllFaces
    (
        [&](const label facei, const label own, const label nei)
        {
            const vector force
            (
                (nei >= 0 ? P[own] - P[nei] : P[own]) & Sf[facei]
            );
            const face& f = faces[facei];
            const vector share(force/f.size());
            for (const label pointi : f)
            {
                pointForce_[pointi] += share;
            }
        }
    );

    syncTools::syncPointList
    (
        faces_.mesh(), pointForce_, plusEqOp<vector>(), vector::zero
    );

    // The momentum rate does the opposite work: -A^T Pi^T f
    constraints_.constrainTranspose(pointForce_);
    pointForce_ = -pointForce_;

    pointInterpolation_.addTranspose(pointForce_, lmRate);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdates::compatible::compatible
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    deformationUpdate(controls, faces, law, riemann, reconstruction),
    pointInterpolation_(faces.mesh(), reconstruction),
    constraints_(faces.mesh()),
    faceFree_(faces.mesh().boundary().size()),
    faceVelocity_(faces.mesh().boundary().size()),
    pointForce_(faces.mesh().nPoints(), Zero)
{
    forAll(faces.mesh().boundary(), patchi)
    {
        const label n = pC_[patchi].size();

        faceFree_.set(patchi, new tensorField(n, tensor::I));
        faceVelocity_.set(patchi, new vectorField(n, Zero));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::rates
(
    const label stage,
    vectorField& lmRate,
    tensorField& FRate,
    vectorField& pointV,
    vector& torque
)
{
    constraints_.reset();

    addUpwindRate(lmRate);
    addBoundaryRate(stage, lmRate, torque);

    constraints_.finalise();

    // Point velocities v_a = Pi_a (A v)_a + b_a
    pointInterpolation_.interpolate(faces_.lm(), 1/law_.rho(), pointV);
    constraints_.constrain(pointV);

    // F follows the point motion alone (no upwind part: see the header)
    addFaceMeanFRate(pointV, FRate);

    addTransposeRate(lmRate);
}


// ************************************************************************* //
