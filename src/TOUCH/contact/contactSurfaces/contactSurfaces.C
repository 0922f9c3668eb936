/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "ListListOps.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace Foam
{
    //- A face within this fraction of its size of its partner touches it
    static const scalar contactTouchingTolerance = 1e-6;

    //- Number of contact faces of this rank
    static label nContactFaces(const fvMesh& mesh, const labelList& patches)
    {
        label n = 0;
        for (const label patchi : patches)
        {
            n += mesh.boundary()[patchi].size();
        }
        return n;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::contactSurfaces::contactPatches
(
    const volVectorField& lm
)
{
    DynamicList<label> patches;
    forAll(lm.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = lm.boundaryField()[patchi];
        if
        (
            isA<solidFluxFvPatchVectorField>(pf)
         && refCast<const solidFluxFvPatchVectorField>(pf).contactSurface()
        )
        {
            patches.append(patchi);
        }
    }
    return labelList(std::move(patches));
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactSurfaces::gather
(
    const Field<Type>& local
) const
{
    if (!Pstream::parRun())
    {
        return tmp<Field<Type>>(new Field<Type>(local));
    }

    List<Field<Type>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    return tmp<Field<Type>>
    (
        new Field<Type>
        (
            ListListOps::combine<Field<Type>>(all, accessOp<Field<Type>>())
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactSurfaces::contactSurfaces
(
    const fvMesh& mesh,
    const volVectorField& lm
)
:
    mesh_(mesh),
    patches_(contactPatches(lm)),
    allowed_(),
    start_(patches_.size() + 1, 0),
    globalFaces_(nContactFaces(mesh, patches_)),
    searchSize_(0),
    mostTensile_(-GREAT),
    friction_(false),
    frictionRatio_(0),
    pairFrictionRatio_(0),
    pairFrictionPower_(-GREAT),
    matchChecked_(false)
{
    setAllowed(lm);

    for (const label patchi : patches_)
    {
        friction_ =
            friction_
         || !refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patchi]
            ).friction().frictionless();
    }
    reduce(friction_, orOp<bool>());

    forAll(patches_, a)
    {
        start_[a + 1] = start_[a] + mesh.boundary()[patches_[a]].size();
    }

    if (Pstream::master())
    {
        const fileName dir
        (
            mesh.time().globalPath()/"postProcessing"/"contact"
           /mesh.time().timeName()
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/"contact.dat"));
        file_()
            << "# Contact of the bodyContact patches: at the first stage of"
            << " each step; force and area summed over the pairs" << nl
            << "# Time nFaces normalForce area maxPenetration"
            << " mostTensileTraction"
            << (friction_ ? " maxFrictionRatio maxPairFrictionPower"
                " frictionPower maxPairFrictionRatio" : "") << nl;
        file_().precision(12);
    }
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

bool Foam::contactSurfaces::any(const volVectorField& lm)
{
    return returnReduce(contactPatches(lm).size(), maxOp<label>()) > 0;
}


void Foam::contactSurfaces::update
(
    const PtrList<solidFluxFvPatchVectorField::interiorState>& states,
    const volTensorField& F,
    volVectorField& lm,
    const label stage,
    const scalar time
)
{
    // 1. This rank's faces on the current surface, per current area
    const label nLocal = globalFaces_.localSize();
    pointField x(nLocal);
    vectorField n(nLocal);
    vectorField v(nLocal);
    vectorField t(nLocal);
    scalarField Zp(nLocal);
    scalarField Zs(nLocal);
    scalarField a(nLocal);
    vectorField f(nLocal);
    labelList slot(nLocal);

    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        const solidFluxFvPatchVectorField::interiorState& state = states[s];
        const labelUList& faceCells = patch.faceCells();
        const vectorField& Sf = patch.Sf();
        const scalarField& magSf = patch.magSf();
        const vectorField& nodalForce =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[s]]
            ).nodalForce();

        forAll(faceCells, i)
        {
            const label k = start_[s] + i;
            f[k] = nodalForce[i];

            // Current area by the cell's F (Nanson), and the factor from
            // per reference area to per current area
            a[k] = mag(cof(F[faceCells[i]]) & Sf[i]);
            const scalar perCurrent = magSf[i]/a[k];

            x[k] = state.xPoints[i];
            n[k] = state.n[i];
            v[k] = state.p[i]/state.rho[i];
            t[k] = perCurrent*state.t[i];
            Zp[k] = perCurrent*state.rho[i]*state.Up[i];
            Zs[k] = perCurrent*state.rho[i]*state.Us[i];
            slot[k] = s;
        }
    }

    x_ = gather(x);
    n_ = gather(n);
    v_ = gather(v);
    t_ = gather(t);
    Zp_ = gather(Zp);
    Zs_ = gather(Zs);
    a_ = gather(a);
    f_ = gather(f);
    slot_ = gather(Field<label>(slot));

    // The faces' free points: the lowest of them decides the entry
    {
        vectorField offsets;
        labelField counts;
        freePoints(lm, x, offsets, counts);
        pointOffsets_ = gather(offsets);
        const labelField allCounts(gather(counts));

        offsetStart_.setSize(allCounts.size() + 1);
        offsetStart_[0] = 0;
        forAll(allCounts, g)
        {
            offsetStart_[g + 1] = offsetStart_[g] + allCounts[g];
        }
    }

    // 2. Candidates, rebuilt only when the faces moved far enough
    updateSearch();

    // 3-5. Each face of this rank as side 1 of its pair
    const label offset = globalFaces_.localStart();
    vectorField force(x_.size(), Zero);
    vectorField moment(x_.size(), Zero);

    // Per face, the pairs pushing on it weighted by their areas: the
    // weight, the outward normal and the contact velocity v*_n n (the
    // constraint of the compatible update)
    scalarField weight(x_.size(), Zero);
    vectorField normalSum(x_.size(), Zero);
    vectorField velocitySum(x_.size(), Zero);

    labelList partners(matchChecked_ ? 0 : x_.size(), -1);

    label nActive = 0;
    scalar normalForce = 0;
    scalar area = 0;
    scalar penetration = 0;

    forAll(patches_, s)
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                lm.boundaryFieldRef()[patches_[s]]
            );
        boolList& contact = condition.contact();

        // The pair's friction (the same on both patches: setAllowed)
        const frictionLaw& law = condition.friction();
        const bool friction = !law.frictionless();
        vectorField& slip = condition.slip();
        scalar& frictionPower = condition.frictionPower();
        frictionPower = 0;

        forAll(contact, i)
        {
            const label k = start_[s] + i;
            const label gi = offset + k;
            const label gj = partner(k, gi);

            if (!matchChecked_)
            {
                partners[gi] = gj;
            }

            if (gj < 0)
            {
                contact[i] = false;
                if (friction)
                {
                    slip[i] = Zero;
                }
                continue;
            }

            vector nij(n_[gi] - n_[gj]);
            nij /= mag(nij);

            // Both tractions on the plane of normal n (side 2's own
            // normal is -n)
            const vector t1(t_[gi]);
            const vector t2(-t_[gj]);
            const vector dv(v_[gj] - v_[gi]);

            const scalar Zn1 = Zp_[gi];
            const scalar Zn2 = Zp_[gj];
            const scalar tN =
                (Zn2*(t1 & nij) + Zn1*(t2 & nij) + Zn1*Zn2*(dv & nij))
               /(Zn1 + Zn2);

            const scalar gap = (x_[gj] - x_[gi]) & nij;
            const bool compressive = tN < 0;

            // Each side within the rigid wall's tolerance of its size of
            // the contact plane: the pair's gap within the sum (with the
            // first side's alone, two equal bars released one stage early
            // did not touch again where a bar on a wall did: their gap of
            // 3.8e-8 m against 2e-8 m, a wall's 1.9e-8 m against 2e-8 m).
            // The gap of the lowest free point of either face, not of the
            // centres: on curved bodies the centres of the faces that
            // meet lag the surfaces (two balls touched 2.7 us late)
            contact[i] =
                compressive
             && (
                    contact[i]
                 || pointGap(gi, gj, nij)
                 <= contactTouchingTolerance
                   *(Foam::sqrt(a_[gi]) + Foam::sqrt(a_[gj]))
                );

            if (!contact[i])
            {
                if (friction)
                {
                    // Side 1's sliding relative to side 2 as it arrives: a
                    // face that lands sliding starts with the kinetic limit
                    slip[i] = ((dv & nij)*nij) - dv;
                }
                continue;
            }

            const scalar share = 0.5*a_[gi];
            vector f(tN*nij);

            if (friction)
            {
                // The sticking traction (S-wave impedances), which makes
                // the two sides' tangential velocities equal, and the
                // law's return to its cone; each side's tangential
                // velocity then follows its own characteristic,
                //     v*_1 = v_1 + (t - t_1)/Z_1,  v*_2 = v_2 - (t - t_2)/Z_2,
                // so side 1 slides relative to side 2 at
                //     (t - stick)(1/Z_1 + 1/Z_2),
                // against t: the pair's friction power t . slip <= 0
                const scalar Zt1 = Zs_[gi];
                const scalar Zt2 = Zs_[gj];
                const tensor tangential(tensor::I - sqr(nij));
                const vector stick
                (
                    tangential
                  & ((Zt2*t1 + Zt1*t2 + Zt1*Zt2*dv)/(Zt1 + Zt2))
                );
                const vector tT(law.tangentialTraction(stick, -tN, slip[i]));

                slip[i] = (tT - stick)*(1/Zt1 + 1/Zt2);
                const scalar pairPower = (tT & slip[i])*share;
                frictionPower += pairPower;
                pairFrictionPower_ = max(pairFrictionPower_, pairPower);
                pairFrictionRatio_ =
                    max(pairFrictionRatio_, mag(tT)/max(-tN, VSMALL));
                f += tT;
            }
            f *= share;

            force[gi] += f;
            force[gj] -= f;

            // Both sides' torques at the pair's contact point
            const vector m(0.5*(x_[gi] + x_[gj]) ^ f);
            moment[gi] += m;
            moment[gj] -= m;

            // The constraint's normal velocity: the impedance-weighted
            // mean of the two sides', without the Riemann velocity's
            // traction jump (t2 - t1).n/(Z1 + Z2).  Under the constraint
            // the central traction is its reaction, so the jump is already
            // carried (and balanced) by the two sides' reactions; counted
            // once more here it moved the points faster than both sides'
            // cells, the faces' damping towards v*_n then pushed both
            // balls the same way (+126 N and +122 N along y at 20 us,
            // n = 8) and the balancing of the forces gave that back as
            // energy (+0.44 E0 over the contact).  The mean lies between
            // the sides and the two dampings are equal and opposite
            //
            // Less the two sides' shares of the nodal forces at the faces'
            // points per area, f_1/a_1 + f_2/a_2, along n over (Z1 + Z2)
            // (the compatible update's; zero with the others; per area,
            // so that faces that do not match, of different areas, cancel
            // under a uniform stress: with (f_1 + f_2)/a bars of 2 x 2
            // and 3 x 3 faces were 1.65 % off the contact stress, per area
            // 0.43 %): the constraint takes each side's
            // nodal force there out as its reaction, and with this
            // velocity the faces' dampings towards it take the two
            // reactions' sum back, so that the two sides' forces are equal
            // and opposite pair by pair (the balancing is left the shares
            // that do not meet, at the contact's edge); in the work of the
            // points' prescribed motion it adds -(f_1 + f_2)^2/((Z1 + Z2)
            // a) for matching faces, a dissipation, as the point upwinding
            // of a free point.
            // Without it the balancing took the reactions' sum back from
            // the cells, a work of either sign, and two balls gained
            // energy (validation/sphereImpact/FINDINGS.md 7)
            const scalar vN =
                (
                    Zn1*(v_[gi] & nij) + Zn2*(v_[gj] & nij)
                  - ((f_[gi]/a_[gi] + f_[gj]/a_[gj]) & nij)
                )/(Zn1 + Zn2);
            weight[gi] += share;
            weight[gj] += share;
            normalSum[gi] += share*nij;
            normalSum[gj] -= share*nij;
            velocitySum[gi] += (share*vN)*nij;
            velocitySum[gj] += (share*vN)*nij;

            ++nActive;
            normalForce -= tN*share;
            area += share;
            penetration = max(penetration, -gap);
            mostTensile_ = max(mostTensile_, tN);
        }
    }

    if (!matchChecked_)
    {
        checkMatching(partners);
    }

    if (Pstream::parRun())
    {
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
    }

    // The conditions' tractions per reference area
    forAll(patches_, s)
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                lm.boundaryFieldRef()[patches_[s]]
            );
        vectorField& traction = condition.traction();
        vectorField& faceMoment = condition.moment();
        boolList& touching = condition.touching();
        vectorField& normal = condition.normal();
        vectorField& velocity = condition.contactVelocity();
        const scalarField& magSf = condition.patch().magSf();

        forAll(traction, i)
        {
            const label g = offset + start_[s] + i;
            traction[i] = force[g]/magSf[i];
            faceMoment[i] = moment[g];
            touching[i] = weight[g] > 0;
            if (touching[i])
            {
                normal[i] = normalSum[g]/mag(normalSum[g]);
                velocity[i] = velocitySum[g]/weight[g];

                if (friction_)
                {
                    const scalar tn = traction[i] & normal[i];
                    const scalar tt = mag(traction[i] - tn*normal[i]);
                    if (tt > 0)
                    {
                        frictionRatio_ =
                            max(frictionRatio_, tt/max(mag(tn), VSMALL));
                    }
                }
            }
        }
    }

    // The report, at the step's first stage
    if (stage == 1)
    {
        writeReport(lm, time, nActive, normalForce, area, penetration);
    }
}


// ************************************************************************* //
