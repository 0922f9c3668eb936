/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    touchSolid's checks and reports: input that reads but cannot be meant
    (unused Coeffs, wave speeds no material has, an initial F whose stress
    overflows, a CFL number above the measured stable one), an initial
    velocity that a clamped patch or a symmetric plane forbids, and the
    report of a cell a step made invalid: where it is (label, reference and
    current centre, nearest boundary, body), what it holds (J, F, |lm|, the
    law's state) and when (step, dt, Runge-Kutta stage).

\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
#include "modelCoeffs.H"
#include "emptyFvPatch.H"
#include "clampedFvPatchVectorField.H"
#include "symmetricPlaneFvPatchVectorField.H"
#include "regionSplit.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::label Foam::touchSolid::firstInvalidCell() const
{
    forAll(F_, celli)
    {
        if (!validCell(F_[celli], lm_[celli]))
        {
            return celli;
        }
    }

    return -1;
}



void Foam::touchSolid::checkInput() const
{
    // The sub-dictionary of a model that is not selected is ignored
    // (kept while switching models back and forth): say so
    checkUnusedCoeffs
    (
        controls_, "system/fvSolution TOUCH", "reconstruction or FUpdate"
    );

    // A modulus in the wrong unit (MPa for Pa) is legal but gives a wave
    // speed no material has: elastic solids lie between a soft gel's
    // (about 10 m/s) and diamond's (about 18000 m/s)
    for (label m = 0; m < law_->nMaterials(); ++m)
    {
        const scalar Up = law_->materialUp(m);
        if (Up < 10 || Up > 20000)
        {
            WarningInFunction
                << "The longitudinal wave speed Up = " << Up << " m/s of"
                << " material " << m << " in constant/mechanicalProperties"
                << " lies outside 10 .. 20000 m/s, the range of solid"
                << " materials: are E [Pa] and rho [kg/m^3] in SI units"
                << " (rho " << law_->materialRho(m) << " kg/m^3)?" << endl;
        }
    }

    // An initial F whose stress overflows (a component of 1e300) is
    // finite with J > 0, and would stop the first step with a
    // floating-point trap: name it while the input is read
    tensorField P(F_.size());
    law_->stress(F_.primitiveField(), gradD_.primitiveField(), P);
    forAll(P, celli)
    {
        if (!std::isfinite(magSqr(P[celli])))
        {
            FatalErrorInFunction
                << "The stress of cell " << celli << " at "
                << mesh_.C()[celli] << " overflows for the initial F = "
                << F_[celli] << " read from "
                << F_.time().timeName()/"F" << " (law "
                << law_->type() << ')' << nl << exit(FatalError);
        }
    }

    const scalar stableCFL = update_->stableCFL(rungeKutta_.name());
    if (timeStep_.CFL() > stableCFL)
    {
        WarningInFunction
            << "Entry 'CFL' = " << timeStep_.CFL() << " in "
            << controls_.name() << " is above " << stableCFL
            << ", the largest CFL number at which FUpdate "
            << update_->type() << " with timeScheme " << rungeKutta_.name()
            << " was measured stable (validation/stabilityMap): the energy"
            << " may grow and cells invert" << endl;
    }
}


void Foam::touchSolid::checkInitialVelocity() const
{
    // The velocity of the cells next to a patch that fixes it: nonzero
    // there, the body starts with a jump at the patch (an impact on a
    // clamped face does; a mistaken set-up does too).  A velocity that
    // vanishes smoothly at the patch keeps a few per cent of its peak in
    // the adjacent cells of a coarse mesh (twisting column at 2 x 12 x 2
    // cells: 4.6 %), a body launched at the patch keeps all of it
    const scalar tolerance = 0.1;

    const scalarField rho(cellDensity(mesh_, *law_));
    const vectorField U(lm_.primitiveField()/rho);
    const scalar maxU = gMax(mag(U)());
    if (maxU <= 0)
    {
        return;
    }

    forAll(lm_.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = lm_.boundaryField()[patchi];
        const bool clamped = isA<clampedFvPatchVectorField>(pf);
        const bool symmetric = isA<symmetricPlaneFvPatchVectorField>(pf);
        if (!clamped && !symmetric)
        {
            continue;
        }

        const labelUList& cells = pf.patch().faceCells();
        const vectorField n(pf.patch().nf());
        scalar worst = 0;
        forAll(cells, facei)
        {
            const vector& v = U[cells[facei]];
            worst = max(worst, clamped ? mag(v) : mag(v & n[facei]));
        }
        reduce(worst, maxOp<scalar>());

        if (worst > tolerance*maxU)
        {
            WarningInFunction
                << "The initial velocity violates the "
                << (clamped ? "clamped" : "symmetricPlane") << " patch "
                << pf.patch().name() << ": its adjacent cells move at up to "
                << worst << " m/s" << (clamped ? "" : " normal to it")
                << ", " << worst/maxU << " of the largest |U| " << maxU
                << " m/s" << nl
                << "    The body starts with a velocity jump at the patch"
                << " (intended in an impact on a clamped face)" << endl;
        }
    }
}


void Foam::touchSolid::reportInvalidCell
(
    const label celli,
    const label stage,
    const scalar dt
) const
{
    // The reference centres of every rank's invalid cell (none: a rank
    // without one), known to all ranks: the nearest boundary face may lie
    // on another rank than the cell
    List<point> x0s(Pstream::nProcs(), point::max);
    if (celli >= 0)
    {
        x0s[Pstream::myProcNo()] = mesh_.C()[celli];
    }
    Pstream::gatherList(x0s);
    Pstream::scatterList(x0s);

    // The bodies: regions of cells connected through faces (across ranks).
    // Several (a bar and a ring meshed apart, two bodies that touch) make
    // 'which one' part of 'where'
    const regionSplit bodies(mesh_);

    word nearestPatch("none");
    scalar nearestDistance = GREAT;
    forAll(x0s, proci)
    {
        if (x0s[proci] == point::max)
        {
            continue;
        }

        // The boundary face nearest to the cell in the reference
        // configuration, over the faces of all ranks; the patches other
        // than processor ones are the same on every rank, in one order
        scalar distance = GREAT;
        label patchi = labelMax;
        for (const fvPatch& patch : mesh_.boundary())
        {
            if (patch.coupled() || isA<emptyFvPatch>(patch))
            {
                continue;
            }
            for (const point& c : patch.Cf())
            {
                const scalar d = mag(c - x0s[proci]);
                if (d < distance)
                {
                    distance = d;
                    patchi = patch.index();
                }
            }
        }
        const scalar least = returnReduce(distance, minOp<scalar>());
        const label nearest =
            returnReduce(distance == least ? patchi : labelMax, minOp<label>());

        if (proci == Pstream::myProcNo() && nearest < mesh_.boundary().size())
        {
            nearestPatch = mesh_.boundary()[nearest].name();
            nearestDistance = least;
        }
    }

    if (celli < 0)
    {
        return;
    }

    const point& x0 = mesh_.C()[celli];
    const tensor& F = F_[celli];
    const scalar t = mesh_.time().value();

    Pout<< "touchSolid: invalid cell " << celli << " (first on this rank)"
        << nl << "    current centre   " << x0 + D_[celli]
        << nl << "    reference centre " << x0
        << nl << "    J = det F        " << det(F)
        << nl << "    F                " << F
        << nl << "    |lm|             " << mag(lm_[celli])
        << nl << "    finite           "
        << (std::isfinite(det(F)) && std::isfinite(mag(lm_[celli]))
            ? "yes" : "no")
        << nl << "    step             " << t - dt << " -> " << t
        << " (dt = " << dt << ')'
        << nl << "    stage            " << stage << " of " << nStages()
        << " of " << rungeKutta_.name() << " (stage time "
        << t - dt + rungeKutta_.stageTime(stage)*dt << ')'
        << nl << "    nearest boundary " << nearestPatch << " ("
        << nearestDistance << " m from the reference centre)"
        << nl << "    body             " << bodies[celli] << " of "
        << bodies.nRegions() << " (regions of cells connected by faces)"
        << nl << "    law              " << law_->type();

    // The law's state in the cell, as the stage left it: the fields a law
    // with state writes with the time (vonMisesPlastic: epsilonP, CpInv;
    // a zoned law's several laws alike)
    if (law_->hasState())
    {
        Pout<< nl << "    law state       ";
        for (const word& name : mesh_.sortedNames<volScalarField>())
        {
            const volScalarField& f = mesh_.lookupObject<volScalarField>(name);
            if (f.writeOpt() == IOobject::AUTO_WRITE)
            {
                Pout<< ' ' << name << ' ' << f[celli];
            }
        }
        for (const word& name : mesh_.sortedNames<volSymmTensorField>())
        {
            const volSymmTensorField& f =
                mesh_.lookupObject<volSymmTensorField>(name);
            if (f.writeOpt() == IOobject::AUTO_WRITE)
            {
                Pout<< ' ' << name << ' ' << f[celli];
            }
        }
    }
    Pout<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::touchSolid::valid() const
{
    return returnReduce(firstInvalidCell() < 0, andOp<bool>());
}


// ************************************************************************* //
