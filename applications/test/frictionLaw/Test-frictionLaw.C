/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-frictionLaw

Description
    Checks the friction laws against Coulomb's cone, for random sticking
    tractions, pressures and sliding velocities:
    - frictionless: zero tangential traction, frictionless() true, also
      when the condition has no 'friction' sub-dictionary;
    - coulomb: |t| <= muStatic pN; t along tStick with |t| <= |tStick|, so
      that the work rate on the face's characteristic, t . (t - tStick),
      is <= 0; inside the cone (|tStick| <= muKinetic pN) the face sticks,
      t = tStick exactly; outside it slides with |t| = muKinetic pN; a
      face that stuck (zero sliding velocity) holds up to muStatic pN, one
      that slid only muKinetic pN; no pressure, no traction;
      muStatic = muKinetic = 0 gives zero;
    - bad input is refused naming the entry: an unknown law (with the
      valid names), muKinetic > muStatic, a negative coefficient, a
      coefficient of no law, 'friction' not a sub-dictionary.
    Exits non-zero on any wrong answer.

Usage
    Test-frictionLaw

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "frictionLaw.H"
#include "IStringStream.H"
#include "Random.H"
#include "testReport.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- A condition's dictionary from text
dictionary conditionDict(const string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

//- A random vector in the plane normal to z, scaled
vector randomTangent(Random& rnd, const scalar scale)
{
    return scale*vector(2*rnd.sample01<scalar>() - 1, 2*rnd.sample01<scalar>() - 1, 0);
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::noBanner();
    argList args(argc, argv, false, false, false);

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    testReport report;
    Random rnd(11);

    // No sub-dictionary, and an explicit frictionless law
    {
        autoPtr<frictionLaw> none(frictionLaw::New(dictionary()));
        autoPtr<frictionLaw> explicitNone
        (
            frictionLaw::New(conditionDict("friction { type frictionless; }"))
        );
        scalar largest = 0;
        for (label i = 0; i < 100; ++i)
        {
            const vector tStick(randomTangent(rnd, 1e6));
            const scalar pN = 1e6*rnd.sample01<scalar>();
            largest = max(largest, mag(none->tangentialTraction(tStick, pN, Zero)));
            largest = max(largest, mag(explicitNone->tangentialTraction(tStick, pN, tStick)));
        }
        report.check("frictionless: zero traction", largest, 0);
        report.check
        (
            "frictionless() of the absent and the explicit law",
            none->frictionless() && explicitNone->frictionless()
        );
    }

    // Coulomb with different static and kinetic coefficients
    const scalar muS = 0.4;
    const scalar muK = 0.25;
    autoPtr<frictionLaw> law
    (
        frictionLaw::New
        (
            conditionDict
            (
                "friction { type coulomb; muStatic 0.4; muKinetic 0.25; }"
            )
        )
    );
    report.check("coulomb: frictionless() false", !law->frictionless());
    report.check("coulomb: maxCoefficient = muStatic", law->maxCoefficient() == muS);

    scalar coneExcess = 0;      // max of |t| - muS pN
    scalar workRate = -GREAT;   // max of t . (t - tStick)/|tStick|^2
    scalar offLine = 0;         // max of |t ^ tStick|/|tStick|^2
    scalar stickError = 0;      // max |t - tStick| inside the kinetic cone
    scalar slideError = 0;      // max ||t| - muK pN|/(muK pN) sliding
    label nStick = 0;
    label nSlide = 0;

    for (label i = 0; i < 10000; ++i)
    {
        const scalar pN = 1e8*rnd.sample01<scalar>();
        const vector tStick(randomTangent(rnd, 1e8));
        const bool stuck = rnd.sample01<scalar>() < 0.5;
        const vector slip(stuck ? vector::zero : randomTangent(rnd, 10));

        const vector t(law->tangentialTraction(tStick, pN, slip));
        const scalar magStick2 = max(magSqr(tStick), VSMALL);

        coneExcess = max(coneExcess, (mag(t) - muS*pN)/(muS*pN));
        workRate = max(workRate, (t & (t - tStick))/magStick2);
        offLine = max(offLine, mag(t ^ tStick)/magStick2);

        const scalar limit = (stuck ? muS : muK)*pN;
        if (mag(tStick) <= limit)
        {
            ++nStick;
            stickError = max(stickError, mag(t - tStick));
        }
        else
        {
            ++nSlide;
            slideError = max(slideError, mag(mag(t) - muK*pN)/(muK*pN));
        }
    }

    report.check("coulomb: (|t| - muS pN)/(muS pN) <= 0", coneExcess, 0);
    report.check("coulomb: work rate t.(t - tStick)/|tStick|^2 <= 0", workRate, 0);
    report.check("coulomb: t along tStick", offLine, 1e-15);
    report.check("coulomb: sticking faces keep tStick", stickError, 0);
    report.check("coulomb: sliding faces get muK pN", slideError, 1e-15);
    report.check("coulomb: both cases sampled", nStick > 100 && nSlide > 100);

    // Between the kinetic and the static limit: a stuck face holds, a
    // sliding one slides
    {
        const scalar pN = 1e6;
        const vector tStick(0.3*pN, 0, 0);
        const vector held(law->tangentialTraction(tStick, pN, Zero));
        const vector slid(law->tangentialTraction(tStick, pN, vector(-1e-3, 0, 0)));
        report.check("coulomb: a stuck face holds 0.3 pN < muS pN", mag(held - tStick), 0);
        report.check("coulomb: a sliding face gets muK pN", mag(slid - vector(muK*pN, 0, 0)), 1e-9);
        report.check
        (
            "coulomb: no pressure, no traction",
            mag(law->tangentialTraction(tStick, 0, Zero))
          + mag(law->tangentialTraction(tStick, -pN, Zero)),
            0
        );
    }

    // mu = 0 is frictionless
    {
        autoPtr<frictionLaw> zero
        (
            frictionLaw::New
            (
                conditionDict("friction { type coulomb; muStatic 0; muKinetic 0; }")
            )
        );
        scalar largest = 0;
        for (label i = 0; i < 100; ++i)
        {
            const vector tStick(randomTangent(rnd, 1e6));
            largest = max(largest, mag(zero->tangentialTraction(tStick, 1e6, Zero)));
        }
        report.check("coulomb mu = 0: zero traction", largest, 0);
    }

    // Bad input
    {
        const string unknown
        (
            errorMessageOf
            ([]{ frictionLaw::New(conditionDict("friction { type coulom; }")); })
        );
        report.check
        (
            "unknown law refused with the valid names: " + unknown,
            unknown.find("coulomb") != string::npos
         && unknown.find("frictionless") != string::npos
        );

        const string faster
        (
            errorMessageOf
            ([]{
                frictionLaw::New
                (
                    conditionDict("friction { type coulomb; muStatic 0.2; muKinetic 0.3; }")
                );
            })
        );
        report.check
        (
            "muKinetic > muStatic refused: " + faster,
            faster.find("muKinetic") != string::npos
        );

        const string negative
        (
            errorMessageOf
            ([]{
                frictionLaw::New
                (
                    conditionDict("friction { type coulomb; muStatic -0.2; muKinetic 0; }")
                );
            })
        );
        report.check
        (
            "negative muStatic refused: " + negative,
            negative.find("muStatic") != string::npos
        );

        const string misspelt
        (
            errorMessageOf
            ([]{
                frictionLaw::New
                (
                    conditionDict
                    (
                        "friction { type coulomb; muStatic 0.2; muKinetic 0.1;"
                        " mu 0.3; }"
                    )
                );
            })
        );
        report.check
        (
            "unknown entry refused: " + misspelt,
            misspelt.find("Unknown entry 'mu'") != string::npos
        );

        const string notDict
        (
            errorMessageOf
            ([]{ frictionLaw::New(conditionDict("friction coulomb;")); })
        );
        report.check
        (
            "'friction' not a sub-dictionary refused: " + notDict,
            notDict.find("sub-dictionary") != string::npos
        );
    }

    return report.result("Test-frictionLaw");
}


// ************************************************************************* //
