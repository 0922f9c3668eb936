/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-restrictAliasing

Description
    Guards the build against the GCC 12 -O3 miscompilation of v1912 field
    expressions through UList's __restrict__ data pointer: F.T() & F and
    other expressions that reuse a temporary's storage must equal the same
    products taken cell by cell, to round-off (1e-14 for entries of order
    1: the miscompilation gave differences up to 0.08; with -march=native
    the two paths may contract multiply-adds differently, 3e-16).  Fails
    when the project is built without -D__restrict__= (etc/bashrc,
    FOAM_EXTRA_CXXFLAGS).

Usage
    Test-restrictAliasing -case <any case with a mesh>

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "Random.H"
#include "testReport.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    testReport report;
    Random rnd(42);

    volTensorField F
    (
        IOobject("F", runTime.timeName(), mesh),
        mesh,
        dimensionedTensor("I", dimless, tensor::I)
    );
    forAll(F, celli)
    {
        F[celli] = tensor::I + 0.5*(rnd.sample01<tensor>() - 0.5*tensor::one);
    }

    const volTensorField C(F.T() & F);
    const volTensorField B(F & F.T());
    const volScalarField J(det(F));
    const volTensorField H(J*inv(F)().T());

    scalar errC = 0, errB = 0, errH = 0;
    forAll(F, celli)
    {
        const tensor& f = F[celli];
        errC = max(errC, mag(C[celli] - (f.T() & f)));
        errB = max(errB, mag(B[celli] - (f & f.T())));
        errH = max(errH, mag(H[celli] - det(f)*inv(f).T()));
    }

    report.check("F.T() & F equals the per-cell product", errC, 1e-14);
    report.check("F & F.T() equals the per-cell product", errB, 1e-14);
    report.check("det(F) inv(F).T() equals the per-cell value", errH, 1e-15);

    // Exit here: the status must not be lost in argList's destructor
    Pstream::exit(report.result("Test-restrictAliasing"));

    return 0;
}


// ************************************************************************* //
