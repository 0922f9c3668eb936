/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-vonMisesPlastic

Description
    Checks the von Mises hyperelastic-plastic law and its return mapping on
    the cells of a mesh, driving the state hooks as touchSolid does:
    - the eigen-decomposition (symmetricEigen: random, repeated and nearly
      repeated eigenvalues, be = I), with OpenFOAM's eigenValues printed
      for comparison,
    - the pointwise (virgin) law: P(I) = 0, P = dpsi/dF, and P equal to the
      Hencky stress computed with an independent matrix logarithm,
    - (a) below yield the stress is the Hencky stress with the state, which
      is unchanged bit for bit (virgin cells and cells unloaded after
      plastic flow, through a whole RK3 step),
    - (b) after a plastic step the stress is on the yield surface and is the
      Hencky stress of the updated state,
    - (c) uniaxial stress along a rotated axis (repeated eigenvalues) by a
      prescribed F history: loading, elastic unloading, reversed yield,
      with one stage per step and with the stages of RK2 and RK3;
      tau_11 = +-(sigma_y0 + H epsbar_p), the lateral stresses vanish and
      epsbar_p is the analytic one (no plastic flow lost at unloading),
    - (d) plastic flow is isochoric: det Cp^-1 = 1 after the return mapping
      and after a Runge-Kutta step; each stage reaches the state of its own
      F from s^n caught up to F^n,
    - (e) frame invariance P(QF) = Q P(F) and Cp^-1(QF) = Cp^-1(F) with the
      same state, elastic and plastic,
    - (f) restoreOldTime() after stages returns the state bit for bit,
    - the stored energy with the state: dE/dF = P,
    - (g) yieldStress <= 0 and hardeningModulus < 0 refused naming the file,
      the entry and the range; hardeningModulus 0 accepted; an unknown
      yieldStressMeasure refused naming the valid choices,
    - (h) in confined compression (J = 0.8) the von Mises Kirchhoff stress
      is the yield stress with yieldStressMeasure Kirchhoff, the von Mises
      Cauchy stress with Cauchy.
    Exits non-zero on any wrong answer.

Usage
    Test-vonMisesPlastic -case <any case with a mesh>

\*---------------------------------------------------------------------------*/

#include "plasticTestTools.H"

using namespace Foam;
using namespace Foam::plasticTest;

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    testReport report;
    Random rnd(4321);

    volTensorField F
    (
        IOobject("F", runTime.timeName(), mesh),
        mesh,
        dimensionedTensor("I", dimless, tensor::I)
    );
    volTensorField P
    (
        IOobject("P", runTime.timeName(), mesh),
        mesh,
        dimensionedTensor("0", dimPressure, Zero)
    );
    tensorField& Fi = F.primitiveFieldRef();
    const tensorField& Pi = P.primitiveField();
    const label nCells = mesh.nCells();


    // Eigen-decomposition
    Info<< nl << "Eigen-decomposition (symmetricEigen)" << nl;
    {
        vector values;
        tensor n;
        symmetricEigen(symmTensor::I, values, n);
        report.check
        (
            "eigen(I): values 1 and vectors I, bit for bit",
            values == vector::one && n == tensor::I
         && cmptMax(cmptMag(values - vector::one)) == 0
         && cmptMax(cmptMag(n - tensor::I)) == 0
        );

        // Random, doubly and triply repeated, nearly repeated eigenvalues,
        // exact ones known: A = Q diag Q^T
        scalar errRandom = 0, errRepeated = 0, errOrtho = 0;
        FixedList<scalar, 5> errFoam(Zero);
        for (label sample = 0; sample < 3000; ++sample)
        {
            const tensor Q(randomRotation(rnd, 3*rnd.sample01<scalar>()));
            const scalar a = 0.5 + rnd.sample01<scalar>();
            vector exact(a, 0.5 + rnd.sample01<scalar>(), 0.5 + rnd.sample01<scalar>());
            const label kind = sample % 5;
            if (kind == 1) exact.y() = a;                       // a a b
            if (kind == 2) exact = vector(a, a, a);             // a a a
            if (kind == 3) exact.y() = a*(1 + 1e-9);            // nearly
            if (kind == 4) exact = vector(a, a*(1 + 1e-12), a*(1 - 1e-12));

            const symmTensor A
            (
                transform(Q, symmTensor(exact.x(), 0, 0, exact.y(), 0, exact.z()))
            );
            vector values;
            tensor n;
            symmetricEigen(A, values, n);

            const symmTensor rebuilt
            (
                values.x()*sqr(n.x()) + values.y()*sqr(n.y())
              + values.z()*sqr(n.z())
            );
            const scalar err = mag(rebuilt - A)/mag(A);
            (kind == 0 ? errRandom : errRepeated) =
                max(kind == 0 ? errRandom : errRepeated, err);
            errOrtho = max(errOrtho, mag((n & n.T()) - tensor::I));

            // Sorted eigenvalues against the exact ones
            auto sorted = [](vector v)
            {
                if (v.x() > v.y()) Swap(v.x(), v.y());
                if (v.y() > v.z()) Swap(v.y(), v.z());
                if (v.x() > v.y()) Swap(v.x(), v.y());
                return v;
            };
            const scalar errValues =
                cmptMax(cmptMag(sorted(values) - sorted(exact)))/cmptMax(exact);
            (kind == 0 ? errRandom : errRepeated) =
                max(kind == 0 ? errRandom : errRepeated, errValues);

            // OpenFOAM's, for comparison (its warnings silenced)
            const int level = messageStream::level;
            messageStream::level = 0;
            const vector foamValues(eigenValues(A));
            messageStream::level = level;
            errFoam[kind] = max
            (
                errFoam[kind],
                cmptMax(cmptMag(foamValues - sorted(exact)))/cmptMax(exact)
            );
        }
        report.check
        (
            "eigen: random spectra, |V^T L V - A|/|A| and eigenvalue error",
            errRandom, 1e-14
        );
        report.check
        (
            "eigen: repeated and nearly repeated spectra, same errors",
            errRepeated, 1e-14
        );
        report.check("eigen: |V V^T - I|", errOrtho, 1e-14);
        Info<< "    (OpenFOAM v1912 eigenValues, max relative eigenvalue "
            << "error: distinct " << errFoam[0] << ", a a b " << errFoam[1]
            << ", a a a " << errFoam[2] << ", a a(1 + 1e-9) b " << errFoam[3]
            << ", a a(1 +- 1e-12) " << errFoam[4] << ")" << nl;
    }


    autoPtr<mechanicalLaw> lawPtr(mechanicalLaw::New(mesh, material(sigmaY, H)));
    mechanicalLaw& law = lawPtr();
    const vonMisesPlastic& plastic = refCast<const vonMisesPlastic>(law);


    // Pointwise (virgin) law
    Info<< nl << "Pointwise law (virgin state, no yield)" << nl;
    {
        report.check("P(I) = 0", mag(law.P(tensor::I))/E, 1e-14);

        scalar errHencky = 0, errEnergy = 0;
        for (label sample = 0; sample < 20; ++sample)
        {
            const tensor Fs(randomF(rnd, 0.2));
            const tensor Ps(law.P(Fs));
            const tensor Pref(henckyTau(law, Fs, symmTensor::I) & inv(Fs).T());
            errHencky = max(errHencky, mag(Ps - Pref)/mag(Pref));

            const scalar eps = 1e-6;
            tensor dpsi(Zero);
            for (direction i = 0; i < tensor::nComponents; ++i)
            {
                tensor Fp(Fs), Fm(Fs);
                Fp[i] += eps;
                Fm[i] -= eps;
                dpsi[i] =
                    (law.strainEnergy(Fp) - law.strainEnergy(Fm))/(2*eps);
            }
            errEnergy = max(errEnergy, mag(Ps - dpsi)/mag(Ps));
        }
        report.check
        (
            "P(F) = Hencky stress (series logarithm)", errHencky, 1e-12
        );
        report.check("P(F) = dpsi/dF (central differences)", errEnergy, 1e-6);
    }


    // (a) Below yield, virgin state: large rotations, small strains
    Info<< nl << "(a) Elastic below yield" << nl;
    {
        scalar maxRatio = 0;
        forAll(Fi, celli)
        {
            Fi[celli] =
                randomRotation(rnd, 3*rnd.sample01<scalar>())
              & randomF(rnd, 5e-4);
            maxRatio = max
            (
                maxRatio,
                equivalent(henckyTau(law, Fi[celli], symmTensor::I))/sigmaY
            );
        }
        Info<< "    largest trial sqrt(3/2)|tau'|/sigma_y0 = " << maxRatio
            << nl;
        report.check("the sample is below yield", maxRatio < 1);

        const volSymmTensorField CpInvBefore("CpInvBefore", plastic.CpInv());
        const volScalarField epsBefore("epsBefore", plastic.epsilonP());

        eulerStep(law, F, P);

        scalar err = 0;
        forAll(Fi, celli)
        {
            const tensor Pref
            (
                henckyTau(law, Fi[celli], symmTensor::I) & inv(Fi[celli]).T()
            );
            err = max(err, mag(Pi[celli] - Pref)/mag(Pref));
        }
        // The strains are ~5e-4: F carries them to eps/5e-4 ~ 4e-13
        report.check("virgin: P = Hencky stress, max relative error", err, 2e-11);
        report.check
        (
            "virgin: CpInv and epsilonP unchanged, differing components",
            scalar
            (
                nDifferent(plastic.CpInv(), CpInvBefore)
              + nDifferent(plastic.epsilonP(), epsBefore)
            ),
            0
        );
    }


    // (b) A plastic step from the virgin state, then a second one with
    // hardening from the first
    Info<< nl << "(b) On the yield surface after a plastic step" << nl;
    tensorField Fplastic(nCells);
    for (label step = 1; step <= 2; ++step)
    {
        forAll(Fi, celli)
        {
            Fi[celli] =
                (step == 1)
              ? (randomRotation(rnd, 3*rnd.sample01<scalar>()) & randomF(rnd, 0.1))
              : (randomF(rnd, 0.05) & Fplastic[celli]);
        }
        Fplastic = Fi;
        const scalarField eps0(plastic.epsilonP().primitiveField());

        eulerStep(law, F, P);

        const scalarField& eps = plastic.epsilonP().primitiveField();
        const symmTensorField& CpInv = plastic.CpInv().primitiveField();

        scalar fMax = 0, errHencky = 0, errRepeat = 0;
        label nYielded = 0;
        scalar dEpsMin = GREAT, dEpsMax = 0;
        forAll(Fi, celli)
        {
            const symmTensor tau(kirchhoff(Pi[celli], Fi[celli]));
            const scalar yield = sigmaY + H*eps[celli];
            fMax = max(fMax, mag(equivalent(tau) - yield)/yield);

            if (eps[celli] > eps0[celli])
            {
                ++nYielded;
            }
            dEpsMin = min(dEpsMin, eps[celli] - eps0[celli]);
            dEpsMax = max(dEpsMax, eps[celli] - eps0[celli]);

            // The updated state's elastic stress at the same F
            const symmTensor tauRef(henckyTau(law, Fi[celli], CpInv[celli]));
            errHencky = max(errHencky, mag(tau - tauRef)/mag(tauRef));
        }

        // The output stress at the updated state: the same stress
        tensorField Pout(nCells);
        law.stress(Fi, Pout);
        forAll(Fi, celli)
        {
            errRepeat = max(errRepeat, mag(Pout[celli] - Pi[celli])/mag(Pi[celli]));
        }

        const word s("step " + Foam::name(step) + ": ");
        Info<< "    " << s << nYielded << " of " << nCells
            << " cells yield, dgamma in [" << dEpsMin << ", " << dEpsMax
            << "]" << nl;
        report.check(s + "every cell yields", nYielded == nCells);
        report.check
        (
            s + "|sqrt(3/2)|tau'| - (sigma_y0 + H epsbar_p)|/yield, max",
            fMax, 1e-10
        );
        report.check
        (
            s + "tau = Hencky stress of the updated Cp^-1, max relative",
            errHencky, 1e-10
        );
        report.check
        (
            s + "stress() at the updated state = P of correct()",
            errRepeat, 1e-12
        );
    }


    // (d) Isochoric plastic flow, and the states of the stages of an RK3
    // step with plastic flow in every stage: stage 1 return-maps s^n to
    // F^n (the base), the later stages return-map the base to their F
    Info<< nl << "(d) Isochoric plastic flow; the states of the stages" << nl;
    {
        auto maxDetError = [&]()
        {
            scalar err = 0;
            for (const symmTensor& C : plastic.CpInv().primitiveField())
            {
                err = max(err, mag(det(C) - 1));
            }
            return err;
        };
        report.check
        (
            "after the return mappings of (b): max |det Cp^-1 - 1|",
            maxDetError(), 1e-12
        );

        const symmTensorField CpInvN(plastic.CpInv().primitiveField());
        const scalarField epsN(plastic.epsilonP().primitiveField());

        // Beyond the state: the base flows
        forAll(Fi, celli)
        {
            Fi[celli] = randomF(rnd, 0.05) & Fi[celli];
        }
        symmTensorField CpInvBase(nCells);
        scalarField epsBase(nCells);
        forAll(Fi, celli)
        {
            symmTensor tau;
            plastic.returnMapping
            (
                Fi[celli], CpInvN[celli], epsN[celli],
                tau, CpInvBase[celli], epsBase[celli]
            );
        }

        law.storeOldTime();
        label nDiffer = 0, nFlowing = 0;
        for (const scalar alpha : {0.0, 0.75, 1.0/3.0})
        {
            // The state this stage must reach
            symmTensorField CpInvStage(nCells);
            scalarField epsStage(nCells);
            forAll(Fi, celli)
            {
                symmTensor tau;
                plastic.returnMapping
                (
                    Fi[celli], CpInvBase[celli], epsBase[celli],
                    tau, CpInvStage[celli], epsStage[celli]
                );
                nFlowing += (epsStage[celli] > epsBase[celli]);
            }
            if (alpha == 0)
            {
                nFlowing = 0;
                CpInvStage = CpInvBase;
                epsStage = epsBase;
            }

            law.correct(F, P);
            law.advanceStage(alpha);

            forAll(Fi, celli)
            {
                for (direction c = 0; c < symmTensor::nComponents; ++c)
                {
                    nDiffer +=
                        !(plastic.CpInv()[celli][c] == CpInvStage[celli][c]);
                }
                nDiffer += !(plastic.epsilonP()[celli] == epsStage[celli]);
            }

            // The next stage's F: further on
            forAll(Fi, celli)
            {
                Fi[celli] = randomF(rnd, 0.05) & Fi[celli];
            }
        }
        law.commitStep(F);

        Info<< "    stages 2 and 3 flowed beyond the base in " << nFlowing
            << " of " << 2*nCells << " cell-stages" << nl;
        report.check("the later stages flow", nFlowing == 2*nCells);
        report.check
        (
            "RK3 stages: state = RM(RM(s^n, F^n), F^(k-1)), differing "
            "components",
            scalar(nDiffer), 0
        );
        report.check
        (
            "after the RK3 step: max |det Cp^-1 - 1|", maxDetError(), 1e-12
        );
    }


    // (e) Frame invariance with the (varied) plastic state of (b) and (d)
    Info<< nl << "(e) Frame invariance" << nl;
    {
        const symmTensorField& CpInv = plastic.CpInv().primitiveField();
        const scalarField& eps = plastic.epsilonP().primitiveField();

        for (const scalar amplitude : {1e-4, 0.2})
        {
            tensorField F1(nCells), F2(nCells), P1(nCells), P2(nCells);
            tensorField Q(nCells);
            scalar errState = 0;
            label nYielded = 0;
            forAll(F1, celli)
            {
                // Near the elastic state of the cell (Fe = I) or far beyond
                const tensor Up(sqrtSPD(inv(CpInv[celli])));
                F1[celli] = randomF(rnd, amplitude) & Up;
                Q[celli] = randomRotation(rnd, 3*rnd.sample01<scalar>());
                F2[celli] = Q[celli] & F1[celli];

                symmTensor tau1, tau2, C1, C2;
                scalar e1, e2;
                nYielded += plastic.returnMapping
                (
                    F1[celli], CpInv[celli], eps[celli], tau1, C1, e1
                );
                plastic.returnMapping
                (
                    F2[celli], CpInv[celli], eps[celli], tau2, C2, e2
                );
                errState = max(errState, mag(C2 - C1) + mag(e2 - e1));
            }
            law.stress(F1, P1);
            law.stress(F2, P2);

            scalar err = 0;
            forAll(F1, celli)
            {
                err = max
                (
                    err,
                    mag(P2[celli] - (Q[celli] & P1[celli]))/mag(P1[celli])
                );
            }
            // Rounding Q F costs eps |F|: a relative error ~ eps/strain
            // in the stress of a small elastic strain
            const scalar tolerance = max(1e-12, 1e-14/amplitude);
            const word s("|F - Up| ~ " + Foam::name(amplitude) + ", "
              + Foam::name(nYielded) + " of " + Foam::name(nCells)
              + " cells yield: ");
            report.check
            (
                s + "|P(QF) - Q P(F)|/|P(F)|, max", err, tolerance
            );
            report.check
            (
                s + "state reached at QF = at F, max difference",
                errState, 1e-12
            );
        }
    }


    // (a) again: cells unloaded elastically after plastic flow keep their
    // state bit for bit through a whole RK3 step, and P is the Hencky
    // stress of the state
    Info<< nl << "(a) Elastic below yield after plastic flow" << nl;
    {
        const symmTensorField& CpInv = plastic.CpInv().primitiveField();
        forAll(Fi, celli)
        {
            Fi[celli] =
                randomRotation(rnd, 3*rnd.sample01<scalar>())
              & randomF(rnd, 5e-4) & sqrtSPD(inv(CpInv[celli]));
        }

        const volSymmTensorField CpInvBefore("CpInvBefore", plastic.CpInv());
        const volScalarField epsBefore("epsBefore", plastic.epsilonP());

        law.storeOldTime();
        for (const scalar alpha : {0.0, 0.75, 1.0/3.0})
        {
            law.correct(F, P);
            law.advanceStage(alpha);
        }
        law.commitStep(F);

        scalar err = 0;
        forAll(Fi, celli)
        {
            const tensor Pref
            (
                henckyTau(law, Fi[celli], CpInv[celli]) & inv(Fi[celli]).T()
            );
            err = max(err, mag(Pi[celli] - Pref)/mag(Pref));
        }
        report.check
        (
            "unloaded: P = Hencky stress of the state, max relative", err, 1e-10
        );
        report.check
        (
            "unloaded: state unchanged through RK3, differing components",
            scalar
            (
                nDifferent(plastic.CpInv(), CpInvBefore)
              + nDifferent(plastic.epsilonP(), epsBefore)
            ),
            0
        );

        // The stored energy with the state: dE/dF = P, and (nearly) zero
        // where the elastic deformation is (nearly) none although the
        // virgin law's energy of the same F is not
        const scalarField& V = mesh.V();
        scalar errEnergy = 0;
        for (const label celli : {label(0), nCells/2, nCells - 1})
        {
            const scalar h = 1e-7;
            tensor dE(Zero);
            for (direction i = 0; i < tensor::nComponents; ++i)
            {
                const tensor F0(Fi[celli]);
                Fi[celli][i] = F0[i] + h;
                const scalar Ep = law.totalStrainEnergy(F);
                Fi[celli][i] = F0[i] - h;
                const scalar Em = law.totalStrainEnergy(F);
                Fi[celli] = F0;
                dE[i] = (Ep - Em)/(2*h*V[celli]);
            }
            errEnergy = max(errEnergy, mag(dE - Pi[celli])/mag(Pi[celli]));
        }
        report.check
        (
            "stored energy with the state: dE/dF = P, max relative",
            errEnergy, 1e-6
        );

        scalar virgin = 0;
        forAll(Fi, celli)
        {
            virgin += V[celli]*law.strainEnergy(Fi[celli]);
        }
        const scalar stored = law.totalStrainEnergy(F);
        Info<< "    stored energy " << stored << " J, virgin law at the same "
            << "F " << virgin << " J" << nl;
        report.check("stored energy: elastic part only", stored < 1e-3*virgin);
    }


    checkRestore(law, plastic, rnd, F, P, report);

    lawPtr.clear();


    checkUniaxial(mesh, rnd, F, P, report);


    checkYieldMeasure(mesh, report);


    checkEntries(mesh, report);

    // Exit here: the status must not be lost in argList's destructor
    Pstream::exit(report.result("Test-vonMisesPlastic"));

    return 0;
}


// ************************************************************************* //
