/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's report of the force a condition applies (a
    rigid wall): the force its faces add to the momentum rate and the
    reaction of its constraint at its points.

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "syncTools.H"
#include "bodyContactFvPatchVectorField.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The condition's part of the reaction R at a point whose constraint
//  combines its fixed directions (the sum of its faces' fixed projectors
//  there, own) with those of other conditions (others): the r in the span
//  of its own for which R - r lies in the span of the others'.  With one
//  face's fixed projector applied to R instead, a contact meeting a
//  symmetry plane took a part of the plane's reaction along its tilted
//  normal, and a point held by contact faces of different normals lost the
//  reaction's other fixed directions: two balls exchanged momentum along
//  their axis to 2e-3 of it.  Where the spans overlap (no unique split)
//  the others take what lies in their span
static vector conditionPart
(
    const tensor& own,
    const tensor& others,
    const vector& R
)
{
    const tensor fixed
    (
        tensor::I - kinematicPointConstraints::freeProjector(own)
    );
    // The others' sum is the point's total less the own one: round-off
    // where no other condition fixes a direction
    if (mag(others) <= 1e-9*mag(own))
    {
        return fixed & R;
    }

    // rest: onto the complement of the others' span; r = fixed r solves
    // rest r = rest R: (fixed rest fixed) r = fixed rest R on the own span,
    // the identity on its complement
    const tensor rest(kinematicPointConstraints::freeProjector(others));
    const tensor M((fixed & rest & fixed) + tensor::I - fixed);
    if (det(M) > 1e-4)
    {
        return inv(M) & (fixed & (rest & R));
    }
    return rest & R;
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::vector Foam::deformationUpdates::compatible::conditionReaction
(
    const label pointi,
    const tensor& ownFixed
) const
{
    return conditionPart
    (
        ownFixed,
        constraints_.fixedSum(pointi) - ownFixed,
        constraints_.reaction(pointi, pointForce_[pointi])
    );
}


void Foam::deformationUpdates::compatible::addConditionRates
(
    const label stage,
    vectorField& lmRate,
    vector& torque
)
{
    if (!releasing_)
    {
        addBoundaryRate(stage, lmRate, torque, true);
        constraints_.finalise();
        return;
    }

    rateBeforeConditions_ = lmRate;
    reconstructedBeforeConditions_ = reconstructedForce_;
    const vector torqueBefore(torque);

    addBoundaryRate(stage, lmRate, torque, true);
    constraints_.finalise();

    // A face whose wall solution pushes (t_W > 0) can still be pulled on
    // by the force the update applies: the central traction reaches the
    // momentum as the constraint's reaction at the face's points, which
    // neighbouring cells load, and the damping pulls where the cell moves
    // off the wall.  Released, such a face is traction-free and its points
    // free where no other face holds them; each pass releases at least one
    // face, so the passes end
    while (releaseTensileFaces())
    {
        lmRate = rateBeforeConditions_;
        reconstructedForce_ = reconstructedBeforeConditions_;
        torque = torqueBefore;

        constraints_.reset();
        addBoundaryRate(stage, lmRate, torque, false);
        constraints_.finalise();
    }
}


bool Foam::deformationUpdates::compatible::releaseTensileFaces()
{
    const fvMesh& mesh = faces_.mesh();
    label released = 0;

    forAll(mesh.boundary(), patchi)
    {
        if (!releaseFaceForce_.set(patchi))
        {
            continue;
        }

        const fvPatch& patch = mesh.boundary()[patchi];
        solidFluxFvPatchVectorField& condition =
            refCast<solidFluxFvPatchVectorField>
            (
                faces_.lm().boundaryFieldRef()[patchi]
            );
        const labelList& meshPoints = patch.patch().meshPoints();
        const faceList& localFaces = patch.patch().localFaces();
        const tensorField& free = faceFree_[patchi];
        const boolList* held = condition.heldPoints();

        // Per point of the patch, the number of its faces that fix a
        // direction there, on all ranks (every rank takes part in the
        // sync, also one whose part of the patch is empty)
        labelList holding(meshPoints.size(), 0);
        forAll(localFaces, i)
        {
            if (magSqr(tensor::I - free[i]) > SMALL)
            {
                for (const label pointj : localFaces[i])
                {
                    if (!held || (*held)[pointj])
                    {
                        ++holding[pointj];
                    }
                }
            }
        }
        syncTools::syncPointList
        (
            mesh, meshPoints, holding, plusEqOp<label>(), label(0)
        );

        // Each face's damping and its shares of the reaction: summed over
        // the faces of all ranks, the force reportWallForces gives
        vectorField force(releaseFaceForce_[patchi]);
        forAll(localFaces, i)
        {
            const tensor fixed(tensor::I - free[i]);
            if (magSqr(fixed) > SMALL)
            {
                for (const label pointj : localFaces[i])
                {
                    if (held && !(*held)[pointj])
                    {
                        continue;
                    }
                    const label pointi = meshPoints[pointj];
                    force[i] +=
                        (
                            fixed
                          & constraints_.reaction(pointi, pointForce_[pointi])
                        )/holding[pointj];
                }
            }
        }

        released += condition.releaseTensile(force);
    }

    return returnReduce(released, sumOp<label>()) > 0;
}


void Foam::deformationUpdates::compatible::reportWallForces
(
    vector& torque
)
{
    const fvMesh& mesh = faces_.mesh();

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];

        // Not the coupled and empty patches
        fvPatchVectorField& pf = faces_.lm().boundaryFieldRef()[patchi];
        if (patch.coupled() || !isA<solidFluxFvPatchVectorField>(pf))
        {
            continue;
        }

        solidFluxFvPatchVectorField& condition =
            refCast<solidFluxFvPatchVectorField>(pf);

        // Every rank takes part (the sync), also one whose part of the
        // patch is empty
        if (!condition.reportsForce())
        {
            continue;
        }

        const labelList& meshPoints = patch.patch().meshPoints();
        const faceList& localFaces = patch.patch().localFaces();
        const tensorField& free = faceFree_[patchi];
        const boolList* held = condition.heldPoints();

        // Sized on first use, for the patches of such a condition alone
        if (pointMarks_.empty())
        {
            pointMarks_.setSize(mesh.nPoints());
        }
        if (!fixingFace_.set(patchi))
        {
            fixingFace_.set(patchi, new labelList(meshPoints.size()));
        }

        // The points of the faces that fix a direction, with the fixed
        // projector of one of them, and on how many ranks each is one
        labelList& fixingFace = fixingFace_[patchi];
        fixingFace = -1;
        forAll(localFaces, i)
        {
            if (magSqr(tensor::I - free[i]) > SMALL)
            {
                for (const label pointj : localFaces[i])
                {
                    if (!held || (*held)[pointj])
                    {
                        fixingFace[pointj] = i;
                    }
                }
            }
        }

        pointMarks_ = 0;
        forAll(meshPoints, j)
        {
            pointMarks_[meshPoints[j]] = fixingFace[j] >= 0;
        }
        syncTools::syncPointList
        (
            mesh, pointMarks_, plusEqOp<label>(), label(0)
        );

        // The sum of the condition's own fixed projectors at each point,
        // on all ranks: the rest of the point's sum is the other
        // conditions' (a symmetry plane the contact meets)
        tensorField ownSum(meshPoints.size(), Zero);
        forAll(localFaces, i)
        {
            const tensor fixed(tensor::I - free[i]);
            if (magSqr(fixed) > SMALL)
            {
                for (const label pointj : localFaces[i])
                {
                    if (!held || (*held)[pointj])
                    {
                        ownSum[pointj] += fixed;
                    }
                }
            }
        }
        syncTools::syncPointList
        (
            mesh, meshPoints, ownSum, plusEqOp<tensor>(), tensor::zero
        );

        // The facets of a contact surface held along their normal alone,
        // as the constraint combined them (kinematicPointConstraints)
        // A patch with side nodes keeps each point's normal and its share
        // of the reaction, which go to the partner surface
        // (transferNodeReactions)
        const bool nodes = nodeShare_.set(patchi);
        if (condition.contactSurface())
        {
            vector e;
            forAll(ownSum, j)
            {
                ownSum[j] =
                    kinematicPointConstraints::surfaceFixed(ownSum[j], e);
                if (nodes)
                {
                    nodeNormal_[patchi][j] = e;
                }
            }
        }
        if (nodes)
        {
            nodeShare_[patchi] = Zero;
        }
        if (wallShare_.set(patchi))
        {
            wallShare_[patchi] = Zero;
        }

        // Side nodes: a held point whose reaction pulls is let go; with
        // friction a point that sticks is held in every direction
        if (nodes)
        {
            releaseTensileNodes(patchi, ownSum);
        }
        if (nodeStuck_.set(patchi))
        {
            if (nodes)
            {
                stickNodes(patchi, ownSum);
            }
            else
            {
                stickWallPoints(patchi, ownSum);
            }
        }

        // The wall's part of the constraint's reaction at those points,
        // each rank its share
        vector reaction(Zero);
        forAll(meshPoints, j)
        {
            if (fixingFace[j] >= 0)
            {
                const label pointi = meshPoints[j];
                // A sticking point holds every direction no other
                // condition fixes
                const bool stuck =
                    nodeStuck_.set(patchi) && nodeStuck_[patchi][j];
                const vector share
                (
                    (
                        stuck
                      ? vector(nodeOwn_[patchi][j] & pointForce_[pointi])
                      : conditionReaction(pointi, ownSum[j])
                    )/pointMarks_[pointi]
                );
                reaction += share;
                if (nodes)
                {
                    nodeShare_[patchi][j] = share;
                }
                if (wallShare_.set(patchi))
                {
                    wallShare_[patchi][j] = share;
                }
                if (frictionMarks_.set(patchi))
                {
                    frictionMarks_[patchi][j] = pointMarks_[pointi];
                }

                // At the point where it acts (the stage's positions)
                if (pointDisplacement_)
                {
                    torque +=
                        (mesh.points()[pointi] + (*pointDisplacement_)[pointi])
                      ^ share;
                }
            }
        }

        condition.correctStageForce
        (
            (patch.size() ? faceForce_[patchi] : vector(Zero)) + reaction
        );
    }
}


void Foam::deformationUpdates::compatible::releaseTensileNodes
(
    const label patchi,
    const tensorField& ownFixed
)
{
    const fvMesh& mesh = faces_.mesh();
    const fvPatch& patch = mesh.boundary()[patchi];
    const labelList& meshPoints = patch.patch().meshPoints();
    const labelList& fixingFace = fixingFace_[patchi];
    const vectorField& Sf = patch.Sf();

    // Pulls: the contact's part of the reaction along the surface's normal
    // points out of the body (the outward normal of a face holding it);
    // decided where a face holds it, then on every rank that shares it
    labelField pulls(meshPoints.size(), 0);
    forAll(meshPoints, j)
    {
        if (fixingFace[j] >= 0)
        {
            pulls[j] =
                (
                    conditionReaction(meshPoints[j], ownFixed[j])
                  & Sf[fixingFace[j]]
                ) > 0;
        }
    }
    syncTools::syncPointList
    (
        mesh, meshPoints, pulls, maxEqOp<label>(), label(0)
    );

    forAll(meshPoints, j)
    {
        if (pulls[j])
        {
            const label pointi = meshPoints[j];
            constraints_.release
            (
                pointi, constraints_.fixedSum(pointi) - ownFixed[j]
            );
            fixingFace_[patchi][j] = -1;
        }
    }
}


// ************************************************************************* //
