/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-riemannSolver

Description
    Checks the acoustic Riemann solver and the boundary conditions:
    - consistency: equal left and right states give the physical flux
      (t^C = t, p^C = p);
    - conservation: the flux seen from the right cell (normal reversed,
      tractions of the reversed normal) is the same contact momentum and the
      opposite traction;
    - upwinding: a pure normal (tangential) momentum jump gives the traction
      Up/2 (Us/2) times the jump;
    - the wave speeds: Up = sqrt((lambda + 2 mu)/rho) and Us = sqrt(mu/rho)
      computed here from E, nu and rho of constant/mechanicalProperties;
    - the contact velocity of a traction jump against the 1D acoustic
      closed form: equal momenta and tractions tL, tR = tL + [[t]] give
      p^C - p = ([[t]].n) n/(2 Up) + (I - n n)[[t]]/(2 Us) (the two
      characteristics meet with momenta whose difference carries the
      traction jump over the impedances rho Up and rho Us);
    - every boundary condition of the test case imposes what it claims
      (zero normal velocity and shear traction on symmetric planes, ...),
      and returns the interior state when that state already satisfies it.
    Exits non-zero on any wrong answer.

Usage
    Test-riemannSolver -case applications/test/case

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mechanicalLaw.H"
#include "riemannSolver.H"
#include "solidFluxFvPatchVectorField.H"
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
    Random rnd(7);

    autoPtr<mechanicalLaw> law(mechanicalLaw::New(mesh));
    const dictionary& controls = mesh.solutionDict().subDict("TOUCH");
    autoPtr<riemannSolver> riemann(riemannSolver::New(controls, *law));

    const scalar Up = law->Up();
    const scalar Us = law->Us();
    const scalar rho = law->rho();
    const scalar pScale = rho*Up;   // momentum of a 1 m/s velocity, ...
    const scalar tScale = law->E(); // ... and a unit strain

    // The wave speeds from the material entries, independently of the law
    const IOdictionary properties
    (
        IOobject
        (
            "mechanicalProperties", runTime.constant(), mesh,
            IOobject::MUST_READ
        )
    );
    const scalar E0(properties.get<scalar>("E"));
    const scalar nu0(properties.get<scalar>("nu"));
    const scalar rho0(properties.get<scalar>("rho"));
    const scalar mu0 = E0/(2*(1 + nu0));
    const scalar lambda0 = E0*nu0/((1 + nu0)*(1 - 2*nu0));
    const scalar Up0 = Foam::sqrt((lambda0 + 2*mu0)/rho0);
    const scalar Us0 = Foam::sqrt(mu0/rho0);
    Info<< "Up " << Up << " (closed form " << Up0 << "), Us " << Us
        << " (closed form " << Us0 << ")" << nl;
    report.check("Up = sqrt((lambda + 2 mu)/rho)", mag(Up - Up0)/Up0, 1e-14);
    report.check("Us = sqrt(mu/rho)", mag(Us - Us0)/Us0, 1e-14);

    auto randomVector = [&](const scalar scale)
    {
        return scale*(rnd.sample01<vector>() - 0.5*vector::one);
    };
    auto unitVector = [&]()
    {
        const vector v(randomVector(1));
        return v/mag(v);
    };

    for (label sample = 0; sample < 5; ++sample)
    {
        const vector n(unitVector());
        const vector pL(randomVector(pScale)), tL(randomVector(tScale));
        const vector pR(randomVector(pScale)), tR(randomVector(tScale));
        vector pC, tC;

        riemann->flux(pL, tL, pL, tL, n, pC, tC);
        report.check
        (
            "consistency: equal states give t^C = t, p^C = p",
            mag(tC - tL)/tScale + mag(pC - pL)/pScale,
            1e-14
        );

        vector pC2, tC2;
        riemann->flux(pL, tL, pR, tR, n, pC, tC);
        riemann->flux(pR, -tR, pL, -tL, -n, pC2, tC2);
        report.check
        (
            "conservation: the right cell sees -t^C and the same p^C",
            mag(tC + tC2)/tScale + mag(pC - pC2)/pScale,
            1e-14
        );

        // Normal and tangential momentum jumps with equal tractions
        const vector tangent(unitVector() ^ n);
        riemann->flux(pL, tL, pL + pScale*n, tL, n, pC, tC);
        report.check
        (
            "upwinding: normal jump gives Up/2 [[p]]",
            mag(tC - tL - 0.5*Up*pScale*n)/tScale,
            1e-14
        );
        riemann->flux
        (
            pL, tL, pL + pScale*tangent/mag(tangent), tL, n, pC, tC
        );
        report.check
        (
            "upwinding: tangential jump gives Us/2 [[p]]",
            mag(tC - tL - 0.5*Us*pScale*tangent/mag(tangent))/tScale,
            1e-14
        );

        // A traction jump at equal momenta: the closed-form contact
        // velocity with the closed-form wave speeds
        const vector jump(randomVector(tScale));
        riemann->flux(pL, tL, pL, tL + jump, n, pC, tC);
        const vector jumpN((jump & n)*n);
        report.check
        (
            "traction jump: p^C - p = [[t]]n/(2 Up) + [[t]]s/(2 Us)",
            mag(pC - pL - jumpN/(2*Up0) - (jump - jumpN)/(2*Us0))/pScale,
            1e-14
        );
        report.check
        (
            "traction jump: t^C = mean of the tractions",
            mag(tC - tL - 0.5*jump)/tScale,
            1e-14
        );
    }

    // The flux between two materials (interfaceFlux), in velocities
    for (label sample = 0; sample < 5; ++sample)
    {
        const vector n(unitVector());
        const vector vL(randomVector(1)), tL(randomVector(tScale));
        const vector vR(randomVector(1)), tR(randomVector(tScale));
        const scalar Zn = rho*Up;
        const scalar Zt = rho*Us;
        vector vC, tC, pC, tC1;

        // Equal impedances: the one-material flux, p = rho v
        riemann->interfaceFlux(vL, tL, Zn, Zt, vR, tR, Zn, Zt, n, vC, tC);
        riemann->flux(rho*vL, tL, rho*vR, tR, n, pC, tC1);
        report.check
        (
            "interface flux of equal impedances is the material's flux",
            mag(tC - tC1)/tScale + mag(rho*vC - pC)/pScale,
            1e-13
        );

        // Impedances Z_L, Z_R = 3 Z_L (normal) and 2 Z_L (tangential):
        // a state at rest and unloaded on the right, a normal stress
        // wave (t = -Z_L v n in the left material, moving right)
        const scalar ZnR = 3*Zn;
        const scalar ZtR = 2*Zt;
        const scalar v0 = 1.7;
        riemann->interfaceFlux
        (
            v0*n, -Zn*v0*n, Zn, Zt, Zero, Zero, ZnR, ZtR, n, vC, tC
        );
        // Transmitted stress 2 Z_R/(Z_L + Z_R) of the incident one
        report.check
        (
            "interface: transmitted normal stress 2 Z_R/(Z_L + Z_R)",
            mag(tC - (2*ZnR/(Zn + ZnR))*(-Zn*v0)*n)/(Zn*v0),
            1e-14
        );
        // Contact velocity 2 Z_L v0/(Z_L + Z_R), tangential the same
        const vector tangent((unitVector() ^ n)/mag(unitVector() ^ n));
        vector vC2, tC2;
        riemann->interfaceFlux
        (
            v0*tangent, -Zt*v0*tangent, Zn, Zt, Zero, Zero, ZnR, ZtR, n,
            vC2, tC2
        );
        report.check
        (
            "interface: contact velocities 2 Z_L v0/(Z_L + Z_R)",
            mag(vC - (2*Zn/(Zn + ZnR))*v0*n)/v0
          + mag(vC2 - (2*Zt/(Zt + ZtR))*v0*tangent)/v0,
            1e-14
        );
        // Conservation: seen from the right, -t^C and the same v^C
        riemann->interfaceFlux(vL, tL, Zn, Zt, vR, tR, ZnR, ZtR, n, vC, tC);
        riemann->interfaceFlux
        (
            vR, -tR, ZnR, ZtR, vL, -tL, Zn, Zt, -n, vC2, tC2
        );
        report.check
        (
            "interface: the right cell sees -t^C and the same v^C",
            mag(tC + tC2)/tScale + mag(vC - vC2),
            1e-13
        );
    }

    // Boundary conditions of the test case, fed random interior states
    volVectorField lm
    (
        IOobject("lm", runTime.timeName(), mesh, IOobject::MUST_READ),
        mesh
    );

    forAll(lm.boundaryField(), patchi)
    {
        const auto& bc =
            refCast<const solidFluxFvPatchVectorField>
            (
                lm.boundaryField()[patchi]
            );
        const label size = bc.size();
        const word type(bc.type());
        const word patch(bc.patch().name());

        vectorField pM(size), tM(size), nM(size), xM(bc.patch().Cf());
        forAll(pM, i)
        {
            pM[i] = randomVector(pScale);
            tM[i] = randomVector(tScale);
            nM[i] = unitVector();
        }

        const scalarField rhoF(size, rho), UpF(size, Up), UsF(size, Us);
        const solidFluxFvPatchVectorField::interiorState interior
        {
            pM, tM, nM, xM, xM, rhoF, UpF, UsF, 1, 0
        };
        vectorField pC(size), tC(size);
        bc.flux(interior, pC, tC);

        scalar err = 0;

        forAll(pC, i)
        {
            const vector& n = nM[i];
            const tensor nn(sqr(n));
            const tensor T(tensor::I - nn);

            if (type == "symmetricPlane")
            {
                err = max(err, mag(n & pC[i])/pScale + mag(T & tC[i])/tScale);
            }
            else if (type == "skewSymmetricPlane")
            {
                err = max(err, mag(T & pC[i])/pScale + mag(n & tC[i])/tScale);
            }
            else if (type == "clamped")
            {
                err = max(err, mag(pC[i])/pScale);
            }
            else if (type == "traction")
            {
                // The test case: traction (1e5 0 0) and pressure 5e4 on Z0,
                // free on Z1
                const vector tStar
                (
                    patch == "Z0"
                  ? vector(1e5, 0, 0) - 5e4*n
                  : vector::zero
                );
                err = max(err, mag(tC[i] - tStar)/tScale);
            }
            else if (type == "prescribedVelocity")
            {
                err = max(err, mag(pC[i] - rho*vector(1, 2, 3))/pScale);
            }
        }

        report.check(patch + " (" + type + ") imposes its condition", err, 1e-14);

        // An interior state that satisfies the condition is left unchanged
        forAll(pM, i)
        {
            const vector& n = nM[i];
            const tensor nn(sqr(n));
            const tensor T(tensor::I - nn);

            if (type == "symmetricPlane")
            {
                pM[i] = T & pM[i];
                tM[i] = nn & tM[i];
            }
            else if (type == "skewSymmetricPlane")
            {
                pM[i] = nn & pM[i];
                tM[i] = T & tM[i];
            }
            else if (type == "clamped")
            {
                pM[i] = Zero;
            }
            else if (type == "traction")
            {
                tM[i] =
                    patch == "Z0" ? vector(1e5, 0, 0) - 5e4*n : vector::zero;
            }
            else if (type == "prescribedVelocity")
            {
                pM[i] = rho*vector(1, 2, 3);
            }
        }
        bc.flux(interior, pC, tC);
        report.check
        (
            patch + " (" + type + ") keeps a state that satisfies it",
            max(mag(pC - pM))/pScale + max(mag(tC - tM))/tScale,
            1e-14
        );
    }

    // Exit here: the status must not be lost in argList's destructor
    Pstream::exit(report.result("Test-riemannSolver"));

    return 0;
}


// ************************************************************************* //
