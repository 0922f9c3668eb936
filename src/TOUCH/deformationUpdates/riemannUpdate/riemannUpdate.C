/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "riemannUpdate.H"
#include "emptyPolyPatch.H"
#include "kinematicPointConstraints.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The patches whose condition is a contact surface between bodies
Foam::labelList contactSurfacePatches(const Foam::volVectorField& lm)
{
    Foam::DynamicList<Foam::label> patches;
    forAll(lm.boundaryField(), patchi)
    {
        const auto* condition =
            Foam::isA<Foam::solidFluxFvPatchVectorField>
            (
                lm.boundaryField()[patchi]
            );
        if (condition && condition->contactSurface())
        {
            patches.append(patchi);
        }
    }
    return Foam::labelList(std::move(patches));
}

} // End anonymous namespace


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::deformationUpdates::riemannUpdate::momentumRates
(
    const label stage,
    vectorField& lmRate,
    vectorField& pointV,
    vector& torque
)
{
    if (!law_.uniformMaterial())
    {
        momentumRatesOfMaterials(stage, lmRate, pointV, torque);
        return;
    }

    const scalar rho = law_.rho();
    faces_.forAllCoupled
    (
        [&](const solidFaces::coupledFace& face)
        {
            vector pC;
            vector tC;
            riemann_.flux
            (
                face.pL(), face.tL(), face.pR(), face.tR(), face.n(), pC, tC
            );

            tC *= face.magSf;
            faceVelocity_[face.facei] = pC/rho;

            lmRate[face.owner] += tC;
            if (face.neighbour >= 0)
            {
                lmRate[face.neighbour] -= tC;
            }
        }
    );

    tensorField fixedSum
    (
        mirrorsFormed_ ? 0 : faces_.mesh().nPoints(), Zero
    );
    faces_.forAllSolidPatches
    (
        law_,
        stage,
        [&]
        (
            const fvPatch& patch,
            solidFluxFvPatchVectorField& condition,
            const solidFluxFvPatchVectorField::interiorState& state,
            const solidFluxFvPatchVectorField::interiorState& reference
        )
        {
            // A mirror's plane is fixed in space: its flux with the
            // reference normals (the whole body's face there has the
            // normal of (F + R F R)^-T N, along N); with the boundary
            // cell's cof F N, off N by O(h) where the cell shears, the
            // plane's traction pushed along the plane and its velocity
            // crossed it
            const bool mirror = condition.mirror();
            boundaryFlux
            (
                patch, condition, mirror ? reference : state, torque
            );
            if (mirror && !mirrorsFormed_)
            {
                addMirror(patch, condition, reference, fixedSum);
            }

            const vectorField& pC = pC_[patch.index()];
            const vectorField& tC = tC_[patch.index()];
            const scalarField& magSf = patch.magSf();
            const labelUList& faceCells = patch.faceCells();

            forAll(faceCells, i)
            {
                faceVelocity_[patch.start() + i] = pC[i]/rho;
                lmRate[faceCells[i]] += tC[i]*magSf[i];
            }
        }
    );

    // The empty patches' faces (2D) have the velocity a symmetric plane's
    // flux gives them where the state is plane strain: the owner's, less
    // its part along the plane's normal axis (exactly zero)
    const fvMesh& mesh = faces_.mesh();
    const vectorField& lm = faces_.lm().primitiveField();
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(patch))
        {
            continue;
        }

        const labelUList& faceCells = patch.faceCells();
        forAll(faceCells, i)
        {
            const label facei = patch.start() + i;
            const vector magS(cmptMag(mesh.faceAreas()[facei]));
            const direction d =
                magS.x() >= max(magS.y(), magS.z())
              ? 0
              : (magS.y() >= magS.z() ? 1 : 2);
            vector v(lm[faceCells[i]]/rho);
            v[d] = 0;
            faceVelocity_[facei] = v;
        }
    }

    pointFit_.interpolate
    (
        faces_.lm().primitiveField(),
        1/rho,
        faceVelocity_,
        pointV
    );
    if (surfaceFitActive_)
    {
        surfaceFit_.interpolate(faceVelocity_, pointV);
    }
    if (!mirrorsFormed_)
    {
        formMirrors(fixedSum);
    }
    constrainMirrorPoints(pointV);
}


void Foam::deformationUpdates::riemannUpdate::momentumRatesOfMaterials
(
    const label stage,
    vectorField& lmRate,
    vectorField& pointV,
    vector& torque
)
{
    // Each side's velocity with its own density, and the flux of the two
    // impedances at every face (equal ones within a material)
    faces_.forAllCoupled
    (
        [&](const solidFaces::coupledFace& face)
        {
            const label mL = law_.material(face.owner);
            const label mR = rightMaterial(face.facei, face.neighbour);
            const scalar rhoL = law_.materialRho(mL);
            const scalar rhoR = law_.materialRho(mR);

            vector vC;
            vector tC;
            riemann_.interfaceFlux
            (
                face.pL()/rhoL, face.tL(),
                rhoL*law_.materialUp(mL), rhoL*law_.materialUs(mL),
                face.pR()/rhoR, face.tR(),
                rhoR*law_.materialUp(mR), rhoR*law_.materialUs(mR),
                face.n(), vC, tC
            );
            tC *= face.magSf;

            faceVelocity_[face.facei] = vC;
            lmRate[face.owner] += tC;
            if (face.neighbour >= 0)
            {
                lmRate[face.neighbour] -= tC;
            }
        }
    );

    // A boundary face's flux is its cell's material's (solidFaces)
    tensorField fixedSum
    (
        mirrorsFormed_ ? 0 : faces_.mesh().nPoints(), Zero
    );
    faces_.forAllSolidPatches
    (
        law_,
        stage,
        [&]
        (
            const fvPatch& patch,
            solidFluxFvPatchVectorField& condition,
            const solidFluxFvPatchVectorField::interiorState& state,
            const solidFluxFvPatchVectorField::interiorState& reference
        )
        {
            // A mirror's plane is fixed in space: its flux with the
            // reference normals (the whole body's face there has the
            // normal of (F + R F R)^-T N, along N); with the boundary
            // cell's cof F N, off N by O(h) where the cell shears, the
            // plane's traction pushed along the plane and its velocity
            // crossed it
            const bool mirror = condition.mirror();
            boundaryFlux
            (
                patch, condition, mirror ? reference : state, torque
            );
            if (mirror && !mirrorsFormed_)
            {
                addMirror(patch, condition, reference, fixedSum);
            }

            const vectorField& pC = pC_[patch.index()];
            const vectorField& tC = tC_[patch.index()];
            const scalarField& magSf = patch.magSf();
            const labelUList& faceCells = patch.faceCells();

            forAll(faceCells, i)
            {
                faceVelocity_[patch.start() + i] = pC[i]/state.rho[i];
                lmRate[faceCells[i]] += tC[i]*magSf[i];
            }
        }
    );

    const fvMesh& mesh = faces_.mesh();
    const vectorField& lm = faces_.lm().primitiveField();
    vectorField v(lm.size());
    forAll(v, celli)
    {
        v[celli] = lm[celli]/law_.rho(celli);
    }

    // The empty patches' faces as for one material
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(patch))
        {
            continue;
        }

        const labelUList& faceCells = patch.faceCells();
        forAll(faceCells, i)
        {
            const label facei = patch.start() + i;
            const vector magS(cmptMag(mesh.faceAreas()[facei]));
            const direction d =
                magS.x() >= max(magS.y(), magS.z())
              ? 0
              : (magS.y() >= magS.z() ? 1 : 2);
            vector vf(v[faceCells[i]]);
            vf[d] = 0;
            faceVelocity_[facei] = vf;
        }
    }

    pointFit_.interpolate(v, 1, faceVelocity_, pointV);
    if (surfaceFitActive_)
    {
        surfaceFit_.interpolate(faceVelocity_, pointV);
    }
    if (!mirrorsFormed_)
    {
        formMirrors(fixedSum);
    }
    constrainMirrorPoints(pointV);
}


void Foam::deformationUpdates::riemannUpdate::addMirror
(
    const fvPatch& patch,
    const solidFluxFvPatchVectorField& condition,
    const solidFluxFvPatchVectorField::interiorState& reference,
    tensorField& fixedSum
) const
{
    tensorField free(patch.size());
    vectorField velocity(patch.size());
    condition.constraint(reference, free, velocity);

    const faceList& faces = faces_.mesh().faces();
    forAll(free, i)
    {
        const tensor fixed(tensor::I - free[i]);
        for (const label pointi : faces[patch.start() + i])
        {
            fixedSum[pointi] += fixed;
        }
    }
}


void Foam::deformationUpdates::riemannUpdate::formMirrors
(
    tensorField& fixedSum
)
{
    syncTools::syncPointList
    (
        faces_.mesh(), fixedSum, plusEqOp<tensor>(), tensor::zero
    );

    DynamicList<label> points;
    DynamicList<tensor> free;
    forAll(fixedSum, pointi)
    {
        if (magSqr(fixedSum[pointi]) > 0)
        {
            points.append(pointi);
            free.append
            (
                kinematicPointConstraints::freeProjector(fixedSum[pointi])
            );
        }
    }
    mirrorPoints_.transfer(points);
    mirrorFree_.transfer(free);
    mirrorsFormed_ = true;
}


void Foam::deformationUpdates::riemannUpdate::constrainMirrorPoints
(
    vectorField& pointV
) const
{
    forAll(mirrorPoints_, m)
    {
        vector& v = pointV[mirrorPoints_[m]];
        v = mirrorFree_[m] & v;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdates::riemannUpdate::riemannUpdate
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    deformationUpdate(controls, faces, law, riemann, reconstruction),
    faceVelocity_(faces.mesh().nFaces(), Zero),
    pointFit_(faces.mesh()),
    surfaceFit_(faces.mesh(), contactSurfacePatches(faces.lm())),
    surfaceFitActive_(surfaceFit_.active()),
    mirrorsFormed_(false)
{}


// ************************************************************************* //
