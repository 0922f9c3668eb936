/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-pointInterpolation

Description
    Checks linearPointInterpolation, the map A from cell to point values of
    the compatible update, on the case's mesh (any cell shape):
    - a linear field is interpolated exactly at every point (on meshes other
      than hexahedra: at the points away from the boundary, where no
      least-squares stencil needs regularising);
    - the transpose is exact: f . (A v) = (A^T f) . v for arbitrary v and f,
      which is the energy pairing of the compatible update;
    and surfacePointFit, the points of contact surfaces from their faces'
    values alone, with every boundary patch as the surface:
    - a linear field of the faces is exact at every point of a flat part
      of the boundary (its faces of one normal; edges and corners, where
      the fit lies in the mean of two planes, are not), and a uniform one
      at every point.
    Exits non-zero on any wrong answer.

Usage
    Test-pointInterpolation -case <case with a mesh and a TOUCH dictionary>

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "linearPointInterpolation.H"
#include "surfacePointFit.H"
#include "calculatedFvPatchFields.H"
#include "Random.H"
#include "syncTools.H"
#include "bitSet.H"
#include "testReport.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    testReport report;

    dictionary controls;
    controls.add("reconstruction", "linear");
    const linearReconstruction reconstruction(mesh, controls);
    const linearPointInterpolation interpolation(mesh, reconstruction);

    const pointField& points = mesh.points();
    const vectorField& C = mesh.C();

    volVectorField v
    (
        IOobject("v", runTime.timeName(), mesh),
        mesh,
        dimensionedVector("0", dimless, Zero),
        calculatedFvPatchVectorField::typeName
    );

    // A linear field
    const vector a(1, -2, 3);
    const tensor B(0.5, 1, -1, 2, 0.3, 0.7, -0.4, 1.1, 0.9);
    auto exact = [&](const vector& X) { return a + (X & B); };

    forAll(C, celli)
    {
        v[celli] = exact(C[celli]);
    }
    v.correctBoundaryConditions();

    vectorField pointValues(mesh.nPoints());
    interpolation.interpolate(v, 2, pointValues);

    bool hexahedra = true;
    forAll(mesh.cells(), celli)
    {
        hexahedra = hexahedra && mesh.cells()[celli].size() == 6;
    }
    reduce(hexahedra, andOp<bool>());

    bitSet onBoundary(mesh.nPoints());
    for (label facei = mesh.nInternalFaces(); facei < mesh.nFaces(); ++facei)
    {
        if (!mesh.boundaryMesh()[mesh.boundaryMesh().whichPatch(facei)].coupled())
        {
            for (const label pointi : mesh.faces()[facei])
            {
                onBoundary.set(pointi);
            }
        }
    }

    scalar err = 0;
    label nChecked = 0;
    forAll(points, pointi)
    {
        if (hexahedra || !onBoundary.test(pointi))
        {
            err = max(err, mag(pointValues[pointi] - 2*exact(points[pointi])));
            ++nChecked;
        }
    }
    reduce(err, maxOp<scalar>());
    reduce(nChecked, sumOp<label>());

    report.check
    (
        "linear field exact at " + Foam::name(nChecked) + " points",
        err,
        1e-10
    );

    // The transpose: f . (A v) against (A^T f) . v for pseudo-random fields
    Random rnd(1234 + Pstream::myProcNo());
    forAll(C, celli)
    {
        v[celli] = rnd.sample01<vector>() - 0.5*vector::one;
    }
    v.correctBoundaryConditions();

    vectorField f(mesh.nPoints());
    forAll(f, pointi)
    {
        // Point values must agree across processors: a function of position
        const point& x = points[pointi];
        f[pointi] = vector
        (
            Foam::sin(7*x.x() + 3*x.y()),
            Foam::cos(5*x.z() - x.x()),
            Foam::sin(2*x.y()*x.z() + 1)
        );
    }

    interpolation.interpolate(v, 1, pointValues);

    // Points shared by processors count once
    const bitSet isMaster(syncTools::getMasterPoints(mesh));
    scalar fAv = 0;
    forAll(f, pointi)
    {
        if (isMaster.test(pointi))
        {
            fAv += f[pointi] & pointValues[pointi];
        }
    }
    reduce(fAv, sumOp<scalar>());

    vectorField ATf(mesh.nCells(), Zero);
    interpolation.addTranspose(f, ATf);
    const scalar ATfv = gSum(ATf & v.primitiveField());

    report.check
    (
        "transpose: f.(A v) = (A^T f).v, relative",
        mag(fAv - ATfv)/(mag(fAv) + mag(ATfv)),
        1e-12
    );

    // surfacePointFit on every non-coupled patch
    labelList patches;
    forAll(mesh.boundaryMesh(), patchi)
    {
        if (!mesh.boundaryMesh()[patchi].coupled())
        {
            patches.append(patchi);
        }
    }
    const surfacePointFit surfaceFit(mesh, patches);

    // The points whose boundary faces share one normal (on any rank)
    const vectorField& Sf = mesh.faceAreas();
    vectorField firstNormal(mesh.nPoints(), Zero);
    scalarField spread(mesh.nPoints(), Zero);
    for (const label patchi : patches)
    {
        const polyPatch& patch = mesh.boundaryMesh()[patchi];
        forAll(patch, i)
        {
            const vector n(Sf[patch.start() + i]/mag(Sf[patch.start() + i]));
            for (const label pointi : patch[i])
            {
                if (magSqr(firstNormal[pointi]) == 0)
                {
                    firstNormal[pointi] = n;
                }
                spread[pointi] =
                    max(spread[pointi], mag(n - firstNormal[pointi]));
            }
        }
    }
    syncTools::syncPointList(mesh, spread, maxEqOp<scalar>(), scalar(0));
    // A point whose faces lie on different ranks: its normal on one rank
    // may differ from another's; compare the ranks' first normals too
    vectorField otherNormal(firstNormal);
    syncTools::syncPointList
    (
        mesh, otherNormal, maxMagSqrEqOp<vector>(), vector::zero
    );

    const vectorField& Cf = mesh.faceCentres();
    vectorField faceValues(mesh.nFaces(), Zero);
    vectorField uniformValues(mesh.nFaces(), a);
    forAll(faceValues, facei)
    {
        faceValues[facei] = exact(Cf[facei]);
    }
    vectorField surfaceValues(mesh.nPoints(), vector::max);
    vectorField uniformPoints(mesh.nPoints(), vector::max);
    surfaceFit.interpolate(faceValues, surfaceValues);
    surfaceFit.interpolate(uniformValues, uniformPoints);

    scalar flatErr = 0;
    scalar uniformErr = 0;
    label nFlat = 0;
    label nSurface = 0;
    forAll(points, pointi)
    {
        if (magSqr(firstNormal[pointi]) == 0)
        {
            continue;
        }
        ++nSurface;
        uniformErr = max(uniformErr, mag(uniformPoints[pointi] - a));
        if
        (
            spread[pointi] < 1e-8
         && mag(mag(otherNormal[pointi]) - 1) < 1e-8
         && mag(otherNormal[pointi] - firstNormal[pointi]) < 1e-8
        )
        {
            flatErr =
                max(flatErr, mag(surfaceValues[pointi] - exact(points[pointi])));
            ++nFlat;
        }
    }
    reduce(flatErr, maxOp<scalar>());
    reduce(uniformErr, maxOp<scalar>());
    reduce(nFlat, sumOp<label>());
    reduce(nSurface, sumOp<label>());

    report.check
    (
        "surfacePointFit: linear field exact at "
      + Foam::name(nFlat) + " points of flat boundary parts",
        flatErr,
        1e-10
    );
    report.check
    (
        "surfacePointFit: uniform field exact at "
      + Foam::name(nSurface) + " boundary points",
        uniformErr,
        1e-12
    );

    // Exit here: the status must not be lost in argList's destructor
    Pstream::exit(report.result("Test-pointInterpolation"));

    return 0;
}


// ************************************************************************* //
