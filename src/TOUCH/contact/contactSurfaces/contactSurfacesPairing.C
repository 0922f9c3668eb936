/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The pairing of contactSurfaces: which patches may touch, the candidate
    faces (an indexedOctree of the face centres, rebuilt only after a face
    moved h/2), the faces' points (their overlaps) and their free points
    that decide when a face enters contact.

\*---------------------------------------------------------------------------*/

#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "indexedOctree.H"
#include "treeDataPoint.H"
#include "syncTools.H"
#include "pointFields.H"

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


void Foam::contactSurfaces::facePoints
(
    const volVectorField& lm,
    const pointField& centres,
    vectorField& offsets,
    boolList& free,
    labelField& counts
) const
{
    // The points' displacement is the solver's pointD
    const pointField& X = mesh_.points();
    const vectorField& pointU =
        mesh_.lookupObject<pointVectorField>("pointD").primitiveField();
    const faceList& faces = mesh_.faces();

    // The points a face pushed on in the last stage, where the update holds
    // them (compatible), on any rank: they stay out, so that a face beside
    // the contact area does not touch through the points its neighbours
    // hold (as the rigid wall's lowestFreePoint; two balls pressed twice
    // the closed form's force otherwise).  Where nothing holds them (plain)
    // they count: such a point shared with a face not yet in contact sank
    // with it until that face's own points touched, 0.37 of a plate face
    // on the projectile (validation/projectileImpact/FINDINGS.md 9)
    boolList held(mesh_.nPoints(), false);
    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        const bodyContactFvPatchVectorField& condition =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[s]]
            );
        if (!condition.pointConstrained())
        {
            continue;
        }
        const boolList& touching = condition.touching();

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

    // Per face of this rank, its points' offsets from its centre and
    // whether they are free
    DynamicList<vector> all(4*centres.size());
    DynamicList<bool> isFree(4*centres.size());
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
                all.append(X[pointi] + pointU[pointi] - centres[k]);
                isFree.append(!held[pointi]);
                ++counts[k];
            }
        }
    }

    offsets.transfer(all);
    free.transfer(isFree);
}


bool Foam::contactSurfaces::over
(
    const point& x,
    const label g,
    const vector& n
) const
{
    // The polygon's orientation seen along n, then x on the inner side of
    // every edge (a convex face; its own edges and points count as over)
    const label first = pointStart_[g];
    const label nPoints = pointStart_[g + 1] - first;
    vector area(Zero);
    for (label k = 0; k < nPoints; ++k)
    {
        area +=
            pointOffsets_[first + k]
          ^ pointOffsets_[first + (k + 1) % nPoints];
    }
    const scalar orientation = sign(area & n);
    const vector r(x - x_[g]);
    const scalar tolerance = 1e-6*a_[g];
    for (label k = 0; k < nPoints; ++k)
    {
        const vector& a = pointOffsets_[first + k];
        const vector& b = pointOffsets_[first + (k + 1) % nPoints];
        if (orientation*(((b - a) ^ (r - a)) & n) < -tolerance)
        {
            return false;
        }
    }
    return true;
}


bool Foam::contactSurfaces::opposed
(
    const label gi,
    const label gj,
    const vector& n
) const
{
    // Where the update holds the points of faces in contact (compatible),
    // a pair acts only while one face's centre lies over the other: every
    // face has such a partner where its centre lies over the other
    // surface, and the held points carry the force of the rest.  A face
    // also overlaps by a sliver the neighbours of the face opposite it
    // (every overlap is a pair); such pairs held the points of two balls
    // to their tilted contact velocities, and the energy grew in 237 steps
    // of the release at n = 8 (1.1e-4 E0 in one), in 121 of the loading at
    // n = 12; with opposed pairs alone, in none (validation/sphereImpact/
    // FINDINGS.md 9).  Where nothing holds the points (plain) every
    // overlap acts: its traction is all the pair exchanges
    if (!(held_[slot_[gi]] || held_[slot_[gj]]))
    {
        return true;
    }
    return over(x_[gi], gj, n) || over(x_[gj], gi, n);
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
    // touch, were a face's height difference apart.  Where the update
    // holds the points of faces in contact (compatible), only the points
    // over the partner: with the pairs of every overlap, a face's point
    // beyond the edge of a partner that it overlaps by a sliver lay below
    // that partner's tilted plane, and two balls were held together by
    // faces outside their contact (+145 % of Hertz's force at n = 8,
    // validation/sphereImpact/FINDINGS.md 8).  Where nothing holds them
    // (plain) every free point counts: the projectile's points sank to
    // 0.21 of a plate face (0.05 so) when only those over the partner did
    const bool overOnly = held_[slot_[gi]] || held_[slot_[gj]];
    scalar gap = (x_[gj] - x_[gi]) & n;
    for (label o = pointStart_[gi]; o < pointStart_[gi + 1]; ++o)
    {
        const point x(x_[gi] + pointOffsets_[o]);
        if (pointFree_[o] && (!overOnly || over(x, gj, n)))
        {
            gap = min(gap, (x - x_[gj]) & n_[gj]);
        }
    }
    for (label o = pointStart_[gj]; o < pointStart_[gj + 1]; ++o)
    {
        const point x(x_[gj] + pointOffsets_[o]);
        if (pointFree_[o] && (!overOnly || over(x, gi, n)))
        {
            gap = min(gap, (x - x_[gi]) & n_[gi]);
        }
    }
    return gap;
}


// ************************************************************************* //
