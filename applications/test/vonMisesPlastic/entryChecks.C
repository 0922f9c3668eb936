/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    Test-vonMisesPlastic (g): the law's entries are checked on read.

\*---------------------------------------------------------------------------*/

#include "plasticTestTools.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::plasticTest::checkEntries(const fvMesh& mesh, testReport& report)
{
    // (g) Bad entries stop with an error naming the file, the entry and
    // the range
    Info<< nl << "(g) Entries checked" << nl;
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    auto errorMessage = [&](const dictionary& dict)
    {
        return errorMessageOf([&]() { mechanicalLaw::New(mesh, dict); });
    };

    {
        const string msg(errorMessage(material(0, H)));
        Info<< "    yieldStress 0 gives: " << msg.c_str() << nl;
        report.check
        (
            "yieldStress 0 is refused naming the file, entry and range",
            msg.find("'yieldStress'") != string::npos
         && msg.find("mechanicalProperties") != string::npos
         && msg.find("0 < yieldStress") != string::npos
        );
    }
    {
        const string msg(errorMessage(material(sigmaY, -1)));
        Info<< "    hardeningModulus -1 gives: " << msg.c_str() << nl;
        report.check
        (
            "hardeningModulus -1 is refused naming the file, entry and range",
            msg.find("'hardeningModulus'") != string::npos
         && msg.find("mechanicalProperties") != string::npos
         && msg.find("0 <= hardeningModulus") != string::npos
        );
    }
    {
        dictionary dict(material(sigmaY, H));
        dict.subDict("vonMisesPlasticCoeffs")
            .add("yieldStressMeasure", "PK2");
        const string msg(errorMessage(dict));
        Info<< "    yieldStressMeasure PK2 gives: " << msg.c_str() << nl;
        report.check
        (
            "yieldStressMeasure PK2 is refused naming the entry and choices",
            msg.find("'yieldStressMeasure'") != string::npos
         && msg.find("mechanicalProperties") != string::npos
         && msg.find("Kirchhoff") != string::npos
         && msg.find("Cauchy") != string::npos
        );
    }
    {
        dictionary dict(material(sigmaY, H));
        dict.subDict("vonMisesPlasticCoeffs").remove("yieldStress");
        const string msg(errorMessage(dict));
        report.check
        (
            "a missing yieldStress is refused naming it",
            msg.find("'yieldStress'") != string::npos
        );
    }
    {
        dictionary dict(material(sigmaY, H));
        dict.remove("vonMisesPlasticCoeffs");
        const string msg(errorMessage(dict));
        Info<< "    no vonMisesPlasticCoeffs gives: " << msg.c_str() << nl;
        report.check
        (
            "a missing vonMisesPlasticCoeffs is refused naming the file,"
            " the sub-dictionary and its required entries",
            msg.find("Missing sub-dictionary vonMisesPlasticCoeffs")
         != string::npos
         && msg.find("mechanicalProperties") != string::npos
         && msg.find("yieldStress") != string::npos
         && msg.find("hardeningModulus") != string::npos
        );
    }
    {
        // The place of the law's entries before 2026-12-04
        dictionary dict(material(sigmaY, H));
        dict.add("yieldStress", sigmaY);
        const string msg(errorMessage(dict));
        Info<< "    yieldStress beside model gives: " << msg.c_str() << nl;
        report.check
        (
            "a yieldStress beside model is refused naming where it moved",
            msg.find("'yieldStress'") != string::npos
         && msg.find("vonMisesPlasticCoeffs") != string::npos
         && msg.find("mechanicalProperties") != string::npos
        );
    }
}


// ************************************************************************* //
