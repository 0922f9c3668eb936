/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's boundary conditions: each solid condition's
    kinematic constraint at its points, its flux and the damping of its
    fixed directions (addBoundaryRate), and the transpose of the point
    motion that gives the central momentum rate (addTransposeRate).

\*---------------------------------------------------------------------------*/

#include "compatible.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- Add a face's force to its points, an equal share each
static inline void spreadToPoints
(
    const face& f,
    const vector& force,
    vectorField& pointValues
)
{
    const vector share(force/f.size());
    for (const label pointi : f)
    {
        pointValues[pointi] += share;
    }
}

//- The share of a face's points that are held
static inline scalar heldShare(const face& localFace, const boolList& held)
{
    label n = 0;
    for (const label pointj : localFace)
    {
        n += held[pointj];
    }
    return scalar(n)/localFace.size();
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::addBoundaryRate
(
    const label stage,
    vectorField& lmRate,
    vector& torque,
    const bool decide
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
            // (a contact surface's facets at a point combined into its
            // normal: kinematicPointConstraints::surfaceFixed; a wall that
            // holds only the points that reached it: heldPoints)
            const boolList* held = condition.heldPoints();
            constraints_.add
            (
                patch, free, faceVelocity_[patchi], condition.contactSurface(),
                held
            );
            const faceList& localFaces = patch.patch().localFaces();

            // The fixed directions are damped towards the prescribed
            // momentum with the share of the cell's departure from it that
            // the reconstruction keeps there, which can never feed energy
            // (towards zero instead, a moving wall's bounce was off by
            // 1.2e-3 in momentum)
            vectorField& pM = faces_.interiorMomentum(patchi);
            forAll(faceCells, i)
            {
                const tensor fixed(tensor::I - free[i]);
                const vector pStar(state.rho[i]*faceVelocity_[patchi][i]);
                const vector departure((fixed & lm[faceCells[i]]) - pStar);
                pM[i] =
                    (free[i] & pM[i]) + pStar
                  + upwindShare((fixed & pM[i]) - pStar, departure)*departure;
            }

            // A condition that fixes directions is taken with the normals
            // its constraint was declared with: with the spatial normal of
            // the boundary cell (cof F N, off the plane's normal by O(h)
            // where the cell shears) the flux's normal traction did not
            // match the fixed part of the interior traction taken out
            // below, and the rest did work: a free-flying quarter bar
            // between symmetry planes gained 4e-7 E0 in a step
            bool fixesDirections = false;
            forAll(free, i)
            {
                if (magSqr(tensor::I - free[i]) > SMALL)
                {
                    fixesDirections = true;
                    break;
                }
            }

            boundaryFlux
            (
                patch, condition, fixesDirections ? reference : state, torque
            );

            // The prescribed traction of the free directions, and the
            // upwind damping of the fixed ones; their central traction is
            // the constraint's reaction.  Where only some points of a face
            // are held, the fixed directions are the face's at those points
            // alone: the damping takes their share of the face, and at the
            // others the central traction stays the interior's, as at a
            // free face
            const vectorField& tC = tC_[patchi];
            const scalarField& magSf = patch.magSf();
            vectorField force(faceCells.size());
            vector faceForce(Zero);
            forAll(faceCells, i)
            {
                const tensor fixed(tensor::I - free[i]);
                force[i] =
                    held
                  ? (
                        (free[i] & tC[i])
                      + heldShare(localFaces[i], *held)
                       *(fixed & (tC[i] - state.t[i]))
                    )*magSf[i]
                  : (tC[i] - (fixed & state.t[i]))*magSf[i];
                lmRate[faceCells[i]] += force[i];
                faceForce += force[i];
            }
            faceForce_[patchi] = faceForce;

            // Per face, for a condition released on the force applied
            if (releaseFaceForce_.set(patchi))
            {
                releaseFaceForce_[patchi] = force;
            }

            // The torque of a wall is that of the force it applies: the
            // faces' part above and the constraint's reaction at the
            // points (reportWallForces), not the flux's central traction
            // at the faces, whose total differs from the reaction by up
            // to half of it on a curved body.  The difference turned with
            // the lever arm of the body's drift along the wall: a ring
            // sliding on it at 0.85 of its falling speed spun up to 0.17
            // |p| R_outer and left the wall 4 % early
            // (validation/ringImpact/FINDINGS.md)
            if (pointDisplacement_ && condition.reportsForce())
            {
                forAll(faceCells, i)
                {
                    const tensor fixed(tensor::I - free[i]);
                    torque -=
                        state.x[i]
                      ^ (
                            held
                          ? tC[i]*magSf[i] - force[i]
                          : (fixed & state.t[i])*magSf[i]
                        );
                }
            }

            // The reconstructed traction against the condition's: at a
            // point the face does not hold, against its free part alone
            if (pointUpwinding_ > 0)
            {
                const faceList& faces = faces_.mesh().faces();
                forAll(faceCells, i)
                {
                    const face& f = faces[patch.start() + i];
                    if (!held)
                    {
                        spreadToPoints
                        (
                            f, magSf[i]*(state.t[i] - tC[i]),
                            reconstructedForce_
                        );
                        continue;
                    }
                    const vector atHeld
                    (
                        magSf[i]*(state.t[i] - tC[i])/f.size()
                    );
                    const vector atFree
                    (
                        magSf[i]*(state.t[i] - (free[i] & tC[i]))/f.size()
                    );
                    forAll(f, k)
                    {
                        reconstructedForce_[f[k]] +=
                            (*held)[localFaces[i][k]] ? atHeld : atFree;
                    }
                }
            }
        },
        decide
    );
}


void Foam::deformationUpdates::compatible::addTransposeRate
(
    vectorField& lmRate
)
{
    // The momentum rate does the opposite work of the central point
    // motion: -A^T Pi^T f
    constraints_.constrainTranspose(pointForce_);
    pointForce_ = -pointForce_;

    pointInterpolation_.addTranspose(pointForce_, lmRate);
}

// ************************************************************************* //
