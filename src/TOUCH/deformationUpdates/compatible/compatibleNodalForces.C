/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's reconstruction pass: the nodal forces, the
    reconstructed traction forces and the boundary tractions, cell by cell
    from the stress and its limited derivatives.

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::addBoundaryCellForce
(
    const label celli,
    const label facei,
    const tensor& dPf
)
{
    // The boundary's face-to-patch table, not whichPatch's search at each
    // face of each stage
    const fvMesh& mesh = faces_.mesh();
    const label patchi =
        mesh.boundaryMesh().patchID()[facei - mesh.nInternalFaces()];
    const fvPatch& patch = mesh.boundary()[patchi];
    if (patch.size() == 0)
    {
        // empty: no flux, no force
        return;
    }

    const vector& S = mesh.faceAreas()[facei];
    if (patch.coupled())
    {
        if (pointUpwinding_ > 0)
        {
            faceIncrementForce_[facei] = dPf & S;
        }
    }
    else
    {
        // The interior traction a boundary condition answers
        const label i = facei - patch.start();
        faces_.interiorTraction(patchi)[i] =
            ((faces_.P()[celli] + dPf) & S)/patch.magSf()[i];
    }
}


void Foam::deformationUpdates::compatible::completeNodalForces()
{
    syncTools::syncPointList
    (
        faces_.mesh(), pointForce_, plusEqOp<vector>(), vector::zero
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::reconstruct
(
    linearReconstruction& reconstruction,
    const volVectorField& lm,
    const volTensorField& P
)
{
    // The stress gradients serve only this cell's faces: its nodal forces,
    // the reconstructed traction jumps of the point upwinding and the
    // interior tractions of the boundary conditions. Taken cell by cell
    // they are never stored (27 numbers a cell) nor exchanged, and the
    // face loop no longer reads them
    pointForce_ = Zero;
    reconstructedForce_ = Zero;
    faceIncrementForce_ = Zero;

    // The nodal forces themselves are added face by face (addFaceForces):
    // a cell gives only what needs its stress gradient, the force of the
    // stress increment to each of its faces, summed over the face's two
    // sides, and the interior traction of its boundary-condition faces
    const fvMesh& mesh = faces_.mesh();
    const label nInternal = mesh.nInternalFaces();
    const labelUList& own = mesh.owner();
    const vectorField& Sf = mesh.faceAreas();
    const compactAddressing::rows& cellFaces = cellFaces_;
    const bool upwindPoints = pointUpwinding_ > 0;
    vector* incrementForce = faceIncrementForce_.data();

    reconstruction.update
    (
        lm,
        P,
        [&](const label celli, const tensor* dPf)
        {
            label k = 0;
            for (const label facei : cellFaces[celli])
            {
                if (facei < nInternal)
                {
                    if (upwindPoints)
                    {
                        // The area vector out of this cell
                        const vector dForce(dPf[k] & Sf[facei]);
                        incrementForce[facei] +=
                            own[facei] == celli ? dForce : -dForce;
                    }
                }
                else
                {
                    addBoundaryCellForce(celli, facei, dPf[k]);
                }
                ++k;
            }
        }
    );
}



// ************************************************************************* //
