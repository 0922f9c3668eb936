/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The pairing of contactSurfaces: which patches may touch, the candidate
    faces (an indexedOctree of the face centres, rebuilt only after a face
    moved h/2), the partner of a face, the check of matching faces, and
    the faces' free points that decide when a face enters contact.

\*---------------------------------------------------------------------------*/

#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "indexedOctree.H"
#include "treeDataPoint.H"
#include "syncTools.H"
#include "pointFields.H"

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace Foam
{
    //- Opposed faces: the cosine of the angle of their normals below this
    static const scalar contactOpposedCos = -0.5;

    //- Lexicographic order of positions (ties of the pairing)
    static bool before(const point& a, const point& b)
    {
        for (direction d = 0; d < point::nComponents; ++d)
        {
            if (a[d] != b[d])
            {
                return a[d] < b[d];
            }
        }
        return false;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactSurfaces::setAllowed(const volVectorField& lm)
{
    const label n = patches_.size();
    allowed_.setSize(n);

    forAll(patches_, a)
    {
        allowed_[a].setSize(n, false);
    }

    forAll(patches_, a)
    {
        const bodyContactFvPatchVectorField& pf =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[a]]
            );

        if (pf.patches().empty())
        {
            allowed_[a] = true;
            forAll(patches_, b)
            {
                allowed_[b][a] = true;
            }
            continue;
        }

        for (const word& name : pf.patches())
        {
            label b = -1;
            forAll(patches_, c)
            {
                if (mesh_.boundary()[patches_[c]].name() == name)
                {
                    b = c;
                }
            }

            if (b < 0)
            {
                wordList valid(patches_.size());
                forAll(patches_, c)
                {
                    valid[c] = mesh_.boundary()[patches_[c]].name();
                }

                FatalErrorInFunction
                    << "Entry 'patches' of patch " << pf.patch().name()
                    << " in " << lm.name() << " names '" << name
                    << "', which is not a bodyContact patch" << nl
                    << "Valid: " << valid << nl
                    << exit(FatalError);
            }

            allowed_[a][b] = true;
            allowed_[b][a] = true;
        }
    }

    // A pair's friction is the pair's: the two patches must give the same
    // (each face acts as the first side of its pair with its own patch's
    // law, so different laws would make the exchange depend on the side)
    forAll(patches_, a)
    {
        const bodyContactFvPatchVectorField& pa =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[a]]
            );

        forAll(patches_, b)
        {
            const bodyContactFvPatchVectorField& pb =
                refCast<const bodyContactFvPatchVectorField>
                (
                    lm.boundaryField()[patches_[b]]
                );

            if
            (
                b > a && allowed_[a][b]
             && pa.friction().dict() != pb.friction().dict()
            )
            {
                FatalErrorInFunction
                    << "Patches " << pa.patch().name() << " and "
                    << pb.patch().name() << " in 0/U (or 0/" << lm.name()
                    << ") may touch but give different 'friction': "
                    << pa.friction().dict() << " and "
                    << pb.friction().dict() << nl
                    << "Valid: the same friction sub-dictionary on both"
                    << " (or on neither: frictionless)" << nl
                    << exit(FatalError);
            }
        }
    }
}


void Foam::contactSurfaces::updateSearch()
{
    // Every rank holds every position: they take the same decision
    bool rebuild = searchPositions_.size() != x_.size();
    if (!rebuild)
    {
        const scalar limit = sqr(0.5*searchSize_);
        forAll(x_, i)
        {
            if (magSqr(x_[i] - searchPositions_[i]) > limit)
            {
                rebuild = true;
                break;
            }
        }
    }

    if (!rebuild || x_.empty())
    {
        return;
    }

    searchPositions_ = x_;
    searchSize_ = Foam::sqrt(max(a_));

    treeBoundBox bb(searchPositions_);
    bb.inflate(1e-4);
    bb.min() -= point::uniform(searchSize_);
    bb.max() += point::uniform(searchSize_);

    const indexedOctree<treeDataPoint> tree
    (
        treeDataPoint(searchPositions_), bb, 8, 10, 3.0
    );

    const label offset = globalFaces_.localStart();
    const scalar radiusSqr = sqr(3*searchSize_);

    candidates_.setSize(globalFaces_.localSize());
    forAll(candidates_, i)
    {
        candidates_[i] = tree.findSphere(x_[offset + i], radiusSqr);
        Foam::sort(candidates_[i]);
    }
}


Foam::label Foam::contactSurfaces::partner
(
    const label i,
    const label gi
) const
{
    const point& xi = x_[gi];
    const vector& ni = n_[gi];
    const scalar reachSqr = sqr(2*searchSize_);
    const scalar behind = -0.5*Foam::sqrt(a_[gi]);

    label best = -1;
    scalar bestLateral = GREAT;

    for (const label gj : candidates_[i])
    {
        if (gj == gi || !allowed_[slot_[gi]][slot_[gj]])
        {
            continue;
        }

        const vector d(x_[gj] - xi);
        if ((ni & n_[gj]) > contactOpposedCos || magSqr(d) > reachSqr)
        {
            continue;
        }

        // Not a face of the far side of the body (self-contact of a thin
        // part): a partner lies at most half a face behind
        if ((d & ni) < behind)
        {
            continue;
        }

        // The nearest to the normal line; ties to the smaller global
        // index's position order, not to the order of the ranks
        const scalar lateral = mag(d - (d & ni)*ni);
        if
        (
            lateral < bestLateral - SMALL*searchSize_
         || (
                best >= 0
             && lateral <= bestLateral + SMALL*searchSize_
             && before(x_[gj], x_[best])
            )
        )
        {
            best = gj;
            bestLateral = min(lateral, bestLateral);
        }
    }

    // Its centre projects within about the partner face
    if (best >= 0 && bestLateral > 0.75*Foam::sqrt(a_[best]))
    {
        return -1;
    }

    return best;
}


void Foam::contactSurfaces::checkMatching(const labelList& partners)
{
    labelList all(partners);
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(all, maxEqOp<label>());
        Pstream::listCombineScatter(all);
    }

    label nPaired = 0;
    label nOneWay = 0;
    forAll(all, g)
    {
        if (all[g] >= 0)
        {
            ++nPaired;
            nOneWay += all[all[g]] != g;
        }
    }

    if (nPaired == 0)
    {
        return;
    }
    matchChecked_ = true;

    if (nOneWay)
    {
        WarningInFunction
            << nOneWay << " of " << nPaired << " contact faces with a"
            << " partner are not their partner's partner: the faces that"
            << " meet do not match.  Their forces are exchanged exactly but"
            << " lumped by half areas, not by overlap areas (with FUpdate"
            << " plain such a contact can be unstable)" << endl;
    }
}


void Foam::contactSurfaces::freePoints
(
    const volVectorField& lm,
    const pointField& centres,
    vectorField& offsets,
    labelField& counts
) const
{
    // The points' displacement is the solver's pointD
    const pointField& X = mesh_.points();
    const vectorField& pointU =
        mesh_.lookupObject<pointVectorField>("pointD").primitiveField();
    const faceList& faces = mesh_.faces();

    // The points a face pushed on in the last stage holds, on any rank:
    // they stay out, so that a face beside the contact area does not touch
    // through the points its neighbours hold (as the rigid wall's
    // lowestFreePoint)
    boolList held(mesh_.nPoints(), false);
    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        const boolList& touching =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[s]]
            ).touching();

        forAll(touching, i)
        {
            if (touching[i])
            {
                for (const label pointi : faces[patch.start() + i])
                {
                    held[pointi] = true;
                }
            }
        }
    }
    syncTools::syncPointList(mesh_, held, orEqOp<bool>(), false);

    // Per face of this rank, its free points' offsets from its centre
    DynamicList<vector> free(4*centres.size());
    counts.setSize(centres.size());
    counts = 0;
    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        forAll(patch, i)
        {
            const label k = start_[s] + i;
            for (const label pointi : faces[patch.start() + i])
            {
                if (!held[pointi])
                {
                    free.append(X[pointi] + pointU[pointi] - centres[k]);
                    ++counts[k];
                }
            }
        }
    }

    offsets.transfer(free);
}


Foam::scalar Foam::contactSurfaces::pointGap
(
    const label gi,
    const label gj,
    const vector& n
) const
{
    // Side 1's free points against side 2's face plane (its centre and
    // own normal), side 2's against side 1's: the lowest of them, or the
    // centres' gap along n if lower.  Against the plane through the
    // partner's centre normal to n instead, the poles of two balls, which
    // touch, were a face's height difference apart
    scalar gap = (x_[gj] - x_[gi]) & n;
    for (label o = offsetStart_[gi]; o < offsetStart_[gi + 1]; ++o)
    {
        gap = min(gap, (x_[gi] + pointOffsets_[o] - x_[gj]) & n_[gj]);
    }
    for (label o = offsetStart_[gj]; o < offsetStart_[gj + 1]; ++o)
    {
        gap = min(gap, (x_[gj] + pointOffsets_[o] - x_[gi]) & n_[gi]);
    }
    return gap;
}


// ************************************************************************* //
