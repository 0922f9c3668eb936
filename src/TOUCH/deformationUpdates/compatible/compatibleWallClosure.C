/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's closing of the gaps of held points: a point a
    condition holds off the surface it holds it on (a rigid wall's face in
    contact holds all its points, some of them above the wall) moves onto
    it while the nodal force presses it there (closeWallGaps).

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::closeWallGaps
(
    vectorField& pointV
)
{
    const fvMesh& mesh = faces_.mesh();
    const scalar dt = mesh.time().deltaTValue();

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        const fvPatchVectorField& pf = faces_.lm().boundaryField()[patchi];
        if (patch.coupled() || !isA<solidFluxFvPatchVectorField>(pf))
        {
            continue;
        }

        // The same on every rank (the condition's type decides), also
        // one whose part of the patch is empty: the syncs below
        const tmp<vectorField> toffsets =
            refCast<const solidFluxFvPatchVectorField>(pf).pointOffsets();
        if (!toffsets.valid())
        {
            continue;
        }
        const vectorField& offsets = toffsets();

        // The speed of a free surface under the nodal force f that held
        // the point, f/(2 Z S_a) (the point upwinding's at coefficient 1),
        // with or without the point upwinding
        if (closingMobility_.empty())
        {
            closingMobility_ =
                law_.uniformMaterial()
              ? calcPointMobility
                (
                    mesh, faces_.reconstruction(), 1, law_.rho()*law_.Up()
                )
              : calcPointMobilityOfMaterials(faces_.reconstruction(), 1);
        }

        // The sum of the condition's own fixed projectors at each point,
        // on all ranks: the rest of the point's sum is the other
        // conditions' (a symmetric plane the wall meets)
        const labelList& meshPoints = patch.patch().meshPoints();
        const faceList& localFaces = patch.patch().localFaces();
        const tensorField& free = faceFree_[patchi];
        tensorField ownSum(meshPoints.size(), Zero);
        forAll(localFaces, i)
        {
            const tensor fixed(tensor::I - free[i]);
            if (magSqr(fixed) > SMALL)
            {
                for (const label pointj : localFaces[i])
                {
                    ownSum[pointj] += fixed;
                }
            }
        }
        syncTools::syncPointList
        (
            mesh, meshPoints, ownSum, plusEqOp<tensor>(), tensor::zero
        );

        forAll(meshPoints, pointj)
        {
            const scalar gap = mag(offsets[pointj]);
            if (gap < VSMALL)
            {
                continue;
            }
            const vector towards(offsets[pointj]/gap);
            const label pointi = meshPoints[pointj];

            // Only along a direction the condition fixes and no other
            // condition does (a clamped face, an inclined plane)
            const tensor others
            (
                constraints_.fixedSum(pointi) - ownSum[pointj]
            );
            if
            (
                (towards & ownSum[pointj] & towards) < 0.5
             || mag(others & towards) > 1e-9
            )
            {
                continue;
            }

            // Only while the nodal force presses the point onto the
            // surface (the condition's reaction pushes), at the speed of
            // a free surface under it, never beyond the surface in the
            // stage (each stage of the SSP scheme is a combination of
            // Euler steps of dt).  Its stress power f . w = -press |w| is
            // negative: energy is only taken out.  At the free surface's
            // speed a step moves the point by CFL of the displacement
            // that relieves the force, within which the strain energy
            // only falls; at g/dt the Taylor bar's layer was stretched
            // past its relief, the wall pulled in effect
            const scalar press = -(pointForce_[pointi] & towards);
            if (press > 0)
            {
                pointV[pointi] +=
                    min(gap/dt, closingMobility_[pointi]*press)*towards;
            }
        }
    }
}


// ************************************************************************* //
