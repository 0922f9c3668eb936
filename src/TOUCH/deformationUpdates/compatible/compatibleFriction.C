/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    Coulomb friction at the points the compatible update holds (side nodes
    of a contact between bodies, a rigid wall), about each point's normal
    force N: its reaction and the faces' damping of the approach spread
    over their held points.
    - Points that stick (stickNodes, stickWallPoints): a point sticks
      while both the sticking force -Z S w of its relative velocity w (the
      cells' A v at the point and under it on the partner, or the wall's
      velocity) and the tangential reaction a hold would take lie within
      the law's static cone about N.  It is then held in every direction
      its contact holds, at the partner's velocity under it (the wall's):
      its reaction is the friction, carried to the partner's points with
      the hold's weights (to the wall's force), and the two works cancel
      as the normal ones do.  A point has no history: the stage decides.
    - Points that slide (addNodeFriction, addWallFriction): F is the law's
      return of -Z S w to its cone about N, w the point's velocity
      relative to the partner surface (or the wall) as Pi A v in its free
      directions (before the upwindings and the hold, where its body
      takes all of F), Z S the S-wave impedances in series (a rigid wall:
      the body's) times the point's share of its patch's area (the
      Riemann problem's sticking traction at a point: Runcie, Lee, Haider,
      Gil, Bonet, IJNME 123 (2022) 5700).  F goes to the point, and -F to
      the partner face's points with the hold's weights, as nodal forces
      after the upwindings: momentum is exchanged exactly, and their power
      is F . w <= 0 whatever the meshes (F lies along -w).
    On a wall, where single points may pull while the wall pushes as a
    whole, their pull is taken from the pushing points in proportion.

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "rigidWallFvPatchVectorField.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::calcFrictionAreas()
{
    const fvMesh& mesh = faces_.mesh();

    forAll(frictionArea_, patchi)
    {
        if (!frictionArea_.set(patchi))
        {
            continue;
        }

        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        const labelList& meshPoints = pp.meshPoints();
        const faceList& localFaces = pp.localFaces();
        const scalarField magSf(mag(pp.faceAreas()));
        scalarField& area = frictionArea_[patchi];

        forAll(localFaces, i)
        {
            const face& f = localFaces[i];
            for (const label pointj : f)
            {
                area[pointj] += magSf[i]/f.size();
            }
        }
        syncTools::syncPointList
        (
            mesh, meshPoints, area, plusEqOp<scalar>(), scalar(0)
        );
    }
}


Foam::tmp<Foam::scalarField>
Foam::deformationUpdates::compatible::heldPointLoads
(
    const label patchi,
    const scalarField& faceLoad,
    const bool rankPart
) const
{
    const fvMesh& mesh = faces_.mesh();
    const polyPatch& pp = mesh.boundaryMesh()[patchi];
    const labelList& meshPoints = pp.meshPoints();
    const faceList& localFaces = pp.localFaces();
    const labelList& fixingFace = fixingFace_[patchi];

    tmp<scalarField> tload(new scalarField(meshPoints.size(), Zero));
    scalarField& load = tload.ref();

    forAll(localFaces, i)
    {
        label nHeld = 0;
        for (const label j : localFaces[i])
        {
            nHeld += (fixingFace[j] >= 0);
        }
        for (const label j : localFaces[i])
        {
            if (fixingFace[j] >= 0)
            {
                load[j] += faceLoad[i]/nHeld;
            }
        }
    }
    syncTools::syncPointList
    (
        mesh, meshPoints, load, plusEqOp<scalar>(), scalar(0)
    );

    // Each rank that holds a point its part, as of the reaction
    if (rankPart)
    {
        forAll(load, j)
        {
            load[j] /= frictionMarks_[patchi][j];
        }
    }
    return tload;
}


void Foam::deformationUpdates::compatible::addNodeFriction
(
    scalarField& power
)
{
    const fvMesh& mesh = faces_.mesh();
    contactSurfaces& contact = faces_.contact();
    const labelList& patches = contact.patches();

    // Both sides' velocities at which the friction works
    const vectorField slotV(contact.gatherSlots(pointVBeforeUpwinding_));

    vectorField slotForce(contact.nSlots(), Zero);
    vectorField added(mesh.nPoints(), Zero);
    List<vector> patchForce(patches.size(), Zero);
    scalar largestRatio = 0;
    scalar largestPower = -GREAT;

    // The damping of the cells' approach on the held faces, at their
    // points
    PtrList<scalarField> load(frictionArea_.size());
    forAll(frictionArea_, patchi)
    {
        if (frictionArea_.set(patchi) && nodeShare_.set(patchi))
        {
            bodyContactFvPatchVectorField& condition =
                refCast<bodyContactFvPatchVectorField>
                (
                    faces_.lm().boundaryFieldRef()[patchi]
                );
            const vectorField& Sf = condition.patch().Sf();
            load.set
            (
                patchi,
                heldPointLoads(patchi, -(condition.traction() & Sf))
            );
        }
    }

    forAll(holdPatch_, h)
    {
        const label patchi = holdPatch_[h];
        if (!frictionArea_.set(patchi))
        {
            continue;
        }
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                faces_.lm().boundaryFieldRef()[patchi]
            );

        const label j = holdIndex_[h];
        const label pointi = mesh.boundaryMesh()[patchi].meshPoints()[j];
        const vector& e = nodeNormal_[patchi][j];

        // A sticking point's friction is its reaction's tangential part
        if (nodeStuck_[patchi][j])
        {
            const vector& R = nodeShare_[patchi][j];
            const scalar Nj = mag(R & e) + load[patchi][j];
            const vector Rt(nodeOwn_[patchi][j] & (R - (R & e)*e));
            largestRatio = max(largestRatio, mag(Rt)/max(Nj, VSMALL));
            continue;
        }

        // This rank's part of the normal force (the reaction and the
        // faces' damping) and of the area (the ranks that hold a point
        // share both equally)
        const scalar N = mag(nodeShare_[patchi][j] & e) + load[patchi][j];
        const scalar S =
            frictionArea_[patchi][j]/frictionMarks_[patchi][j];

        vector partner(Zero);
        for (label k = holdStart_[h]; k < holdStart_[h + 1]; ++k)
        {
            partner += holdWeights_[k]*slotV[holdSlots_[k]];
        }
        // In the held point's free directions (its constraint fixes e and
        // those of the planes it lies on), so that the held body gets all
        // of F: taken along the tangent plane alone, a point on a
        // symmetric plane tilted with the dent lost the part of F in the
        // span of e and the plane's normal, which the partner still got (a
        // ball on a plate: p_y drifted by 2e-6 of its momentum)
        vector w(pointVBeforeUpwinding_[pointi] - partner);
        constraints_.constrainOne(pointi, w);

        const scalar Z =
            contact.pairShearImpedance
            (
                contact.localFace(patchi, fixingFace_[patchi][j]),
                holdSlots_[holdStart_[h]]
            );

        const vector F
        (
            condition.friction().tangentialTraction(-Z*S*w, N, Zero)
        );
        if (magSqr(F) == 0)
        {
            continue;
        }

        // To the held point's body, and opposite to the partner's points
        added[pointi] -= F;
        for (label k = holdStart_[h]; k < holdStart_[h + 1]; ++k)
        {
            slotForce[holdSlots_[k]] += holdWeights_[k]*F;
        }

        const label s = patches.find(patchi);
        patchForce[s] += F;
        power[s] += F & pointVBeforeUpwinding_[pointi];
        const scalar pointPower = F & w;
        condition.frictionPower() += pointPower;

        largestRatio = max(largestRatio, mag(F)/max(N, VSMALL));
        largestPower = max(largestPower, pointPower);
    }

    if (Pstream::parRun())
    {
        Pstream::listCombineGather(slotForce, plusEqOp<vector>());
        Pstream::listCombineScatter(slotForce);
    }

    vector slotTorque(Zero);
    contact.addSlotForces(slotForce, added, patchForce, slotTorque);
    // F and its opposite act at the held point: no torque (the slots'
    // positions would leave one where the weights are clipped)
    contact.subtractSlotPowers(slotForce, slotV, power);
    syncTools::syncPointList(mesh, added, plusEqOp<vector>(), vector::zero);
    pointForce_ += added;

    contact.reportNodeFriction(largestRatio, largestPower);

    forAll(patches, s)
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                faces_.lm().boundaryFieldRef()[patches[s]]
            );
        condition.correctStageForce(condition.stageForce() + patchForce[s]);
    }
}


Foam::scalar Foam::deformationUpdates::compatible::wallNormalParts
(
    const label patchi,
    const vectorField& reaction,
    scalarField& normal
) const
{
    const fvPatch& patch = faces_.mesh().boundary()[patchi];
    const vectorField& Sf = patch.Sf();
    const scalarField& magSf = patch.magSf();
    const labelList& fixingFace = fixingFace_[patchi];

    // The faces' forces on the momentum rate (their damping of the
    // approach), their normal parts at the held points
    const scalarField load
    (
        heldPointLoads(patchi, -(releaseFaceForce_[patchi] & Sf)/magSf)
    );

    // Each held point's part of the normal force (this rank's, against
    // the face's outward normal: the reaction and the faces' damping).
    // The wall pushes as a whole, so a point may pull: its pull is taken
    // from the pushing points' forces in proportion, so that the friction
    // of the wall is at most mu times its normal force (with the pushing
    // points alone, a sliding block's |dp_x/dt| passed muStatic times its
    // normal force by 5e-3 M g in steps where it bounced)
    normal.setSize(fixingFace.size());
    normal = 0;
    scalar net = 0;
    scalar pushing = 0;
    forAll(fixingFace, j)
    {
        const label i = fixingFace[j];
        if (i >= 0)
        {
            normal[j] = load[j] - (reaction[j] & Sf[i])/magSf[i];
            net += normal[j];
            pushing += max(normal[j], scalar(0));
        }
    }
    reduce(net, sumOp<scalar>());
    reduce(pushing, sumOp<scalar>());
    return pushing > 0 ? min(max(net, scalar(0))/pushing, scalar(1)) : 0;
}


void Foam::deformationUpdates::compatible::addWallFriction
(
    vector& torque
)
{
    const fvMesh& mesh = faces_.mesh();
    vectorField added(mesh.nPoints(), Zero);

    forAll(wallShare_, patchi)
    {
        if (!wallShare_.set(patchi))
        {
            continue;
        }
        rigidWallFvPatchVectorField& wall =
            refCast<rigidWallFvPatchVectorField>
            (
                faces_.lm().boundaryFieldRef()[patchi]
            );
        const fvPatch& patch = wall.patch();
        const labelList& meshPoints = patch.patch().meshPoints();
        const labelList& fixingFace = fixingFace_[patchi];
        const vectorField& share = wallShare_[patchi];
        const vectorField& Sf = patch.Sf();
        const scalarField& magSf = patch.magSf();
        const labelUList& faceCells = patch.faceCells();
        const vector V(wall.velocity(faces_.stageTime()));

        scalarField& power = wall.pointPower();
        power = 0;
        vector force(Zero);

        scalarField normal;
        const scalar scale = wallNormalParts(patchi, share, normal);

        forAll(meshPoints, j)
        {
            const label i = fixingFace[j];
            if (i < 0 || normal[j] <= 0)
            {
                continue;
            }

            // A sticking point's friction is its reaction's tangential
            // part, which moves with the wall
            if (nodeStuck_[patchi][j])
            {
                const vector n(Sf[i]/magSf[i]);
                power[i] += (share[j] - (share[j] & n)*n) & V;
                continue;
            }

            const scalar N = scale*normal[j];
            const scalar S =
                frictionArea_[patchi][j]/frictionMarks_[patchi][j];

            // The point's velocity relative to the wall, in its free
            // directions (along the wall, and the planes it lies on)
            const label pointi = meshPoints[j];
            vector w(pointVBeforeUpwinding_[pointi] - V);
            constraints_.constrainOne(pointi, w);

            const label celli = faceCells[i];
            const scalar Z = law_.rho(celli)*law_.Us(celli);
            const vector F
            (
                wall.friction().tangentialTraction(-Z*S*w, N, Zero)
            );
            if (magSqr(F) == 0)
            {
                continue;
            }

            added[pointi] -= F;
            force += F;
            power[i] += F & pointVBeforeUpwinding_[pointi];

            if (pointDisplacement_)
            {
                torque +=
                    (mesh.points()[pointi] + (*pointDisplacement_)[pointi])
                  ^ F;
            }
        }

        wall.correctStageForce(wall.stageForce() + force);
    }

    syncTools::syncPointList(mesh, added, plusEqOp<vector>(), vector::zero);
    pointForce_ += added;
}


// ************************************************************************* //
