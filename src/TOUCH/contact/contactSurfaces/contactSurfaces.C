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
    pending_{false, 0, 0, 0, 0, 0},
    lm_(nullptr),
    stiffNodesWarned_(false),
    friction_(false),
    frictionRatio_(0),
    pairFrictionRatio_(0),
    pairFrictionPower_(-GREAT)
{
    setAllowed(lm);

    nodes_.setSize(patches_.size());
    forAll(patches_, s)
    {
        nodes_[s] =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[s]]
            ).nodes();
    }

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
    vectorField vCell(nLocal);
    vectorField t(nLocal);
    scalarField Zp(nLocal);
    scalarField Zs(nLocal);
    scalarField a(nLocal);
    vectorField f(nLocal);
    labelList slot(nLocal);

    held_.setSize(patches_.size());
    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        const solidFluxFvPatchVectorField::interiorState& state = states[s];
        const labelUList& faceCells = patch.faceCells();
        const vectorField& Sf = patch.Sf();
        const scalarField& magSf = patch.magSf();
        const bodyContactFvPatchVectorField& condition =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[s]]
            );
        const vectorField& nodalForce = condition.nodalForce();
        held_[s] = condition.pointConstrained();

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
            vCell[k] = lm.primitiveField()[faceCells[i]]/state.rho[i];
            t[k] = perCurrent*state.t[i];
            Zp[k] = perCurrent*state.rho[i]*state.Up[i];
            Zs[k] = perCurrent*state.rho[i]*state.Us[i];
            slot[k] = s;
        }
    }

    x_ = gather(x);
    n_ = gather(n);
    v_ = gather(v);
    if (anyNodes())
    {
        vCell_ = gather(vCell);
    }
    t_ = gather(t);
    Zp_ = gather(Zp);
    Zs_ = gather(Zs);
    a_ = gather(a);
    f_ = gather(f);
    slot_ = gather(Field<label>(slot));

    // The faces' points (their overlaps; the lowest free one decides the
    // entry) and whether each face was in contact
    {
        vectorField offsets;
        boolList free;
        labelField counts;
        facePoints(lm, x, offsets, free, counts);
        pointOffsets_ = gather(offsets);
        const labelField allCounts(gather(counts));

        labelField freeFlags(free.size());
        forAll(free, o)
        {
            freeFlags[o] = free[o];
        }
        const labelField allFree(gather(freeFlags));
        pointFree_.setSize(allFree.size());
        forAll(allFree, o)
        {
            pointFree_[o] = allFree[o];
        }

        pointStart_.setSize(allCounts.size() + 1);
        pointStart_[0] = 0;
        forAll(allCounts, g)
        {
            pointStart_[g + 1] = pointStart_[g] + allCounts[g];
        }

        labelField inContact(nLocal, 0);
        forAll(patches_, s)
        {
            const boolList& contact =
                refCast<const bodyContactFvPatchVectorField>
                (
                    lm.boundaryField()[patches_[s]]
                ).contact();
            forAll(contact, i)
            {
                inContact[start_[s] + i] = contact[i];
            }
        }
        const labelField allInContact(gather(inContact));
        wasInContact_.setSize(allInContact.size());
        forAll(allInContact, g)
        {
            wasInContact_[g] = allInContact[g];
        }
    }

    // 2. Candidates, rebuilt only when the faces moved far enough
    updateSearch();

    // 3-5. Every pair of faces that overlap, once, summed per face over
    // the ranks
    faceSums sums(x_.size());
    exchange(lm, sums);
    sums.combine();

    const label offset = globalFaces_.localStart();
    label nActive = 0;

    faceActive_.setSize(sums.active.size());
    forAll(sums.active, g)
    {
        faceActive_[g] = sums.active[g];
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
        boolList& contact = condition.contact();
        vectorField& slip = condition.slip();
        boolList& touching = condition.touching();
        vectorField& normal = condition.normal();
        vectorField& velocity = condition.contactVelocity();
        const scalarField& magSf = condition.patch().magSf();

        forAll(traction, i)
        {
            const label g = offset + start_[s] + i;
            traction[i] = sums.force[g]/magSf[i];
            faceMoment[i] = sums.moment[g];
            contact[i] = sums.active[g];
            nActive += contact[i];
            if (friction_ && !condition.friction().frictionless())
            {
                // The area-weighted sliding of the face's pairs (in contact
                // or arriving) decides its pairs' law in the next stage
                slip[i] =
                    sums.slipWeight[g] > 0
                  ? vector(sums.slipSum[g]/sums.slipWeight[g])
                  : vector::zero;
            }
            touching[i] = sums.weight[g] > 0;
            if (touching[i])
            {
                normal[i] = sums.normalSum[g]/mag(sums.normalSum[g]);
                velocity[i] = sums.velocitySum[g]/sums.weight[g];

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
        bool nodesHeld = false;
        forAll(patches_, s)
        {
            nodesHeld = nodesHeld || (nodes_[s] && held_[s]);
        }

        if (nodesHeld)
        {
            pending_ =
            {
                true, time, nActive, sums.normalForce, sums.area,
                sums.penetration
            };
            lm_ = &lm;
        }
        else
        {
            writeReport
            (
                lm, time, nActive, sums.normalForce, sums.area,
                sums.penetration
            );
        }
    }
}


void Foam::contactSurfaces::completeReport
(
    const scalar nodeNormalForce,
    const scalar nodeMostTensile
)
{
    if (!pending_.pending)
    {
        return;
    }
    pending_.pending = false;
    mostTensile_ = max(mostTensile_, nodeMostTensile);
    writeReport
    (
        *lm_, pending_.time, pending_.nActive,
        pending_.normalForce + nodeNormalForce, pending_.area,
        pending_.penetration
    );
}


void Foam::contactSurfaces::setMaterialImpedances(const mechanicalLaw& law)
{
    scalarField Zs(start_.last(), Zero);
    forAll(patches_, s)
    {
        const labelUList& faceCells =
            mesh_.boundary()[patches_[s]].faceCells();
        forAll(faceCells, i)
        {
            Zs[start_[s] + i] = law.rho(faceCells[i])*law.Us(faceCells[i]);
        }
    }
    materialZs_ = gather(Zs);
}


// * * * * * * * * * * * * * Explicit Instantiations * * * * * * * * * * * //

//- The gather of side nodes' slots (contactSurfacesNodes.C)
template Foam::tmp<Foam::Field<Foam::vector>>
Foam::contactSurfaces::gather(const Field<vector>&) const;


// ************************************************************************* //
