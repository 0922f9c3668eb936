/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-reconstruction

Description
    Checks the least-squares linear reconstruction on the case's mesh (any
    cell shape):
    - linear fields p and P are reconstructed exactly at every face, from
      both sides, by 'linear' and by 'limitedLinear' (a linear field needs no
      limiting), on every cell whose neighbours span space;
    - with the limiter, no face value of a non-linear field leaves the range
      of its cell and the cell's face neighbours (no new extrema), for every
      cell without a boundary face (those are also bounded by their own
      extrapolation to the boundary).
    Exits non-zero on any wrong answer.

Usage
    Test-reconstruction -case <case with a mesh and a TOUCH dictionary>

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "linearReconstruction.H"
#include "calculatedFvPatchFields.H"
#include "bitSet.H"
#include "testReport.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

dictionary controls(const word& scheme, const word& limiter)
{
    dictionary dict;
    dict.add("reconstruction", scheme);
    dictionary coeffs;
    coeffs.add("limiter", limiter);
    dict.add("limitedLinearCoeffs", coeffs);
    return dict;
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    testReport report;

    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const vectorField& C = mesh.C();
    const vectorField& Cf = mesh.faceCentres();

    // Cells with a boundary face: their stencil may be regularised
    bitSet nearBoundary(mesh.nCells());
    for (label facei = mesh.nInternalFaces(); facei < mesh.nFaces(); ++facei)
    {
        nearBoundary.set(mesh.faceOwner()[facei]);
    }

    // Linear fields
    const vector a(1, -2, 3);
    const tensor B(0.5, 1, -1, 2, 0.3, 0.7, -0.4, 1.1, 0.9);
    const tensor A0(1, 2, 3, 4, 5, 6, 7, 8, 9);
    const tensor Ax(0.1, -0.2, 0.3, 0.4, 0.5, -0.6, 0.7, 0.8, 0.9);
    const tensor Ay(-1, 0, 1, 0, 2, 0, 1, 0, -1);
    const tensor Az(0.3, 0.3, -0.3, 0.2, 0, 0.1, 0.5, -0.5, 0);

    auto exactp = [&](const vector& X) { return a + (X & B); };
    auto exactP = [&](const vector& X)
    {
        return A0 + X.x()*Ax + X.y()*Ay + X.z()*Az;
    };

    volVectorField p
    (
        IOobject("p", runTime.timeName(), mesh),
        mesh,
        dimensionedVector("0", dimless, Zero),
        calculatedFvPatchVectorField::typeName
    );
    volTensorField P
    (
        IOobject("P", runTime.timeName(), mesh),
        mesh,
        dimensionedTensor("0", dimless, Zero),
        calculatedFvPatchTensorField::typeName
    );

    forAll(C, celli)
    {
        p[celli] = exactp(C[celli]);
        P[celli] = exactP(C[celli]);
    }
    p.correctBoundaryConditions();
    P.correctBoundaryConditions();

    for (const word scheme : {"linear", "limitedLinear"})
    {
        linearReconstruction rec(mesh, controls(scheme, "BarthJespersen"));
        rec.update(p, P);

        const tensorField& gp = rec.gradp();
        const tensorField& gx = rec.gradP(0);
        const tensorField& gy = rec.gradP(1);
        const tensorField& gz = rec.gradP(2);

        scalar errp = 0, errP = 0;
        label nChecked = 0;

        auto checkSide = [&](const label c, const label facei)
        {
            const vector r(Cf[facei] - C[c]);
            errp = max
            (
                errp,
                mag(linearReconstruction::p(p[c], gp[c], r) - exactp(Cf[facei]))
            );
            errP = max
            (
                errP,
                mag
                (
                    linearReconstruction::P(P[c], gx[c], gy[c], gz[c], r)
                  - exactP(Cf[facei])
                )
            );
            ++nChecked;
        };

        forAll(mesh.cells(), celli)
        {
            const cell& faces = mesh.cells()[celli];
            const bool hexLike = (faces.size() == 6);

            // Every cell of a hexahedral mesh has neighbours spanning space;
            // on other meshes check the cells away from the boundary
            if (!hexLike && nearBoundary.test(celli))
            {
                continue;
            }

            forAll(faces, i)
            {
                checkSide(celli, faces[i]);
            }
        }

        report.check
        (
            scheme + ": linear p exact at faces ("
          + Foam::name(nChecked) + " face sides)",
            errp/mag(a),
            1e-12
        );
        report.check(scheme + ": linear P exact at faces", errP/mag(A0), 1e-12);
    }

    // No new extrema for a non-linear field with the limiter
    forAll(C, celli)
    {
        const vector& X = C[celli];
        p[celli] = vector
        (
            Foam::sin(4*X.x())*Foam::cos(3*X.y()),
            Foam::sign(X.x() - 0.5) + X.z(),        // a jump
            sqr(X.x() - 0.4) + sqr(X.y() - 0.6)     // an interior minimum
        );
        P[celli] = p[celli].x()*A0 + p[celli].y()*Ax + p[celli].z()*Ay;
    }
    p.correctBoundaryConditions();
    P.correctBoundaryConditions();

    for (const word limiter : {"BarthJespersen", "Venkatakrishnan"})
    {
        linearReconstruction rec(mesh, controls("limitedLinear", limiter));
        rec.update(p, P);

        // Bounds: the cell and its face neighbours
        vectorField pMax(p.primitiveField()), pMin(p.primitiveField());
        tensorField PMax(P.primitiveField()), PMin(P.primitiveField());
        forAll(own, facei)
        {
            for (const label c : {own[facei], nei[facei]})
            {
                const label o = (c == own[facei] ? nei[facei] : own[facei]);
                pMax[c] = max(pMax[c], p[o]);
                pMin[c] = min(pMin[c], p[o]);
                PMax[c] = max(PMax[c], P[o]);
                PMin[c] = min(PMin[c], P[o]);
            }
        }

        // A cell with a boundary face is also bounded by its own
        // extrapolation to that face (linearReconstruction): check the others
        scalar overshoot = 0;
        label nValues = 0;
        forAll(own, facei)
        {
            for (const label c : {own[facei], nei[facei]})
            {
                if (nearBoundary.test(c))
                {
                    continue;
                }
                ++nValues;
                const vector r(Cf[facei] - C[c]);
                const vector pf
                (
                    linearReconstruction::p(p[c], rec.gradp()[c], r)
                );
                const tensor Pf
                (
                    linearReconstruction::P
                    (
                        P[c], rec.gradP(0)[c], rec.gradP(1)[c],
                        rec.gradP(2)[c], r
                    )
                );
                overshoot = max(overshoot, cmptMax(pf - pMax[c]));
                overshoot = max(overshoot, cmptMax(pMin[c] - pf));
                overshoot = max(overshoot, cmptMax(Pf - PMax[c]));
                overshoot = max(overshoot, cmptMax(PMin[c] - Pf));
            }
        }

        //- The count shows the check saw the mesh (a mesh of boundary
        //  cells alone would pass it vacuously)
        const label nInterior = mesh.nCells() - nearBoundary.count();
        if (nInterior == 0 || nValues == 0)
        {
            FatalErrorInFunction
                << "no cell without a boundary face in " << mesh.nCells()
                << " cells: the extrema check needs a larger mesh"
                << exit(FatalError);
        }
        report.check
        (
            limiter + ": no face value outside its cell's range ("
          + Foam::name(nValues) + " face values of "
          + Foam::name(nInterior) + " interior cells)",
            overshoot,
            1e-12
        );
    }

    // Exit here: the status must not be lost in argList's destructor
    Pstream::exit(report.result("Test-reconstruction"));

    return 0;
}


// ************************************************************************* //
