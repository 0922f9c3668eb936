/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    Test-vonMisesPlastic (f): restoreOldTime() after stages returns the
    plastic state bit for bit.

\*---------------------------------------------------------------------------*/

#include "plasticTestTools.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::plasticTest::checkRestore
(
    mechanicalLaw& law,
    const vonMisesPlastic& plastic,
    Random& rnd,
    volTensorField& F,
    volTensorField& P,
    testReport& report
)
{
    tensorField& Fi = F.primitiveFieldRef();

    // (f) A failed step returns the state bit for bit
    Info<< nl << "(f) Failed-step restore" << nl;
    {
        const volSymmTensorField CpInvN("CpInvN", plastic.CpInv());
        const volScalarField epsN("epsN", plastic.epsilonP());
        const tensorField F0(Fi);

        law.storeOldTime();
        for (const scalar alpha : {0.0, 0.75, 1.0/3.0})
        {
            forAll(Fi, celli)
            {
                Fi[celli] = randomF(rnd, 0.05) & Fi[celli];
            }
            law.correct(F, P);
            law.advanceStage(alpha);
        }
        const label nChanged =
            nDifferent(plastic.CpInv(), CpInvN)
          + nDifferent(plastic.epsilonP(), epsN);
        Info<< "    the stages changed " << nChanged << " components" << nl;
        report.check("the stages changed the state", nChanged > 0);

        law.restoreOldTime();
        Fi = F0;
        report.check
        (
            "restoreOldTime: differing components of CpInv and epsilonP",
            scalar
            (
                nDifferent(plastic.CpInv(), CpInvN)
              + nDifferent(plastic.epsilonP(), epsN)
            ),
            0
        );
    }
}


// ************************************************************************* //
