/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "kinematicPointConstraints.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- Combine the prescribed velocities of a point's faces: the larger
struct prescribeEqOp
{
    void operator()(vector& x, const vector& y) const
    {
        if (magSqr(y) > magSqr(x))
        {
            x = y;
        }
    }
};


//- The projector onto the complement of the range of a sum of fixed
//  projectors M: Gram-Schmidt on its columns, a column that adds less
//  than a relative 1e-6 to the span counting as in it
static tensor freeProjector(const tensor& M)
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

} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::kinematicPointConstraints::kinematicPointConstraints(const fvMesh& mesh)
:
    mesh_(mesh),
    boundaryIndex_(mesh.nPoints(), -1)
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

    free_.setSize(boundaryPoints_.size(), tensor::I);
    prescribed_.setSize(boundaryPoints_.size(), Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::kinematicPointConstraints::reset()
{
    free_ = Zero;
    prescribed_ = Zero;
}


void Foam::kinematicPointConstraints::add
(
    const fvPatch& patch,
    const tensorField& free,
    const vectorField& velocity
)
{
    const faceList& faces = mesh_.faces();

    forAll(free, i)
    {
        const tensor fixed(tensor::I - free[i]);

        for (const label pointi : faces[patch.start() + i])
        {
            const label b = boundaryIndex_[pointi];
            free_[b] += fixed;
            prescribeEqOp()(prescribed_[b], velocity[i]);
        }
    }
}


void Foam::kinematicPointConstraints::finalise()
{
    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, free_, plusEqOp<tensor>(), tensor::zero
    );
    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, prescribed_, prescribeEqOp(), vector::zero
    );

    forAll(free_, b)
    {
        free_[b] = freeProjector(free_[b]);
    }
}


void Foam::kinematicPointConstraints::constrain(vectorField& pointV) const
{
    forAll(boundaryPoints_, b)
    {
        vector& v = pointV[boundaryPoints_[b]];
        v = (free_[b] & v) + prescribed_[b];
    }
}


void Foam::kinematicPointConstraints::constrainTranspose
(
    vectorField& pointForce
) const
{
    forAll(boundaryPoints_, b)
    {
        vector& f = pointForce[boundaryPoints_[b]];
        f = free_[b].T() & f;
    }
}


// ************************************************************************* //
