/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's point upwinding: the points' areas and
    mobilities, the upwinding of the nodal forces and the turn of the
    points' drift with the body's spin (compatible.H).

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::addPointUpwinding
(
    vectorField& pointV
)
{
    syncTools::syncPointList
    (
        faces_.mesh(), reconstructedForce_, plusEqOp<vector>(), vector::zero
    );

    // w_a = -kappa_a phi_a Pi_a f_a: its stress power -kappa phi |Pi f|^2
    // can only take energy out, and phi, the share of the nodal force that
    // the reconstructed traction jumps keep, is O(h) where the stress is
    // smooth
    vectorField& freeForce = reconstructedForce_;
    constraints_.constrainTranspose(freeForce);

    forAll(pointV, pointi)
    {
        vector f(pointForce_[pointi]);
        constraints_.constrainOne(pointi, f);

        const scalar magSqrF = magSqr(f);
        if (magSqrF > VSMALL)
        {
            const scalar phi =
                min(max((freeForce[pointi] & f)/magSqrF, scalar(0)), scalar(1));

            pointV[pointi] -= (pointMobility_[pointi]*phi)*f;
        }
    }
}


void Foam::deformationUpdates::compatible::addDriftRotation
(
    vectorField& pointV
)
{
    // The drift d_a = u_a - (A u)_a of the points from the extrapolated cell
    // motion is the point upwinding's sum over the run. The map A moves
    // the points with the cells, so it turns the points of a rigid rotation
    // omega about x_a - d_a, not about x_a: the drift stayed fixed in space
    // while the body turned, lagged behind the nodal forces it came from,
    // and their torque sum_a d_a ^ f_a took angular momentum out (a free
    // spinning cube, 6^3: 60 times the upwind torque after 220 steps, and
    // restoring it gave the body energy it never had, 1e-4 E0 a step).
    // Turning the drift with the body's spin removes that torque.
    pointDrift_.setSize(pointV.size());
    pointInterpolation_.interpolate(faces_.u(), 1, pointDrift_);

    const vector omega(rigidSpin_/law_.rho());
    const vectorField& pointU = *pointDisplacement_;

    forAll(pointV, pointi)
    {
        pointV[pointi] += omega ^ (pointU[pointi] - pointDrift_[pointi]);
    }

    constraints_.constrain(pointV);
}


Foam::scalarField Foam::deformationUpdates::compatible::calcPointMobility
(
    const fvMesh& mesh,
    const linearReconstruction& reconstruction,
    const scalar coefficient,
    const scalar impedance
)
{
    if (!(coefficient > 0))
    {
        return scalarField();
    }

    // The area of a point, a third of the sum of its faces' shares (a
    // processor face counts half on each side, and so does a mirror's,
    // whose other side is the reflection: the whole body's point has
    // twice the area and twice the nodal force; an empty patch's faces
    // count as a symmetric plane's, so that a 2D case is its one-cell
    // slab between symmetric planes): a plane wave's traction
    // jump [[t]] on a hexahedral mesh gives f_a = [[t]] S_a, so that
    // w = f/(2 rho Up S_a) is the Riemann contact velocity [[t]]/(2 rho Up)
    scalarField area(mesh.nPoints(), Zero);
    const faceList& faces = mesh.faces();
    const vectorField& Sf = mesh.faceAreas();

    forAll(faces, facei)
    {
        scalar share = 1.0/(3*faces[facei].size());
        if (!mesh.isInternalFace(facei))
        {
            const label patchi = mesh.boundaryMesh().whichPatch(facei);
            if
            (
                mesh.boundary()[patchi].coupled()
             || reconstruction.mirror(patchi)
            )
            {
                share *= 0.5;
            }
        }
        for (const label pointi : faces[facei])
        {
            area[pointi] += share*mag(Sf[facei]);
        }
    }

    syncTools::syncPointList(mesh, area, plusEqOp<scalar>(), scalar(0));

    return coefficient/(2*impedance*area);
}


// ************************************************************************* //
