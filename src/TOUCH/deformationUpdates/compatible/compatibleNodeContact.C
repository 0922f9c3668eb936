/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's contact between bodies with side nodes (a
    node-to-surface contact): the points of the patch with side nodes are
    held along the surface's normal e at the velocity of the partner
    surface under them, X = sum_b w_b v_b over the partner face's points b
    (their final velocities, upwinding included; w_b linear over a
    triangle of the face split about the mean of its points), and the
    constraint's reaction R at each (its part along e) is given to those
    points as nodal forces w_b R.  Momentum: the held side gets R, the
    partner -R, at every point.  Energy: the reaction's work on the held
    side is R . e (e . X), on the partner -sum_b w_b R . v_b = -R . X, and
    R lies along e: they cancel, whatever the two surfaces' meshes.  Each
    body's remainder is then its upwindings' dissipation, at the partner's
    points kappa phi |Pi (f + w R)|^2 >= 0 (their upwinding sees the
    reactions too, so that the surface moves with the net force, not away
    from the contact).  The faces add the damping of the two cells'
    approach (contactSurfaces), equal and opposite, and a held point
    whose reaction pulls is let go for the stage (releaseTensileNodes, in
    compatibleWallForces.C).  With both sides held (side both) each side
    holds its own faces, the two forces differ where the faces do not
    match, and balancing their sum made energy (a steel ball on a steel
    plate: validation/sphereImpact/FINDINGS.md 11 and 12).

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::transferNodeReactions
(
    vector& torque
)
{
    if (!hasNodeContact_)
    {
        return;
    }

    const fvMesh& mesh = faces_.mesh();
    contactSurfaces& contact = faces_.contact();
    const pointField& X = mesh.points();
    const vectorField& pointU =
        mesh.lookupObject<pointVectorField>("pointD").primitiveField();

    holdPatch_.clear();
    holdIndex_.clear();
    holdStart_.clear();
    holdSlots_.clear();
    holdWeights_.clear();

    // Each held point's partner slots and weights, and its share of the
    // reaction spread over them
    scalar nodeNormalForce = 0;
    scalar nodeMostTensile = -GREAT;

    slotForce_.setSize(contact.nSlots());
    slotForce_ = Zero;
    vectorField& slotForce = slotForce_;

    forAll(nodeShare_, patchi)
    {
        if (!nodeShare_.set(patchi) || !fixingFace_.set(patchi))
        {
            continue;
        }

        const fvPatch& patch = mesh.boundary()[patchi];
        const labelList& meshPoints = patch.patch().meshPoints();
        const labelList& fixingFace = fixingFace_[patchi];
        const vectorField& share = nodeShare_[patchi];
        const vectorField& normal = nodeNormal_[patchi];
        const vectorField& Sf = patch.Sf();
        const faceList& localFaces = patch.patch().localFaces();

        forAll(meshPoints, j)
        {
            if (fixingFace[j] < 0)
            {
                continue;
            }

            const label pointi = meshPoints[j];
            const label from = holdSlots_.size();
            holdPatch_.append(patchi);
            holdIndex_.append(j);
            holdStart_.append(from);

            contact.surfaceWeights
            (
                contact.localFace(patchi, fixingFace[j]),
                X[pointi] + pointU[pointi],
                normal[j],
                holdSlots_,
                holdWeights_
            );

            for (label h = from; h < holdSlots_.size(); ++h)
            {
                slotForce[holdSlots_[h]] += holdWeights_[h]*share[j];
            }

            // The report: the reaction along the face's outward normal
            // (negative: pushing on the body, compressive) and as a
            // traction over the point's share of the face
            const label facei = fixingFace[j];
            const scalar outward = share[j] & (Sf[facei]/mag(Sf[facei]));
            nodeNormalForce -= outward;
            nodeMostTensile =
                max
                (
                    nodeMostTensile,
                    outward*localFaces[facei].size()/mag(Sf[facei])
                );
        }
    }
    holdStart_.append(holdSlots_.size());

    if (Pstream::parRun())
    {
        Pstream::listCombineGather(slotForce, plusEqOp<vector>());
        Pstream::listCombineScatter(slotForce);
    }

    // To the partner's points (each slot on the rank of its face, then
    // completed at the points the ranks share), its patch's force and the
    // torque at the partner's points
    vectorField added(mesh.nPoints(), Zero);
    List<vector> patchForce(contact.patches().size(), Zero);
    vector slotTorque(Zero);
    contact.addSlotForces(slotForce, added, patchForce, slotTorque);
    syncTools::syncPointList(mesh, added, plusEqOp<vector>(), vector::zero);
    pointForce_ += added;

    // The partner's torque at the held points, where the held side's is
    // taken (reportWallForces): each reaction and its opposite act on one
    // line, also where a point lies beyond the partner's edge and its
    // weights are clipped to the face (taken at the slots, the two blocks
    // of an oblique collision drifted by 4e-4 of their angular momentum)
    if (pointDisplacement_)
    {
        forAll(holdPatch_, h)
        {
            const label patchi = holdPatch_[h];
            const label j = holdIndex_[h];
            const label pointi =
                mesh.boundaryMesh()[patchi].meshPoints()[j];
            torque -=
                (X[pointi] + (*pointDisplacement_)[pointi])
              ^ nodeShare_[patchi][j];
        }
    }

    // The report waits for the stage's friction (holdNodesOnSurfaces)
    nodeNormalForce_ = nodeNormalForce;
    nodeMostTensile_ = nodeMostTensile;

    forAll(contact.patches(), s)
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                faces_.lm().boundaryFieldRef()[contact.patches()[s]]
            );
        condition.correctStageForce(condition.stageForce() + patchForce[s]);
    }
}


void Foam::deformationUpdates::compatible::holdNodesOnSurfaces
(
    vectorField& pointV
)
{
    if (!hasNodeContact_)
    {
        return;
    }

    const fvMesh& mesh = faces_.mesh();
    contactSurfaces& contact = faces_.contact();
    // The partners' points' velocities, final (their upwinding by the
    // stresses' and the reactions' nodal forces included)
    const vectorField slotV(contact.gatherSlots(pointV));

    // Per patch point, the sum of the partner's velocities the ranks
    // holding it found, and their number
    PtrList<vectorField> velocity(nodeShare_.size());
    PtrList<labelField> count(nodeShare_.size());
    forAll(nodeShare_, patchi)
    {
        if (nodeShare_.set(patchi))
        {
            const label n = nodeShare_[patchi].size();
            velocity.set(patchi, new vectorField(n, Zero));
            count.set(patchi, new labelField(n, Zero));
        }
    }

    forAll(holdPatch_, h)
    {
        const label patchi = holdPatch_[h];
        const label j = holdIndex_[h];

        vector partner(Zero);
        for (label k = holdStart_[h]; k < holdStart_[h + 1]; ++k)
        {
            partner += holdWeights_[k]*slotV[holdSlots_[k]];
        }
        velocity[patchi][j] += partner;
        ++count[patchi][j];
    }

    // The power of the exchange on each side (the account of
    // boundaryWork): the partners' points at the mapped velocities, the
    // held points' reactions at their prescribed ones
    const labelList& patches = contact.patches();
    scalarField power(patches.size(), Zero);
    contact.subtractSlotPowers(slotForce_, slotV, power);

    forAll(nodeShare_, patchi)
    {
        if (!nodeShare_.set(patchi))
        {
            continue;
        }

        const labelList& meshPoints =
            mesh.boundary()[patchi].patch().meshPoints();
        syncTools::syncPointList
        (
            mesh, meshPoints, velocity[patchi], plusEqOp<vector>(),
            vector::zero
        );
        syncTools::syncPointList
        (
            mesh, meshPoints, count[patchi], plusEqOp<label>(), label(0)
        );

        // Along e; a point that sticks (with friction) in every direction
        // its contact holds
        forAll(meshPoints, j)
        {
            if (count[patchi][j] > 0)
            {
                const label pointi = meshPoints[j];
                const vector X(velocity[patchi][j]/count[patchi][j]);
                if (nodeStuck_.set(patchi) && nodeStuck_[patchi][j])
                {
                    const tensor& own = nodeOwn_[patchi][j];
                    constraints_.prescribeOwn(pointi, own, X);
                    pointV[pointi] += own & (X - pointV[pointi]);
                }
                else
                {
                    const vector& e = nodeNormal_[patchi][j];
                    const scalar s = e & X;
                    constraints_.prescribeAlong(pointi, e, s);
                    pointV[pointi] += (s - (pointV[pointi] & e))*e;
                }
            }
        }
    }

    // The held points' reactions at their prescribed velocities (the
    // reaction lies in the directions held)
    forAll(holdPatch_, h)
    {
        const label patchi = holdPatch_[h];
        const label j = holdIndex_[h];
        const label pointi =
            mesh.boundaryMesh()[patchi].meshPoints()[j];
        power[patches.find(patchi)] += nodeShare_[patchi][j] & pointV[pointi];
    }

    // the friction's at the points' velocities before the upwindings
    if (nodeFriction_)
    {
        addNodeFriction(power);
    }

    // and the faces' forces (the damping of the cells' approach) at their
    // cells' velocities
    const vectorField& lm = faces_.lm().primitiveField();
    forAll(patches, s)
    {
        if (contact.nodesContact(s))
        {
            bodyContactFvPatchVectorField& condition =
                refCast<bodyContactFvPatchVectorField>
                (
                    faces_.lm().boundaryFieldRef()[patches[s]]
                );
            const labelUList& faceCells = condition.patch().faceCells();
            const scalarField& magSf = condition.patch().magSf();
            const vectorField& traction = condition.traction();
            forAll(faceCells, i)
            {
                const label celli = faceCells[i];
                power[s] +=
                    magSf[i]*(traction[i] & lm[celli])/law_.rho(celli);
            }
            condition.setStagePower(power[s]);
        }
    }

    contact.completeReport(nodeNormalForce_, nodeMostTensile_);
}


// ************************************************************************* //
