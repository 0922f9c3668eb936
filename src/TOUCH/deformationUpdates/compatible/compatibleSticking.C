/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's sticking hold (the method: compatibleFriction.C):
    per stage, a held point (a side node, a rigid wall's point) sticks while
    its sticking force -Z S w and the tangential reaction of a hold in every
    direction both lie in the friction law's static cone about its normal
    force N; it is then held in every direction no other condition fixes,
    at the partner's velocity (set later, holdNodesOnSurfaces) or the
    wall's.  The decision is made where a face of the patch holds the point
    and applied on every rank that shares it.

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "rigidWallFvPatchVectorField.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::stickNodes
(
    const label patchi,
    const tensorField& ownFixed
)
{
    const fvMesh& mesh = faces_.mesh();
    contactSurfaces& contact = faces_.contact();
    const polyPatch& pp = mesh.boundaryMesh()[patchi];
    const labelList& meshPoints = pp.meshPoints();
    const labelList& fixingFace = fixingFace_[patchi];
    const vectorField& Sf = mesh.boundary()[patchi].Sf();
    bodyContactFvPatchVectorField& condition =
        refCast<bodyContactFvPatchVectorField>
        (
            faces_.lm().boundaryFieldRef()[patchi]
        );
    const frictionLaw& law = condition.friction();
    const pointField& X = mesh.points();
    const vectorField& pointU =
        mesh.lookupObject<pointVectorField>("pointD").primitiveField();

    // The partners' cells' velocities at their points, and the faces'
    // damping of the approach at the held points (all ranks' parts)
    const vectorField slotAv(contact.gatherSlots(pointAv_));
    scalarField load
    (
        heldPointLoads(patchi, -(condition.traction() & Sf), false)
    );

    labelList sticks(meshPoints.size(), 0);
    DynamicList<label> slots;
    DynamicList<scalar> weights;

    forAll(meshPoints, j)
    {
        const label i = fixingFace[j];
        if (i < 0 || law.frictionless())
        {
            continue;
        }
        const label pointi = meshPoints[j];
        const vector& e = nodeNormal_[patchi][j];
        const tensor own(ownDirections(pointi, ownFixed[j]));

        // The reaction of a hold in every direction, its part in those
        // directions (the whole point's, all ranks'), and the normal force
        const vector R(own & pointForce_[pointi]);
        const scalar N = load[j] + mag(R & e);

        // The relative velocity of the cells' motion at the point and
        // under it on the partner, and the tangential reaction a hold
        // would take
        slots.clear();
        weights.clear();
        contact.surfaceWeights
        (
            contact.localFace(patchi, i), X[pointi] + pointU[pointi], e,
            slots, weights
        );
        vector partner(Zero);
        forAll(slots, k)
        {
            partner += weights[k]*slotAv[slots[k]];
        }
        const tensor tangential(own & (tensor::I - sqr(e)));
        const vector w(tangential & (pointAv_[pointi] - partner));
        const vector Rt(tangential & R);
        const scalar Z = contact.pairShearImpedance
        (
            contact.localFace(patchi, i), slots[0]
        );
        const vector stick(-Z*frictionArea_[patchi][j]*w);

        // Both within the static cone: the law keeps them whole
        sticks[j] =
            law.tangentialTraction(stick, N, Zero) == stick
         && law.tangentialTraction(Rt, N, Zero) == Rt;
    }

    holdSticking(patchi, ownFixed, sticks, nullptr);
}


void Foam::deformationUpdates::compatible::stickWallPoints
(
    const label patchi,
    const tensorField& ownFixed
)
{
    rigidWallFvPatchVectorField& wall =
        refCast<rigidWallFvPatchVectorField>
        (
            faces_.lm().boundaryFieldRef()[patchi]
        );
    const frictionLaw& law = wall.friction();
    const fvPatch& patch = wall.patch();
    const labelList& meshPoints = patch.patch().meshPoints();
    const labelList& fixingFace = fixingFace_[patchi];
    const vectorField& Sf = patch.Sf();
    const scalarField& magSf = patch.magSf();
    const labelUList& faceCells = patch.faceCells();
    const vector V(wall.velocity(faces_.stageTime()));

    // Each held point's normal force pushing the body off the wall, as
    // addWallFriction takes it (the pulling points' pull taken from the
    // pushing ones), so that a point sticks under the cone it slides in;
    // the ranks' parts, whole below
    scalarField normal;
    vectorField reaction(meshPoints.size(), Zero);
    forAll(meshPoints, j)
    {
        if (fixingFace[j] >= 0)
        {
            const label pointi = meshPoints[j];
            frictionMarks_[patchi][j] = pointMarks_[pointi];
            reaction[j] =
                conditionReaction(pointi, ownFixed[j])/pointMarks_[pointi];
        }
    }
    const scalar scale = wallNormalParts(patchi, reaction, normal);

    labelList sticks(meshPoints.size(), 0);
    forAll(meshPoints, j)
    {
        const label i = fixingFace[j];
        if (i < 0 || normal[j] <= 0 || law.frictionless())
        {
            continue;
        }
        const label pointi = meshPoints[j];
        const scalar N = scale*normal[j]*pointMarks_[pointi];
        const vector n(Sf[i]/magSf[i]);
        const tensor own(ownDirections(pointi, ownFixed[j]));

        // The sticking force of the cells' motion at the point relative
        // to the wall, and the tangential reaction a hold would take
        const tensor tangential(own & (tensor::I - sqr(n)));
        const vector w(tangential & (pointAv_[pointi] - V));
        const vector Rt(tangential & pointForce_[pointi]);
        const scalar Z = law_.rho(faceCells[i])*law_.Us(faceCells[i]);
        const vector stick(-Z*frictionArea_[patchi][j]*w);

        sticks[j] =
            law.tangentialTraction(stick, N, Zero) == stick
         && law.tangentialTraction(Rt, N, Zero) == Rt;
    }

    holdSticking(patchi, ownFixed, sticks, &V);
}


Foam::tensor Foam::deformationUpdates::compatible::ownDirections
(
    const label pointi,
    const tensor& ownFixed
) const
{
    const tensor others(constraints_.fixedSum(pointi) - ownFixed);
    return
        magSqr(others) > 1e-18
      ? kinematicPointConstraints::freeProjector(others)
      : tensor::I;
}


void Foam::deformationUpdates::compatible::holdSticking
(
    const label patchi,
    const tensorField& ownFixed,
    labelList& sticks,
    const vector* wallVelocity
)
{
    // Decided where a face of the patch holds the point; held on every
    // rank that shares it (its constraint is there too, formed from all
    // ranks' faces), else the ranks' point velocities part
    const labelList& meshPoints =
        faces_.mesh().boundary()[patchi].patch().meshPoints();
    syncTools::syncPointList
    (
        faces_.mesh(), meshPoints, sticks, maxEqOp<label>(), label(0)
    );

    boolList& stuck = nodeStuck_[patchi];
    forAll(meshPoints, j)
    {
        stuck[j] = sticks[j];
        if (sticks[j])
        {
            const label pointi = meshPoints[j];
            const tensor own(ownDirections(pointi, ownFixed[j]));
            nodeOwn_[patchi][j] = own;
            constraints_.holdAll(pointi);
            if (wallVelocity)
            {
                constraints_.prescribeOwn(pointi, own, *wallVelocity);
            }
        }
    }
}


// ************************************************************************* //
