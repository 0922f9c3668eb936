/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-mechanicalLaws

Description
    Checks every constitutive model: P(I) = 0, P = dpsi/dF (central finite
    differences), frame invariance P(QF) = Q P(F) (exact for neoHookean, to
    second order in the rotation angle for linearElastic, which is a
    small-strain law), neoHookean -> linearElastic for small strain (and
    to first order down to strains of 1e-12 in the displacement gradient:
    P(F, gradD), which equals P(F) at finite strain), the
    cofactor convention cof F = J F^-T, closed-form stresses (E 1e6,
    nu 0.3: mu = E/(2(1 + nu)), lambda = E nu/((1 + nu)(1 - 2 nu)),
    kappa = lambda + 2 mu/3):
      uniaxial strain F = I + e X X, linearElastic: P_xx = (lambda + 2 mu) e,
          P_yy = P_zz = lambda e, the rest 0;
      simple shear F = I + g X Y (J = 1), neoHookean: P_xy = mu g,
          P_yx = mu g (1 + g^2/3), P_xx = P_yy = P_zz = -mu g^2/3, the rest 0;
      uniaxial stretch F = diag(a, 1, 1) (J = a), neoHookean:
          P_xx = mu a^(-2/3) (a - (a^2 + 2)/(3 a)) + kappa (a - 1),
          P_yy = P_zz = mu a^(-2/3) (1 - (a^2 + 2)/3) + kappa (a - 1) a;
    and clear errors for bad input.
    Exits non-zero on any wrong answer.

Usage
    Test-mechanicalLaws -case <any case with a mesh>

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mechanicalLaw.H"
#include "Random.H"
#include "quaternion.H"
#include "testReport.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Material dictionary standing for constant/mechanicalProperties
dictionary material(const word& model, const scalar nu = 0.3)
{
    dictionary dict;
    dict.add("model", model);
    dict.add("rho", 1000.0);
    dict.add("E", 1e6);
    dict.add("nu", nu);
    return dict;
}


//- A random deformation gradient with det F > 0 (|F - I| ~ amplitude)
tensor randomF(Random& rnd, const scalar amplitude)
{
    tensor F(tensor::I);
    for (direction i = 0; i < tensor::nComponents; ++i)
    {
        F[i] += amplitude*(2*rnd.sample01<scalar>() - 1);
    }
    return F;
}


//- A random rotation
tensor randomRotation(Random& rnd, const scalar angle)
{
    vector axis(rnd.sample01<vector>() - 0.5*vector::one);
    axis /= mag(axis);
    return quaternion(axis, angle).R();
}


//- dpsi/dF by central differences
tensor numericalStress(const mechanicalLaw& law, const tensor& F)
{
    const scalar eps = 1e-6;
    tensor P(Zero);
    for (direction i = 0; i < tensor::nComponents; ++i)
    {
        tensor Fp(F), Fm(F);
        Fp[i] += eps;
        Fm[i] -= eps;
        P[i] = (law.strainEnergy(Fp) - law.strainEnergy(Fm))/(2*eps);
    }
    return P;
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    testReport report;
    Random rnd(1234);
    const scalar E = 1e6;

    // Cofactor convention used for the spatial normal and neoHookean
    {
        const tensor F(randomF(rnd, 0.3));
        report.check
        (
            "cof(F) = det(F) inv(F)^T",
            mag(cof(F) - det(F)*inv(F).T()),
            1e-14
        );
    }

    // Closed-form stresses, written out component by component
    {
        const scalar nu = 0.3;
        const scalar mu = E/(2*(1 + nu));
        const scalar lambda = E*nu/((1 + nu)*(1 - 2*nu));
        const scalar kappa = lambda + 2*mu/3;

        autoPtr<mechanicalLaw> linear
        (
            mechanicalLaw::New(mesh, material("linearElastic"))
        );
        autoPtr<mechanicalLaw> neo
        (
            mechanicalLaw::New(mesh, material("neoHookean"))
        );

        const scalar e = 0.015625;  // 2^-6: 1 + e - 1 = e exactly
        tensor F(tensor::I);
        F.xx() += e;
        tensor P(Zero);
        P.xx() = (lambda + 2*mu)*e;
        P.yy() = lambda*e;
        P.zz() = lambda*e;
        report.check
        (
            "linearElastic: uniaxial strain P_xx = (lambda + 2 mu) e, "
            "P_yy = P_zz = lambda e",
            mag(linear->P(F) - P)/mag(P),
            1e-14
        );

        const scalar g = 0.4;
        F = tensor::I;
        F.xy() = g;
        P = Zero;
        P.xy() = mu*g;
        P.yx() = mu*g*(1 + sqr(g)/3);
        P.xx() = -mu*sqr(g)/3;
        P.yy() = -mu*sqr(g)/3;
        P.zz() = -mu*sqr(g)/3;
        report.check
        (
            "neoHookean: simple shear P_xy = mu g, P_yx = mu g (1 + g^2/3), "
            "P_ii = -mu g^2/3",
            mag(neo->P(F) - P)/mag(P),
            1e-14
        );

        const scalar a = 1.3;
        F = tensor::I;
        F.xx() = a;
        P = Zero;
        const scalar iso = mu*Foam::pow(a, -2.0/3.0);
        P.xx() = iso*(a - (sqr(a) + 2)/(3*a)) + kappa*(a - 1);
        P.yy() = iso*(1 - (sqr(a) + 2)/3) + kappa*(a - 1)*a;
        P.zz() = P.yy();
        report.check
        (
            "neoHookean: uniaxial stretch F = diag(a, 1, 1)",
            mag(neo->P(F) - P)/mag(P),
            1e-14
        );
    }

    for (const word model : {"linearElastic", "neoHookean"})
    {
        Info<< nl << "Model " << model << nl;
        autoPtr<mechanicalLaw> law(mechanicalLaw::New(mesh, material(model)));

        report.check(model + ": P(I) = 0", mag(law->P(tensor::I))/E, 1e-14);

        for (label sample = 0; sample < 5; ++sample)
        {
            const tensor F(randomF(rnd, 0.2));
            const tensor P(law->P(F));
            report.check
            (
                model + ": P = dpsi/dF",
                mag(P - numericalStress(*law, F))/mag(P),
                1e-6
            );
            report.check
            (
                model + ": P(F, gradD = F - I) = P(F)",
                mag(law->P(F, F - tensor::I) - P)/mag(P),
                1e-13
            );
            report.check
            (
                model + ": psi(F, gradD = F - I) = psi(F)",
                mag(law->strainEnergy(F, F - tensor::I) - law->strainEnergy(F))
               /law->strainEnergy(F),
                1e-13
            );
        }

        if (model == "neoHookean")
        {
            for (label sample = 0; sample < 5; ++sample)
            {
                const tensor F(randomF(rnd, 0.3));
                const tensor Q(randomRotation(rnd, 2.0));
                report.check
                (
                    model + ": P(QF) = Q P(F)",
                    mag(law->P(Q & F) - (Q & law->P(F)))/mag(law->P(F)),
                    1e-12
                );
            }

            // Small strain: the two laws agree to first order in the strain
            autoPtr<mechanicalLaw> linear
            (
                mechanicalLaw::New(mesh, material("linearElastic"))
            );
            for (const scalar strain : {1e-3, 1e-5})
            {
                const tensor F(tensor::I + strain*(randomF(rnd, 1) - tensor::I));
                const tensor Pl(linear->P(F));
                report.check
                (
                    model + " -> linearElastic, strain "
                  + Foam::name(strain),
                    mag(law->P(F) - Pl)/mag(Pl),
                    10*strain
                );
            }

            // Written in gradD the two agree to first order down to any
            // strain (from F, a strain of 1e-9 keeps 7 digits only: 2e-7)
            for (const scalar strain : {1e-6, 1e-9, 1e-12})
            {
                const tensor gradD(strain*(randomF(rnd, 1) - tensor::I));
                const tensor F(tensor::I + gradD);
                const tensor Pl(linear->P(F, gradD));
                report.check
                (
                    model + "(gradD) -> linearElastic(gradD), strain "
                  + Foam::name(strain),
                    mag(law->P(F, gradD) - Pl)/mag(Pl),
                    10*strain + 1e-14
                );

                // The energy, of second order, keeps 1e-16/strain of
                // itself (from F: 1e-16/strain^2, 1e-4 at 1e-6)
                if (strain > 1e-8)
                {
                    const scalar psil = linear->strainEnergy(F, gradD);
                    report.check
                    (
                        model + " psi(gradD) -> linearElastic, strain "
                      + Foam::name(strain),
                        mag(law->strainEnergy(F, gradD) - psil)/psil,
                        10*strain
                    );
                }
            }
        }
        else
        {
            // A small-strain law: the stress of a pure rotation is second
            // order in its angle
            for (const scalar angle : {1e-2, 1e-3})
            {
                const tensor Q(randomRotation(rnd, angle));
                report.check
                (
                    model + ": |P(Q)|/(E angle^2), angle "
                  + Foam::name(angle),
                    mag(law->P(Q))/(E*sqr(angle)),
                    3
                );
            }
        }
    }

    // Bad input stops with an error naming the file and the entry
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    auto errorMessage = [&](const dictionary& dict)
    {
        return errorMessageOf([&]() { mechanicalLaw::New(mesh, dict); });
    };

    {
        const string msg(errorMessage(material("neoHookean", 0.5)));
        Info<< "    nu = 0.5 gives: " << msg.c_str() << nl;
        report.check
        (
            "nu = 0.5 is refused naming the entry and the range",
            msg.find("'nu'") != string::npos
         && msg.find("mechanicalProperties") != string::npos
         && msg.find("< 0.5") != string::npos
        );
    }
    {
        const string msg(errorMessage(material("neoHooke")));
        report.check
        (
            "an unknown model is refused listing the valid ones",
            msg.find("neoHooke") != string::npos
         && msg.find("linearElastic") != string::npos
         && msg.find("neoHookean") != string::npos
        );
    }
    {
        dictionary dict(material("neoHookean"));
        dict.remove("E");
        const string msg(errorMessage(dict));
        report.check
        (
            "a missing entry is refused naming it",
            msg.find("'E'") != string::npos
        );
    }

    // Exit here: the status must not be lost in argList's destructor
    Pstream::exit(report.result("Test-mechanicalLaws"));

    return 0;
}


// ************************************************************************* //
