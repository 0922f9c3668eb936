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

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- 1/n for a face of n points, without a division for the usual sizes
static inline scalar inverseSize(const label n)
{
    static const scalar inverses[] =
        {0, 1, 1.0/2, 1.0/3, 1.0/4, 1.0/5, 1.0/6, 1.0/7, 1.0/8};

    return n <= 8 ? inverses[n] : 1.0/n;
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::addCellForces
(
    const label celli,
    const tensor* dPf
)
{
    const fvMesh& mesh = faces_.mesh();
    const label nInternal = mesh.nInternalFaces();
    const labelUList& own = mesh.owner();
    const faceList& faces = mesh.faces();
    const vectorField& Sf = mesh.faceAreas();
    const tensor& Pc = faces_.P()[celli];
    const bool upwindPoints = pointUpwinding_ > 0;
    const bool uniform = shares_.uniform();

    label k = -1;
    for (const label facei : cellFaces_[celli])
    {
        ++k;
        const bool interior = facei < nInternal;
        label patchi = -1;
        if (!interior)
        {
            patchi = mesh.boundaryMesh().whichPatch(facei);
            if (mesh.boundary()[patchi].size() == 0)
            {
                // empty: no flux, no force
                continue;
            }
        }

        // The area vector out of this cell
        const bool owner = !interior || own[facei] == celli;
        const vector S(owner ? Sf[facei] : -Sf[facei]);
        const Foam::face& f = faces[facei];
        const scalar invSize = inverseSize(f.size());

        // The central nodal forces: this cell's stress on its side of the
        // face (the neighbour adds its own, on this rank or another)
        const vector central(Pc & S);

        // This cell's reconstructed traction force at the face
        const vector reconstructed(central + (dPf[k] & S));

        if (uniform)
        {
            const vector force(central*invSize);
            for (const label pointi : f)
            {
                pointForce_[pointi] += force;
            }
        }
        else
        {
            shares_.forAllPoints
            (
                f, facei, Sf[facei],
                [&](const label pointi, const vector& s)
                {
                    pointForce_[pointi] += Pc & (owner ? s : -s);
                }
            );
        }

        if (!interior && !mesh.boundary()[patchi].coupled())
        {
            // The interior traction a boundary condition answers
            const label i = facei - mesh.boundary()[patchi].start();
            faces_.interiorTraction(patchi)[i] =
                reconstructed/mesh.boundary()[patchi].magSf()[i];
        }
        else if (upwindPoints)
        {
            const vector share(reconstructed*invSize);
            for (const label pointi : f)
            {
                reconstructedForce_[pointi] += share;
            }
        }
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

    reconstruction.update
    (
        lm,
        P,
        [&](const label celli, const tensor* dPf)
        {
            addCellForces(celli, dPf);
        }
    );
}



// ************************************************************************* //
