/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The constraints of the facets of a smooth surface (a contact between
    bodies) at their points: held along the surface's normal alone.
    Summed with the others, the facets of a curved contact, whose normals
    part by O(h/R), held its points in all three directions, the
    tangential velocities the least-squares answer to the facets'
    contact velocities (their differences over O(h/R)), and the fixed
    tangential nodal forces were taken out of the momentum rate as
    reactions: two balls gained energy on fine meshes, up to 3.2e-2 E0
    in a step (validation/sphereImpact/FINDINGS.md 7).

\*---------------------------------------------------------------------------*/

#include "kinematicPointConstraints.H"
#include "syncTools.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::tensor Foam::kinematicPointConstraints::surfaceFixed
(
    const tensor& M,
    vector& e
)
{
    e = Zero;

    const scalar trace = tr(M);
    if (trace < VSMALL)
    {
        return M;
    }

    // The principal direction by power iteration from M's largest
    // column: the other eigenvalues are below 0.18 of the largest where
    // the result is used, so 40 iterations converge to round-off
    vector d(M.x());
    if (magSqr(M.y()) > magSqr(d))
    {
        d = M.y();
    }
    if (magSqr(M.z()) > magSqr(d))
    {
        d = M.z();
    }
    d /= mag(d);
    for (label iter = 0; iter < 40; ++iter)
    {
        const vector Md(M & d);
        const scalar magMd = mag(Md);
        if (magMd < VSMALL)
        {
            return M;
        }
        d = Md/magMd;
    }

    // tan^2(22.5 deg) = (1 - cos 45 deg)/(1 + cos 45 deg): two facets'
    // normals at 45 deg, the smallest angle taken as an edge
    const scalar lambda = d & M & d;
    const scalar c = Foam::sqrt(0.5);
    if (trace - lambda >= (1 - c)/(1 + c)*lambda)
    {
        return M;
    }

    e = d;
    return lambda*sqr(d);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::kinematicPointConstraints::combineSurfaces
(
    tensorField& surfaceSum,
    vectorField& surfaceVelocitySum,
    vectorField& surfaceLargest,
    vectorField& fixedVelocitySum
)
{
    // The smooth surfaces' part: held along their normal alone, at the
    // least-squares velocity along it (the facets' contact velocities
    // weighted by (n_f . e)^2), with no velocity in the free directions
    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, surfaceSum, plusEqOp<tensor>(),
        tensor::zero
    );
    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, surfaceVelocitySum, plusEqOp<vector>(),
        vector::zero
    );
    syncTools::syncPointList
    (
        mesh_, boundaryPoints_, surfaceLargest, prescribeEqOp(),
        vector::zero
    );

    forAll(boundaryPoints_, b)
    {
        vector e;
        const tensor fixed(surfaceFixed(surfaceSum[b], e));
        if (magSqr(e) > 0)
        {
            const scalar lambda = e & fixed & e;
            const vector rhs(e*(e & surfaceVelocitySum[b]));
            fixedSum_[b] += fixed;
            fixedVelocitySum[b] += rhs;
            prescribeEqOp()(velocitySum_[b], rhs/lambda);
        }
        else
        {
            fixedSum_[b] += fixed;
            fixedVelocitySum[b] += surfaceVelocitySum[b];
            prescribeEqOp()(velocitySum_[b], surfaceLargest[b]);
        }
    }
}


// ************************************************************************* //
