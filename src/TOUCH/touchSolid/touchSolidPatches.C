/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The mesh's patch types: which the solid refuses, the checks of a 2D
    mesh (empty patches) and its plane strain, and which patches are
    mirrors (symmetricPlanes mirror).

\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "symmetryPolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "syncTools.H"
#include "declaredEntry.H"
#include "emptyFvPatch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- What to use instead of a patch type the solid cannot use
static string patchTypeAdvice(const polyPatch& patch)
{
    if (isA<wedgePolyPatch>(patch))
    {
        return
            "Axisymmetric (wedge) cases are not supported: mesh a 3D sector"
            " bounded by patches of type patch with the condition"
            " symmetricPlane in 0/U (tutorials/taylorImpact is a quarter"
            " of the bar between two such planes).";
    }
    if (isA<symmetryPlanePolyPatch>(patch) || isA<symmetryPolyPatch>(patch))
    {
        return
            "The solid's symmetry plane is the condition symmetricPlane"
            " (normal velocity and shear traction zero) on a patch of type"
            " patch: OpenFOAM's symmetry types impose their own field type"
            " on every field, in place of the one 0/U gives.";
    }
    if (patch.coupled() || patch.type().find("cyclic") != string::npos)
    {
        // The cyclic family (cyclicAMI and cyclicACMI are not coupled()
        // polyPatches)
        return
            "Periodic and coupled patches other than processor ones are not"
            " supported: mesh the whole body, or cut it on its planes of"
            " symmetry with the conditions symmetricPlane or"
            " skewSymmetricPlane.";
    }
    return
        "Of OpenFOAM's constraint types the solid uses empty (2D) and"
        " processor only.";
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> symmetricPlanesEntry
    (
        "system/fvSolution TOUCH", "symmetricPlanes",
        "symmetric and skew-symmetric planes as one-sided boundaries or as"
        " mirrors (gradients, limiter and point motion see each cell's"
        " reflection)",
        "-", word("oneSided"), entryLimits::oneOf({"oneSided", "mirror"})
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //


bool Foam::touchSolid::readMirrorPlanes(const dictionary& controls)
{
    return symmetricPlanesEntry.read(controls) == "mirror";
}


const Foam::dictionary& Foam::touchSolid::readControls(const fvMesh& mesh)
{
    const dictionary& controls = mesh.solutionDict().subDict("TOUCH");
    const string where("system/fvSolution TOUCH");

    entryDeclaration::checkEntries
    (
        controls, where, entryDeclaration::subDictionaries(where)
    );

    return controls;
}


Foam::scalarList Foam::touchSolid::mirrorPatches
(
    const volVectorField& lm,
    const bool mirrorPlanes
)
{
    scalarList signs(lm.boundaryField().size(), scalar(0));
    if (!mirrorPlanes)
    {
        return signs;
    }

    forAll(lm.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = lm.boundaryField()[patchi];
        if (isA<emptyFvPatch>(pf.patch()))
        {
            // A 2D case is its one-cell slab between symmetric planes
            signs[patchi] = 1;
        }
        else if (isA<solidFluxFvPatchVectorField>(pf))
        {
            const solidFluxFvPatchVectorField& condition =
                refCast<const solidFluxFvPatchVectorField>(pf);
            if (condition.mirror())
            {
                signs[patchi] = condition.mirrorSign();
            }
        }
    }

    return signs;
}


void Foam::touchSolid::checkPatchTypes(const fvMesh& mesh)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();

    for (const polyPatch& patch : patches)
    {
        const bool processor =
            isA<processorPolyPatch>(patch)
        && !isA<processorCyclicPolyPatch>(patch);

        if
        (
            isA<emptyPolyPatch>(patch)
         || processor
         || (!patch.coupled() && !polyPatch::constraintType(patch.type()))
        )
        {
            // A patch (wall, mapped, ...) takes a solid condition in 0/U
            continue;
        }

        FatalErrorInFunction
            << "Patch " << patch.name() << " has type '" << patch.type()
            << "' in " << patches.objectPath()
            << ", which touchFoam cannot use." << nl
            << patchTypeAdvice(patch).c_str() << nl
            << "Give the patch type patch (or wall) in the mesh"
            << " (blockMeshDict) and one of the solid boundary conditions"
            << " in " << mesh.time().timeName()/"U" << " (or lm): "
            << solidFluxFvPatchVectorField::types() << nl
            << exit(FatalError);
    }
}


void Foam::touchSolid::checkTwoD() const
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    if (mesh_.nSolutionD() == 3)
    {
        return;
    }

    // The empty planes normal to the directions left out: the constraint of
    // their points (I - N N) and the zeroed components then agree exactly
    const Vector<label>& solutionD = mesh_.solutionD();
    labelList onEmpty(mesh_.nPoints(), 0);

    for (const polyPatch& patch : patches)
    {
        if (!isA<emptyPolyPatch>(patch))
        {
            continue;
        }

        const vectorField::subField Sf(patch.patchSlice(mesh_.faceAreas()));
        forAll(Sf, i)
        {
            const vector N(Sf[i]/mag(Sf[i]));
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (solutionD[d] > 0 && mag(N[d]) > 1e-6)
                {
                    FatalErrorInFunction
                        << "Face " << i << " of the empty patch "
                        << patch.name() << " in " << patches.objectPath()
                        << " has the normal " << N << ": a 2D mesh's empty"
                        << " planes must be normal to a coordinate axis"
                        << " (x, y or z)" << nl << exit(FatalError);
                }
            }
            for (const label pointi : patch[i])
            {
                onEmpty[pointi] = 1;
            }
        }
    }

    syncTools::syncPointList(mesh_, onEmpty, maxEqOp<label>(), label(0));

    const label nOff = returnReduce(onEmpty.size() - sum(onEmpty), sumOp<label>());
    if (nOff)
    {
        FatalErrorInFunction
            << "The mesh has empty patches (2D) but " << nOff
            << " of its points lie on none of their faces: a 2D mesh is"
            << " one cell thick between its empty patches (blockMesh: 1"
            << " cell across them); see " << patches.objectPath() << nl
            << exit(FatalError);
    }
}


void Foam::touchSolid::constrainEmptyDirections()
{
    // Plane strain: no momentum and no shear across the left-out
    // directions. The point constraints give v_d = 0 at every point
    // exactly, so F's row d stays e_d; its column d and the momentum gain
    // round-off from the faces' normals, which this takes out
    const Vector<label>& solutionD = mesh_.solutionD();
    vectorField& lm = lm_.primitiveFieldRef();
    tensorField& F = F_.primitiveFieldRef();
    tensorField& gradD = gradD_.primitiveFieldRef();

    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD[d] > 0)
        {
            continue;
        }

        forAll(lm, celli)
        {
            lm[celli][d] = 0;
            tensor& Fc = F[celli];
            tensor& Gc = gradD[celli];
            for (direction i = 0; i < vector::nComponents; ++i)
            {
                if (i != d)
                {
                    Fc[3*i + d] = 0;
                    Fc[3*d + i] = 0;
                    Gc[3*i + d] = 0;
                    Gc[3*d + i] = 0;
                }
            }
        }
    }
}


// ************************************************************************* //
