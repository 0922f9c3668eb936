/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "kinematicPointConstraints.H"
#include "syncTools.H"
#include "emptyPolyPatch.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- Whether two declarations are the same to the last bit (OpenFOAM's
//  operator== on a VectorSpace allows a difference of VSMALL)
template<class Type>
static bool sameBits(const Type& a, const Type& b)
{
    for (direction d = 0; d < pTraits<Type>::nComponents; ++d)
    {
        if (component(a, d) != component(b, d))
        {
            return false;
        }
    }
    return true;
}

} // End namespace Foam


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::tensor Foam::kinematicPointConstraints::freeProjector(const tensor& M)
{
    const scalar scale = max(max(mag(M.x()), mag(M.y())), mag(M.z()));

    if (scale < VSMALL)
    {
        return tensor::I;
    }

    tensor fixed(Zero);

    for (direction d = 0; d < vector::nComponents; ++d)
    {
        // Column d of M (M is symmetric: its row d)
        vector c(M.x()[d], M.y()[d], M.z()[d]);
        c -= (fixed & c);

        const scalar magC = mag(c);
        if (magC > 1e-6*scale)
        {
            const vector q(c/magC);
            fixed += q*q;
        }
    }

    return tensor::I - fixed;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::kinematicPointConstraints::formProjectors()
{
    fixedSum_ = Zero;
    velocitySum_ = Zero;

    // Per point, the sum of its faces' fixed parts of their velocities,
    // sum_f (I - Pi_f) v_f: where faces of different normals or
    // velocities meet, the velocity that meets all of them (below)
    vectorField fixedVelocitySum(boundaryPoints_.size(), Zero);

    // The same of the faces of smooth surfaces (a contact between
    // bodies), apart, and their largest velocity: combined per point once
    // complete (combineSurfaces)
    tensorField surfaceSum;
    vectorField surfaceVelocitySum;
    vectorField surfaceLargest;
    const bool anySurface =
        returnReduce(surface_.found(true), orOp<bool>());
    if (anySurface)
    {
        surfaceSum.setSize(boundaryPoints_.size(), Zero);
        surfaceVelocitySum.setSize(boundaryPoints_.size(), Zero);
        surfaceLargest.setSize(boundaryPoints_.size(), Zero);
    }

    const faceList& faces = mesh_.faces();

    forAll(declaredFree_, patchi)
    {
        if (!declaredFree_.set(patchi))
        {
            continue;
        }

        const fvPatch& patch = mesh_.boundary()[patchi];
        const label start = patch.start();
        const tensorField& free = declaredFree_[patchi];
        const vectorField& velocity = declaredVelocity_[patchi];
        const boolList* held =
            declaredHeld_.set(patchi) ? &declaredHeld_[patchi] : nullptr;
        const faceList& localFaces = patch.patch().localFaces();

        // A smooth surface's faces go to its own sums
        const bool surface = surface_[patchi];
        tensorField& sum = surface ? surfaceSum : fixedSum_;
        vectorField& sumVelocity =
            surface ? surfaceVelocitySum : fixedVelocitySum;
        vectorField& largest = surface ? surfaceLargest : velocitySum_;

        forAll(free, i)
        {
            const tensor fixed(tensor::I - free[i]);
            const face& f = faces[start + i];

            forAll(f, k)
            {
                // Not at the points the patch does not hold
                if (held && !(*held)[localFaces[i][k]])
                {
                    continue;
                }

                const label pointi = f[k];
                const label b = boundaryIndex_[pointi];
                sum[b] += fixed;
                sumVelocity[b] += fixed & velocity[i];
                prescribeEqOp()(largest[b], velocity[i]);
            }
        }
    }

    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, fixedSum_, plusEqOp<tensor>(), tensor::zero
    );
    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, velocitySum_, prescribeEqOp(), vector::zero
    );
    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, fixedVelocitySum, plusEqOp<vector>(),
        vector::zero
    );

    if (anySurface)
    {
        combineSurfaces
        (
            surfaceSum, surfaceVelocitySum, surfaceLargest, fixedVelocitySum
        );
    }

    // The largest velocity serves where it meets every face's fixed
    // directions (a wall, a plane, contact faces of one normal and
    // velocity).  Where it does not (a contact face meeting a symmetric
    // plane, contact faces of different normals or contact velocities),
    // the fixed part is the least-squares solution of (I - Pi_f) b =
    // (I - Pi_f) v_f over the faces f, sum_f (I - Pi_f) b = sum_f (I -
    // Pi_f) v_f on the fixed span, and the free part the largest's.  The
    // largest alone moved a point of a contact face at a symmetric plane
    // off the plane, along the face's tilted normal, and the plane's
    // reaction did work there, the same on both bodies (two balls, n = 8:
    // 1.2e-2 E0 over the contact)
    forAll(boundaryPoints_, b)
    {
        const vector& rhs = fixedVelocitySum[b];
        const vector misfit((fixedSum_[b] & velocitySum_[b]) - rhs);
        if (magSqr(misfit) > 1e-24*max(magSqr(rhs), VSMALL))
        {
            const tensor free(freeProjector(fixedSum_[b]));
            velocitySum_[b] =
                (inv(fixedSum_[b] + free) & rhs)
              + (free & velocitySum_[b]);
        }
    }

    for (label a = 0; a < nActive_; ++a)
    {
        activeIndex_[activePoints_[a]] = -1;
    }
    nActive_ = 0;

    // A point no face constrains keeps v: Pi = I exactly and b = 0, which
    // constrain() would only multiply by
    forAll(boundaryPoints_, b)
    {
        const tensor free(freeProjector(fixedSum_[b]));

        if
        (
            !sameBits(free, tensor::I)
         || !sameBits(velocitySum_[b], vector::zero)
        )
        {
            const label pointi = boundaryPoints_[b];
            activeIndex_[pointi] = nActive_;
            activePoints_[nActive_] = pointi;
            free_[nActive_] = free;
            prescribed_[nActive_] = velocitySum_[b];
            ++nActive_;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::kinematicPointConstraints::kinematicPointConstraints(const fvMesh& mesh)
:
    mesh_(mesh),
    boundaryIndex_(mesh.nPoints(), -1),
    declaredFree_(mesh.boundary().size()),
    declaredVelocity_(mesh.boundary().size()),
    declaredHeld_(mesh.boundary().size()),
    declaredNow_(mesh.boundary().size(), false),
    permanent_(mesh.boundary().size(), false),
    surface_(mesh.boundary().size(), false),
    changed_(false),
    nActive_(0),
    activeIndex_(mesh.nPoints(), -1)
{
    // A point of this rank on another rank's boundary face is constrained
    // too: mark the boundary points, then combine the marks
    labelList onBoundary(mesh.nPoints(), 0);

    for (const fvPatch& patch : mesh.boundary())
    {
        if (!patch.coupled())
        {
            for (const face& f : patch.patch())
            {
                for (const label pointi : f)
                {
                    onBoundary[pointi] = 1;
                }
            }
        }
    }

    syncTools::syncPointList(mesh, onBoundary, maxEqOp<label>(), label(0));

    boundaryPoints_ = findIndices(onBoundary, 1);

    forAll(boundaryPoints_, b)
    {
        boundaryIndex_[boundaryPoints_[b]] = b;
    }

    fixedSum_.setSize(boundaryPoints_.size());
    velocitySum_.setSize(boundaryPoints_.size());
    activePoints_.setSize(boundaryPoints_.size());
    free_.setSize(boundaryPoints_.size());
    prescribed_.setSize(boundaryPoints_.size());

    // The empty patches' faces, as a symmetric plane declares its own, with
    // the coordinate axis of the face's normal (touchSolid refuses empty
    // planes that are not normal to one): blockMesh leaves the points of a
    // plane off it by round-off (z = 0.10000000000000002 of 0.1), and the
    // faces' own normals then let the points move across by 1e-16 of
    // their in-plane velocity
    const vectorField& Sf = mesh.faceAreas();
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& patch = mesh.boundaryMesh()[patchi];
        if (isA<emptyPolyPatch>(patch))
        {
            const vectorField::subField S(patch.patchSlice(Sf));
            tensorField free(S.size());
            forAll(S, i)
            {
                const vector magS(cmptMag(S[i]));
                const direction d =
                    magS.x() >= max(magS.y(), magS.z())
                  ? 0
                  : (magS.y() >= magS.z() ? 1 : 2);
                vector axis(Zero);
                axis[d] = 1;
                free[i] = tensor::I - sqr(axis);
            }
            declaredFree_.set(patchi, new tensorField(std::move(free)));
            declaredVelocity_.set(patchi, new vectorField(S.size(), Zero));
            permanent_[patchi] = true;
            changed_ = true;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::kinematicPointConstraints::reset()
{
    declaredNow_ = false;
}


void Foam::kinematicPointConstraints::add
(
    const fvPatch& patch,
    const tensorField& free,
    const vectorField& velocity,
    const bool surface,
    const boolList* held
)
{
    const label patchi = patch.index();
    declaredNow_[patchi] = true;
    if (surface != surface_[patchi])
    {
        surface_[patchi] = surface;
        changed_ = true;
    }

    if (!held)
    {
        if (declaredHeld_.set(patchi))
        {
            declaredHeld_.set(patchi, nullptr);
            changed_ = true;
        }
    }
    else if (!declaredHeld_.set(patchi) || declaredHeld_[patchi] != *held)
    {
        declaredHeld_.set(patchi, new boolList(*held));
        changed_ = true;
    }

    if (!declaredFree_.set(patchi))
    {
        declaredFree_.set(patchi, new tensorField(free));
        declaredVelocity_.set(patchi, new vectorField(velocity));
        changed_ = true;
        return;
    }

    tensorField& lastFree = declaredFree_[patchi];
    vectorField& lastVelocity = declaredVelocity_[patchi];

    forAll(free, i)
    {
        if
        (
            !sameBits(free[i], lastFree[i])
         || !sameBits(velocity[i], lastVelocity[i])
        )
        {
            lastFree[i] = free[i];
            lastVelocity[i] = velocity[i];
            changed_ = true;
        }
    }
}


void Foam::kinematicPointConstraints::finalise()
{
    forAll(declaredFree_, patchi)
    {
        if
        (
            declaredFree_.set(patchi)
         && !declaredNow_[patchi]
         && !permanent_[patchi]
        )
        {
            declaredFree_.set(patchi, nullptr);
            declaredVelocity_.set(patchi, nullptr);
            declaredHeld_.set(patchi, nullptr);
            changed_ = true;
        }
    }

    // The sums are completed across processors: every rank forms them
    // again if any rank's declarations changed
    if (Pstream::parRun())
    {
        reduce(changed_, orOp<bool>());
    }

    if (changed_)
    {
        formProjectors();
        changed_ = false;
    }
}


void Foam::kinematicPointConstraints::constrain(vectorField& pointV) const
{
    for (label a = 0; a < nActive_; ++a)
    {
        vector& v = pointV[activePoints_[a]];
        v = (free_[a] & v) + prescribed_[a];
    }
}


void Foam::kinematicPointConstraints::constrainTranspose
(
    vectorField& pointForce
) const
{
    for (label a = 0; a < nActive_; ++a)
    {
        vector& f = pointForce[activePoints_[a]];
        f = free_[a].T() & f;
    }
}


// ************************************************************************* //
