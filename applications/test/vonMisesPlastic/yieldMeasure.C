/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    Test-vonMisesPlastic (h): the stress the yield stress bounds.

    Confined compression F = diag(1, 0.8, 1) (J = 0.8, proportional: one
    return from the virgin state is the exact incremental answer): with
    yieldStressMeasure Kirchhoff the von Mises Kirchhoff stress is
    sigma_y0 + H epsbar_p, with Cauchy the von Mises Cauchy stress tau/J is.
    For comparison, CalculiX 2.20 (one C3D8, NLGEOM, *PLASTIC, the same
    copper) gives a Cauchy von Mises stress of 4.146e8 Pa at epsbar_p
    0.1457: yield on the Cauchy stress.

\*---------------------------------------------------------------------------*/

#include "plasticTestTools.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::plasticTest::checkYieldMeasure
(
    const fvMesh& mesh,
    testReport& report
)
{
    Info<< nl << "(h) The stress the yield stress bounds" << nl;

    const tensor F(1, 0, 0, 0, 0.8, 0, 0, 0, 1);
    const scalar J = det(F);
    scalar vonMises[2] = {0, 0};

    for (const bool cauchy : {false, true})
    {
        dictionary dict(material(sigmaY, H));
        if (cauchy)
        {
            dict.subDict("vonMisesPlasticCoeffs")
                .add("yieldStressMeasure", "Cauchy");
        }
        autoPtr<mechanicalLaw> lawPtr(mechanicalLaw::New(mesh, dict));
        const vonMisesPlastic& law = refCast<const vonMisesPlastic>(*lawPtr);

        symmTensor tau, CpInv;
        scalar epsilonP;
        const bool plastic =
            law.returnMapping
            (
                F, symmTensor::I, 0, tau, CpInv, epsilonP
            );

        const scalar tauEq = Foam::sqrt(1.5)*mag(dev(tau));
        const scalar bounded = cauchy ? tauEq/J : tauEq;
        const scalar yield = sigmaY + H*epsilonP;
        vonMises[cauchy] = tauEq/J;

        const word name(cauchy ? "Cauchy" : "Kirchhoff");
        Info<< "    " << name << ": epsbar_p " << epsilonP
            << ", von Mises of tau " << tauEq << ", of sigma " << tauEq/J
            << ", yield " << yield << nl;

        report.check(name + ": the point yields", plastic);
        report.check
        (
            name + ": the von Mises " + name + " stress is the yield stress",
            mag(bounded - yield)/yield,
            1e-12
        );
    }

    // The Cauchy measure yields J times as early on tau: its Cauchy von
    // Mises stress is about J times the Kirchhoff one's
    report.check
    (
        "the two measures differ by J",
        mag(vonMises[1]/vonMises[0] - J),
        1e-3
    );
}


// ************************************************************************* //
