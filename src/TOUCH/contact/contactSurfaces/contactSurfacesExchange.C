/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The exchange of contactSurfaces: every pair of opposed faces that
    overlap, once, with the two-body Riemann problem, its active set and
    friction, each pair's force applied over its overlap area to both
    faces (equal and opposite).

\*---------------------------------------------------------------------------*/

#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace Foam
{
    //- A face within this fraction of its size of its partner touches it
    static const scalar contactTouchingTolerance = 1e-6;

    //- Opposed faces: the cosine of the angle of their normals below this
    static const scalar contactOpposedCos = -0.5;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactSurfaces::faceSums::faceSums(const label n)
:
    force(n, Zero),
    moment(n, Zero),
    weight(n, Zero),
    normalSum(n, Zero),
    velocitySum(n, Zero),
    active(n, 0),
    slipSum(n, Zero),
    slipWeight(n, Zero),
    normalForce(0),
    area(0),
    penetration(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactSurfaces::faceSums::combine()
{
    if (!Pstream::parRun())
    {
        return;
    }

    Pstream::listCombineGather(force, plusEqOp<vector>());
    Pstream::listCombineScatter(force);
    Pstream::listCombineGather(moment, plusEqOp<vector>());
    Pstream::listCombineScatter(moment);
    Pstream::listCombineGather(weight, plusEqOp<scalar>());
    Pstream::listCombineScatter(weight);
    Pstream::listCombineGather(normalSum, plusEqOp<vector>());
    Pstream::listCombineScatter(normalSum);
    Pstream::listCombineGather(velocitySum, plusEqOp<vector>());
    Pstream::listCombineScatter(velocitySum);
    Pstream::listCombineGather(active, maxEqOp<label>());
    Pstream::listCombineScatter(active);
    Pstream::listCombineGather(slipSum, plusEqOp<vector>());
    Pstream::listCombineScatter(slipSum);
    Pstream::listCombineGather(slipWeight, plusEqOp<scalar>());
    Pstream::listCombineScatter(slipWeight);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactSurfaces::exchange(volVectorField& lm, faceSums& sums)
{
    const label offset = globalFaces_.localStart();

    // 1. The pairs of this rank's faces and whether each is in contact
    DynamicList<contactPair> pairs(4*globalFaces_.localSize());

    forAll(patches_, s)
    {
        forAll(mesh_.boundary()[patches_[s]], i)
        {
            const label k = start_[s] + i;
            const label gi = offset + k;

            for (const label gj : candidates_[k])
            {
                // Each pair once, from its face of the smaller index
                if (gj <= gi || !allowed_[slot_[gi]][slot_[gj]])
                {
                    continue;
                }
                if ((n_[gi] & n_[gj]) > contactOpposedCos)
                {
                    continue;
                }

                contactPair pair;
                pair.s = s;
                pair.i = i;
                pair.gi = gi;
                pair.gj = gj;
                pair.n = n_[gi] - n_[gj];
                pair.n /= mag(pair.n);
                pair.gap = (x_[gj] - x_[gi]) & pair.n;

                // Not a face of the far side of a body (self-contact of a
                // thin part): a partner lies at most half a face behind
                const scalar size =
                    max(Foam::sqrt(a_[gi]), Foam::sqrt(a_[gj]));
                if (pair.gap < -0.5*size || pair.gap > 2*size)
                {
                    continue;
                }

                pair.share = overlapArea(gi, gj, pair.n, pair.gap);
                if (pair.share <= 0)
                {
                    continue;
                }

                // The normal traction of the two-body Riemann problem, both
                // tractions on the plane of normal n (side 2's own normal
                // is -n)
                const scalar Zn1 = Zp_[gi];
                const scalar Zn2 = Zp_[gj];
                pair.tN =
                    (
                        Zn2*(t_[gi] & pair.n) - Zn1*(t_[gj] & pair.n)
                      + Zn1*Zn2*((v_[gj] - v_[gi]) & pair.n)
                    )/(Zn1 + Zn2);

                // A pair touches when compressive and within the rigid
                // wall's tolerance of the faces' sizes (the lowest free
                // point of either face: on curved bodies the centres lag
                // the surfaces; validation/sphereImpact/FINDINGS.md), and
                // stays while compressive if both faces were in contact.
                // Where the update holds the points, only pairs whose
                // faces face each other act (opposed: not a neighbour's
                // sliver)
                pair.active =
                    pair.tN < 0
                 && opposed(gi, gj, pair.n)
                 && (
                        (wasInContact_[gi] && wasInContact_[gj])
                     || pointGap(gi, gj, pair.n)
                     <= contactTouchingTolerance
                       *(Foam::sqrt(a_[gi]) + Foam::sqrt(a_[gj]))
                    );

                if (pair.active)
                {
                    sums.normalSum[gi] += pair.share*pair.n;
                    sums.normalSum[gj] -= pair.share*pair.n;
                }
                pairs.append(pair);
            }
        }
    }

    // The faces' mean normals of their pairs in contact, on every rank:
    // with friction each pair's cone is narrowed by how far its normal
    // lies from its faces' (below)
    if (friction_ && Pstream::parRun())
    {
        Pstream::listCombineGather(sums.normalSum, plusEqOp<vector>());
        Pstream::listCombineScatter(sums.normalSum);
    }

    // 2. Each pair's forces
    forAll(patches_, s)
    {
        refCast<bodyContactFvPatchVectorField>
        (
            lm.boundaryFieldRef()[patches_[s]]
        ).frictionPower() = 0;
    }

    for (const contactPair& pair : pairs)
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                lm.boundaryFieldRef()[patches_[pair.s]]
            );
        addPair(pair, condition, sums);
    }

    // The normal sums are those of the ranks (combined with the others)
    if (friction_ && Pstream::parRun())
    {
        vectorField local(sums.normalSum.size(), Zero);
        for (const contactPair& pair : pairs)
        {
            if (pair.active)
            {
                local[pair.gi] += pair.share*pair.n;
                local[pair.gj] -= pair.share*pair.n;
            }
        }
        sums.normalSum = local;
    }
}


void Foam::contactSurfaces::warnStiffNodes
(
    const label gNodes,
    const label gSurface
)
{
    if (stiffNodesWarned_ || !(Zp_[gNodes] > stiffNodesRatio*Zp_[gSurface]))
    {
        return;
    }
    stiffNodesWarned_ = true;

    WarningInFunction
        << "The bodyContact patch "
        << mesh_.boundary()[patches_[slot_[gNodes]]].name()
        << " has side nodes and an impedance " << Zp_[gNodes]/Zp_[gSurface]
        << " times its partner "
        << mesh_.boundary()[patches_[slot_[gSurface]]].name() << "'s." << nl
        << "    Its reactions then load the softer body's points and can"
        << " make the run unstable (a steel ball on a plate of 1000 times"
        << " its impedance" << nl
        << "    grew 13 E0 in a step; 10 times was stable): give side nodes"
        << " to the softer side (validation/sphereImpact/FINDINGS.md 12)."
        << " Warned once." << nl << endl;
}


void Foam::contactSurfaces::addPair
(
    const contactPair& pair,
    bodyContactFvPatchVectorField& condition,
    faceSums& sums
)
{
    const label gi = pair.gi;
    const label gj = pair.gj;
    const vector& nij = pair.n;
    const scalar share = pair.share;
    const scalar tN = pair.tN;

    const frictionLaw& law = condition.friction();
    const bool friction = !law.frictionless();

    const vector t1(t_[gi]);
    const vector t2(-t_[gj]);
    const vector dv(v_[gj] - v_[gi]);

    if (!pair.active)
    {
        if (friction)
        {
            // Side 1's sliding relative to side 2 as it arrives: a face
            // that lands sliding starts with the kinetic limit
            const vector arriving(((dv & nij)*nij) - dv);
            sums.slipSum[gi] += share*arriving;
            sums.slipSum[gj] -= share*arriving;
            sums.slipWeight[gi] += share;
            sums.slipWeight[gj] += share;
        }
        return;
    }

    // A pair of side nodes: the update holds the nodes side's points on
    // the other's surface, and their reactions carry the contact force
    // (compatible::transferNodeReactions); the nodes side alone pushed on
    // (its points held), the other's points free.  Here only the
    // upwinding of the two cells' approach, as an interior face's: the
    // Riemann flux's damping Z1 Z2/(Z1 + Z2) of the cell jump along n
    // times phi^2, phi the share of it the reconstructed jump keeps, a
    // force on both cells, equal and opposite, whose power is minus that
    // times the jump: it never feeds energy, never pulls (none while the
    // cells part), and takes the velocity jump of an impact start, which
    // the held points alone left undamped (two bars of non-matching faces
    // meeting at 2 v gained 6e-6 E0 in the first step under RK2)
    if (nodePair(gi, gj))
    {
        const scalar cellJump = (vCell_[gi] - vCell_[gj]) & nij;
        if (cellJump > 0)
        {
            const scalar phi =
                min
                (
                    max(((v_[gi] - v_[gj]) & nij)/cellJump, scalar(0)),
                    scalar(1)
                );
            const scalar Zn1 = Zp_[gi];
            const scalar Zn2 = Zp_[gj];
            const vector damping
            (
                -(Zn1*Zn2/(Zn1 + Zn2))*share*sqr(phi)*cellJump*nij
            );
            sums.force[gi] += damping;
            sums.force[gj] -= damping;
            sums.normalForce -= damping & nij;
            const vector m(0.5*(x_[gi] + x_[gj]) ^ damping);
            sums.moment[gi] += m;
            sums.moment[gj] -= m;
        }

        const label gNodes = nodes_[slot_[gi]] ? gi : gj;
        warnStiffNodes(gNodes, gNodes == gi ? gj : gi);
        sums.weight[gNodes] += share;
        sums.velocitySum[gNodes] += (share*(v_[gNodes] & nij))*nij;
        sums.active[gi] = 1;
        sums.active[gj] = 1;
        sums.area += share;
        sums.penetration = max(sums.penetration, -pair.gap);
        return;
    }

    vector f(tN*nij);

    if (friction)
    {
        // The sticking traction (S-wave impedances), which makes the two
        // sides' tangential velocities equal, and the law's return to its
        // cone, decided with the sliding of face gi's pairs in the last
        // stage; each side's tangential velocity then follows its own
        // characteristic, so side 1 slides relative to side 2 at
        // (t - stick)(1/Z_1 + 1/Z_2): power t . slip <= 0
        const scalar Zt1 = Zs_[gi];
        const scalar Zt2 = Zs_[gj];
        const tensor tangential(tensor::I - sqr(nij));
        const vector stick
        (
            tangential & ((Zt2*t1 + Zt1*t2 + Zt1*Zt2*dv)/(Zt1 + Zt2))
        );
        vector tT
        (
            law.tangentialTraction(stick, -tN, condition.slip()[pair.i])
        );

        // A face's traction is the sum of its pairs', of normals apart by
        // up to delta from the face's mean: each pair's cone is narrowed by
        // delta, so that every face's sum stays within the law's cone
        // about its mean normal (a cone is convex).  Scaled towards zero
        // along itself, the traction still opposes the sliding
        const vector mi(sums.normalSum[gi]/mag(sums.normalSum[gi]));
        const vector mj(-sums.normalSum[gj]/mag(sums.normalSum[gj]));
        const scalar delta =
            max
            (
                Foam::acos(min(max(nij & mi, -1.0), 1.0)),
                Foam::acos(min(max(nij & mj, -1.0), 1.0))
            );
        const scalar ratio =
            Foam::tan
            (
                max(Foam::atan(law.maxCoefficient()) - delta, 0.0)
            );
        if (mag(tT) > -ratio*tN)
        {
            tT *= -ratio*tN/mag(tT);
        }

        const vector pairSlip((tT - stick)*(1/Zt1 + 1/Zt2));
        const scalar pairPower = (tT & pairSlip)*share;
        condition.frictionPower() += pairPower;
        pairFrictionPower_ = max(pairFrictionPower_, pairPower);
        pairFrictionRatio_ = max(pairFrictionRatio_, mag(tT)/max(-tN, VSMALL));
        sums.slipSum[gi] += share*pairSlip;
        sums.slipSum[gj] -= share*pairSlip;
        sums.slipWeight[gi] += share;
        sums.slipWeight[gj] += share;
        f += tT;
    }
    f *= share;

    sums.force[gi] += f;
    sums.force[gj] -= f;

    // Both sides' torques at the pair's contact point
    const vector m(0.5*(x_[gi] + x_[gj]) ^ f);
    sums.moment[gi] += m;
    sums.moment[gj] -= m;

    // The compatible update's constraint: the impedance-weighted mean of
    // the two sides' normal velocities, less the two sides' shares of the
    // nodal forces at the faces' points per area, f_1/a_1 + f_2/a_2 (zero
    // with the other updates), along n over (Z1 + Z2).  Not the Riemann
    // velocity: under the constraint the traction jump is carried by the
    // two sides' reactions, and counted again it moved the points faster
    // than both sides' cells (two balls gained +0.44 E0).  With the nodal
    // forces' shares the faces' dampings towards it take the two
    // reactions' sum back, so that the two sides' forces are equal and
    // opposite pair by pair and the points' prescribed motion dissipates,
    // -(f_1 + f_2)^2/((Z1 + Z2) a) for matching faces
    // (validation/sphereImpact/FINDINGS.md 7)
    const scalar Zn1 = Zp_[gi];
    const scalar Zn2 = Zp_[gj];
    const scalar vN =
        (
            Zn1*(v_[gi] & nij) + Zn2*(v_[gj] & nij)
          - ((f_[gi]/a_[gi] + f_[gj]/a_[gj]) & nij)
        )/(Zn1 + Zn2);
    sums.weight[gi] += share;
    sums.weight[gj] += share;
    sums.velocitySum[gi] += (share*vN)*nij;
    sums.velocitySum[gj] += (share*vN)*nij;
    sums.active[gi] = 1;
    sums.active[gj] = 1;

    sums.normalForce -= tN*share;
    sums.area += share;
    sums.penetration = max(sums.penetration, -pair.gap);
    mostTensile_ = max(mostTensile_, tN);
}


// ************************************************************************* //
