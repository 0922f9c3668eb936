/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    Test-vonMisesPlastic (c): the uniaxial stress history against the
    analytic solution.

\*---------------------------------------------------------------------------*/

#include "plasticTestTools.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::plasticTest::checkUniaxial
(
    const fvMesh& mesh,
    Random& rnd,
    volTensorField& F,
    volTensorField& P,
    testReport& report
)
{
    tensorField& Fi = F.primitiveFieldRef();
    const tensorField& Pi = P.primitiveField();
    const label nCells = mesh.nCells();

    // (c) Uniaxial stress along a rotated axis: a prescribed F history from
    // the analytic solution of the Hencky law in uniaxial Kirchhoff stress
    // tau (log strains add, ln J = (1 - 2 nu) tau/E):
    //     ln lambda_1 = tau/E + e_p,  ln lambda_2 = ln lambda_3
    //   = -nu tau/E - e_p/2,
    // e_p the axial plastic strain; on the yield surface |tau| = sigma_y0 +
    // H epsbar_p.  Loading, elastic unloading to -0.99 of the yield stress,
    // reversed yield (isotropic hardening).  Each increment n -> n+1 is one
    // step with the stages of touchSolid: a single stage at F^(n+1), or
    // RK2 (F^n, F^(n+1)), or RK3 (F^n, F^(n+1), F^(n+1/2)); the stress is
    // the output stress at F^(n+1) and epsbar_p the state return-mapped to
    // F^(n+1).  A scheme that loses plastic flow at unloading fails here.
    Info<< nl << "(c) Uniaxial stress: loading, unloading, reversed yield"
        << nl;
    {
        const tensor Q(randomRotation(rnd, 1.0));

        // (tau, e_p, epsbar_p) along the history
        DynamicList<vector> history;
        history.append(vector::zero);
        for (label i = 1; i <= 5; ++i)
        {
            history.append(vector(0.16*i*sigmaY, 0, 0));     // to 0.8 sigma_y0
        }
        for (label i = 1; i <= 100; ++i)
        {
            const scalar ep = 0.003*i;                       // to 0.3
            history.append(vector(sigmaY + H*ep, ep, ep));
        }
        const scalar epMax = 0.3;
        const scalar tauMax = sigmaY + H*epMax;
        for (label i = 1; i <= 10; ++i)                       // to -0.99
        {
            history.append(vector(tauMax*(1 - 0.199*i), epMax, epMax));
        }
        for (label i = 1; i <= 30; ++i)                       // reversed
        {
            const scalar epsbar = epMax + 0.003*i;
            history.append
            (
                vector(-(sigmaY + H*epsbar), epMax - (epsbar - epMax), epsbar)
            );
        }

        auto uniaxialF = [&](const vector& state)
        {
            const scalar ln1 = state.x()/E + state.y();
            const scalar ln2 = -nu*state.x()/E - 0.5*state.y();
            return tensor
            (
                Q
              & tensor
                (
                    Foam::exp(ln1), 0, 0,
                    0, Foam::exp(ln2), 0,
                    0, 0, Foam::exp(ln2)
                )
              & Q.T()
            );
        };

        for (const word scheme : {"one stage", "RK2", "RK3"})
        {
            autoPtr<mechanicalLaw> uniPtr
            (
                mechanicalLaw::New(mesh, material(sigmaY, H))
            );
            mechanicalLaw& uni = uniPtr();
            const vonMisesPlastic& uniPlastic =
                refCast<const vonMisesPlastic>(uni);

            scalar errTau = 0, errLateral = 0, errEps = 0, errYield = 0;
            scalar errElasticEps = 0, spread = 0;
            scalar epsFinal = 0, tauFinal = 0;

            for (label n = 0; n + 1 < history.size(); ++n)
            {
                const vector& end = history[n + 1];
                const tensor Fend(uniaxialF(end));

                List<tensor> stageF;
                List<scalar> alphas;
                if (scheme == "one stage")
                {
                    stageF = {Fend};
                    alphas = {0};
                }
                else if (scheme == "RK2")
                {
                    stageF = {uniaxialF(history[n]), Fend};
                    alphas = {0, 0.5};
                }
                else
                {
                    stageF =
                    {
                        uniaxialF(history[n]),
                        Fend,
                        uniaxialF(0.5*(history[n] + end))
                    };
                    alphas = {0, 0.75, 1.0/3.0};
                }

                const scalar epsOld = uniPlastic.epsilonP()[0];
                uni.storeOldTime();
                forAll(stageF, stagei)
                {
                    Fi = stageF[stagei];
                    uni.correct(F, P);
                    uni.advanceStage(alphas[stagei]);
                }
                Fi = Fend;
                uni.commitStep(F);

                // The output stress and the state at F^(n+1)
                Fi = Fend;
                tensorField Pout(nCells);
                uni.stress(Fi, Pout);
                symmTensor tauEnd, CpInvEnd;
                scalar epsP;
                uniPlastic.returnMapping
                (
                    Fend, uniPlastic.CpInv()[0], uniPlastic.epsilonP()[0],
                    tauEnd, CpInvEnd, epsP
                );

                const symmTensor tauBar
                (
                    transform(Q.T(), kirchhoff(Pout[0], Fend))
                );
                const scalar tau = end.x();
                const scalar epsbar = end.z();
                const bool yielding = (epsbar > history[n].z() + 1e-3);

                errTau = max(errTau, mag(tauBar.xx() - tau)/sigmaY);
                errLateral = max
                (
                    errLateral,
                    max
                    (
                        max(mag(tauBar.yy()), mag(tauBar.zz())),
                        max
                        (
                            mag(tauBar.xy()),
                            max(mag(tauBar.xz()), mag(tauBar.yz()))
                        )
                    )/sigmaY
                );
                errEps = max(errEps, mag(epsP - epsbar));
                if (yielding)
                {
                    errYield = max
                    (
                        errYield,
                        mag(mag(tauBar.xx()) - (sigmaY + H*epsP))/sigmaY
                    );
                }
                else if (scheme == "one stage")
                {
                    // Elastic steps keep epsbar_p bit for bit
                    errElasticEps = max
                    (
                        errElasticEps,
                        mag(uniPlastic.epsilonP()[0] - epsOld)
                    );
                }
                forAll(Pout, celli)
                {
                    spread = max
                    (
                        spread, mag(Pout[celli] - Pout[0])/mag(Pout[0])
                    );
                }
                epsFinal = epsP;
                tauFinal = tauBar.xx();
            }

            const word s("uniaxial, " + scheme + ": ");
            Info<< "    " << scheme << ": " << history.size() - 1
                << " increments, final epsbar_p " << epsFinal
                << ", final tau_11 " << tauFinal << nl;
            report.check
            (
                s + "|tau_11 - analytic|/sigma_y0, max over the history",
                errTau, 1e-10
            );
            report.check
            (
                s + "lateral and shear tau/sigma_y0, max", errLateral, 1e-10
            );
            report.check(s + "|epsbar_p - analytic|, max", errEps, 1e-12);
            report.check
            (
                s + "| |tau_11| - (sigma_y0 + H epsbar_p) |/sigma_y0 "
                "while yielding, max",
                errYield, 1e-10
            );
            if (scheme == "one stage")
            {
                report.check
                (
                    s + "epsbar_p change in elastic increments",
                    errElasticEps, 0
                );
            }
            report.check(s + "every cell the same stress", spread, 1e-14);
        }
    }


    // Perfect plasticity (H = 0) is accepted and lands on sigma_y0
    Info<< nl << "Perfect plasticity" << nl;
    {
        autoPtr<mechanicalLaw> perfect
        (
            mechanicalLaw::New(mesh, material(sigmaY, 0))
        );
        forAll(Fi, celli)
        {
            Fi[celli] = randomF(rnd, 0.1);
        }
        eulerStep(perfect(), F, P);
        scalar err = 0;
        forAll(Fi, celli)
        {
            err = max
            (
                err,
                mag(equivalent(kirchhoff(Pi[celli], Fi[celli])) - sigmaY)/sigmaY
            );
        }
        report.check
        (
            "H = 0: |sqrt(3/2)|tau'| - sigma_y0|/sigma_y0, max", err, 1e-10
        );
    }
}


// ************************************************************************* //
