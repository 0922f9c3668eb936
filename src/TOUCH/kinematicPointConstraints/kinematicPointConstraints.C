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
    free_(mesh.nPoints(), tensor::I),
    prescribed_(mesh.nPoints(), Zero)
{}


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
            free_[pointi] += fixed;
            prescribeEqOp()(prescribed_[pointi], velocity[i]);
        }
    }
}


void Foam::kinematicPointConstraints::finalise()
{
    syncTools::syncPointList(mesh_, free_, plusEqOp<tensor>(), tensor::zero);
    syncTools::syncPointList
    (
        mesh_, prescribed_, prescribeEqOp(), vector::zero
    );

    forAll(free_, pointi)
    {
        free_[pointi] = freeProjector(free_[pointi]);
    }
}


void Foam::kinematicPointConstraints::constrain(vectorField& pointV) const
{
    forAll(pointV, pointi)
    {
        pointV[pointi] = (free_[pointi] & pointV[pointi]) + prescribed_[pointi];
    }
}


void Foam::kinematicPointConstraints::constrainTranspose
(
    vectorField& pointForce
) const
{
    forAll(pointForce, pointi)
    {
        pointForce[pointi] = free_[pointi].T() & pointForce[pointi];
    }
}


// ************************************************************************* //
