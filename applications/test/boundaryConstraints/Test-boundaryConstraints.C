/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-boundaryConstraints

Description
    Checks that every solid boundary condition declares the kinematic
    constraint its flux obeys.  Each condition (every name of
    solidFluxFvPatchVectorField::types(); the ones with data with nonzero
    data, uniform and nonuniform) is constructed from a 0/lm entry on every
    patch of the test mesh and fed random interior states: random p, t,
    rho and Up > Us > 0, the spatial normal n = cof(F) N/|cof(F) N| of a
    random F (rotations included) and, separately, the reference normal
    n = N.  Over all of them the worst of
    - (I - free) (p^C/rho - velocity), relative to the momentum scale,
    - |free - free^T| and |free free - free| (a symmetric projector),
    - free velocity (nothing prescribed in the free directions)
    must be round-off (1e-12).  That the check can fail is checked too:
    wrong pairings (symmetricPlane's flux against clamped's constraint, ...)
    must violate it by far.  The rigid wall is set up through the middle
    of each patch with the random face positions x = C_f + (+-0.1) on
    both sides of it, fixed, moving and with a velocity table: both its
    faces in contact and its separated faces must have been met (it is
    checked).  The states are taken at random times in [0, 1 ms], the
    range of the tables (prescribedVelocity, traction, rigidWall) whose
    values then differ from state to state.  A registered condition without a test entry
    here is tested with 'type <name>;' alone, and fails if that is not
    enough to construct it.
    Exits non-zero on any wrong answer.

Usage
    Test-boundaryConstraints -case applications/test/case   (meshed)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "solidFluxFvPatchVectorField.H"
#include "transform.H"
#include "Random.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "testReport.H"

#include <functional>

using namespace Foam;


//- The states are taken at random times in [0, stageTimeRange] [s], the
//  range of the tables below (a moving wall moves by less than 1e-3 of
//  the face positions' spread)
static const scalar stageTimeRange = 1e-3;


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Round-off, relative to the momentum scale (or absolute, for the
//  projector, whose size is one)
const scalar tolerance = 1e-12;

//- A wrong pairing must violate the constraint by more than this
const scalar violation = 1e-2;

//- Random interior states per condition, patch and kind of normal
const label nStates = 200;


//- A vector with components uniform in (-scale/2, scale/2)
vector centred(Random& rnd, const scalar scale)
{
    return scale*(rnd.sample01<vector>() - 0.5*vector::one);
}


//- A random unit vector
vector unit(Random& rnd)
{
    vector v(Zero);
    while (mag(v) < 0.1)
    {
        v = centred(rnd, 2);
    }
    return v/mag(v);
}


//- A random deformation gradient: any rotation times a stretch and shear
//  of order one, det F > 0.1
tensor randomF(Random& rnd)
{
    tensor U(tensor::I);
    do
    {
        U = tensor::I + rnd.sample01<tensor>() - 0.5*tensor::one;
    } while (det(U) < 0.1);

    return rotationTensor(unit(rnd), unit(rnd)) & U;
}


//- The worst residuals of a flux against a constraint
struct residuals
{
    //- |(I - free) (p^C/rho - velocity)| rho / momentum scale
    scalar kinematic = 0;

    //- |free - free^T|
    scalar symmetry = 0;

    //- |free free - free|
    scalar idempotency = 0;

    //- |free velocity| rho / momentum scale
    scalar freeVelocity = 0;

    //- Faces met free in every direction, and with a fixed direction
    label nFree = 0;
    label nFixed = 0;

    void worst(const residuals& r)
    {
        kinematic = max(kinematic, r.kinematic);
        symmetry = max(symmetry, r.symmetry);
        idempotency = max(idempotency, r.idempotency);
        freeVelocity = max(freeVelocity, r.freeVelocity);
        nFree += r.nFree;
        nFixed += r.nFixed;
    }
};


//- The flux of fluxBC against the constraint of constraintBC (the same
//  condition, or a deliberately wrong one) over random interior states
residuals measure
(
    solidFluxFvPatchVectorField& fluxBC,
    solidFluxFvPatchVectorField& constraintBC,
    const bool spatialNormal,
    Random& rnd
)
{
    const fvPatch& patch = fluxBC.patch();
    const vectorField N(patch.nf());
    const label size = patch.size();

    vectorField p(size), t(size), n(size), x(size);
    vectorField pC(size), tC(size), velocity(size);
    tensorField free(size);

    residuals r;

    for (label statei = 0; statei < nStates; ++statei)
    {
        const scalar rho = 1000*(1 + 9*rnd.sample01<scalar>());
        const scalar Us = 100 + 2900*rnd.sample01<scalar>();
        const scalar Up = Us*(1.05 + 2*rnd.sample01<scalar>());

        forAll(p, facei)
        {
            // Velocities of order 1 m/s, stresses of the waves they make
            p[facei] = rho*centred(rnd, 2);
            t[facei] = rho*Up*centred(rnd, 2);

            if (spatialNormal)
            {
                const vector m(cof(randomF(rnd)) & N[facei]);
                n[facei] = m/mag(m);
            }
            else
            {
                n[facei] = N[facei];
            }

            x[facei] = patch.Cf()[facei] + centred(rnd, 0.2);
        }

        const scalarField rhoF(p.size(), rho);
        const scalarField UpF(p.size(), Up);
        const scalarField UsF(p.size(), Us);
        const solidFluxFvPatchVectorField::interiorState s
        {
            p, t, n, x, x, rhoF, UpF, UsF, rnd.position<label>(1, 3),
            stageTimeRange*rnd.sample01<scalar>()
        };

        // The active set first, as the solver does at each stage
        fluxBC.updateActiveSet(s);
        if (&constraintBC != &fluxBC)
        {
            constraintBC.updateActiveSet(s);
        }

        fluxBC.flux(s, pC, tC);
        constraintBC.constraint(s, free, velocity);

        const scalar scale =
            max(mag(p) + mag(t)/Us + mag(pC) + rho*mag(velocity));

        const tensorField fixed(tensor::I - free);

        residuals state;
        state.kinematic = max(mag(fixed & (pC/rho - velocity)))*rho/scale;
        state.symmetry = max(mag(free - free.T()));
        state.idempotency = max(mag((free & free) - free));
        state.freeVelocity = max(mag(free & velocity))*rho/scale;
        forAll(free, facei)
        {
            (mag(fixed[facei]) < tolerance ? state.nFree : state.nFixed) += 1;
        }

        r.worst(state);
    }

    return r;
}


//- A 0/lm entry from its text
dictionary lmEntry(const string& text)
{
    IStringStream is(text);
    return dictionary(is);
}


//- A rigid wall through the middle of a patch, its normal into the solid,
//  moving with the given velocity (the text of a Function1 of time)
dictionary rigidWallEntry(const fvPatch& patch, const string& velocity)
{
    const vector normal(-gSum(patch.Sf())/gSum(patch.magSf()));
    const vector point(gSum(patch.Cf()*patch.magSf())/gSum(patch.magSf()));

    OStringStream os;
    os  << "type rigidWall; point " << point << "; normal " << normal
        << "; velocity " << velocity.c_str() << ";";
    return lmEntry(os.str());
}


//- A tested set-up of a condition: its type, a label and its 0/lm entry on
//  a given patch
struct testCondition
{
    word type;
    string label;
    std::function<dictionary(const fvPatch&)> dict;
};


//- A condition constructed from its entry on a patch (null if that fails)
autoPtr<solidFluxFvPatchVectorField> construct
(
    const testCondition& c,
    const fvPatch& patch,
    const volVectorField& lm
)
{
    const bool throwing = FatalError.throwExceptions();
    const bool ioThrowing = FatalIOError.throwExceptions();

    autoPtr<solidFluxFvPatchVectorField> bc;
    try
    {
        tmp<fvPatchVectorField> tbc
        (
            fvPatchVectorField::New(patch, lm, c.dict(patch))
        );
        bc.reset
        (
            &refCast<solidFluxFvPatchVectorField>(*tbc.ptr())
        );
    }
    catch (const Foam::error& err)
    {
        Info<< "    " << c.label << " on " << patch.name()
            << ": construction failed: " << err.message().c_str() << nl;
    }

    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(ioThrowing);

    return bc;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    testReport report;
    Random rnd(11);

    // The internal field the conditions attach to; its own patches are not
    // used
    const volVectorField lm
    (
        IOobject
        (
            "lm",
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector("zero", dimensionSet(1, -2, -1, 0, 0), Zero)
    );

    auto fixedEntry = [](const string& text)
    {
        return [text](const fvPatch&) { return lmEntry(text); };
    };

    // Every condition with nonzero data, uniform and nonuniform
    List<testCondition> conditions
    ({
        {
            "symmetricPlane", "symmetricPlane",
            fixedEntry("type symmetricPlane;")
        },
        {
            "skewSymmetricPlane", "skewSymmetricPlane",
            fixedEntry("type skewSymmetricPlane;")
        },
        {
            "clamped", "clamped",
            fixedEntry("type clamped;")
        },
        {
            "prescribedVelocity", "prescribedVelocity (uniform)",
            fixedEntry("type prescribedVelocity; velocity uniform (1 -2 3);")
        },
        {
            "prescribedVelocity", "prescribedVelocity (nonuniform)",
            [&rnd](const fvPatch& patch)
            {
                vectorField velocity(patch.size());
                forAll(velocity, facei)
                {
                    velocity[facei] = centred(rnd, 6);
                }
                OStringStream os;
                os  << "type prescribedVelocity;" << nl;
                velocity.writeEntry("velocity", os);
                return lmEntry(os.str());
            }
        },
        {
            "traction", "traction (uniform, pressure)",
            fixedEntry
            (
                "type traction; traction uniform (1e5 -2e4 3e4);"
                " pressure uniform 5e4;"
            )
        },
        {
            "traction", "traction (nonuniform)",
            [&rnd](const fvPatch& patch)
            {
                vectorField traction(patch.size());
                scalarField pressure(patch.size());
                forAll(traction, facei)
                {
                    traction[facei] = centred(rnd, 2e6);
                    pressure[facei] = 1e6*(rnd.sample01<scalar>() - 0.5);
                }
                OStringStream os;
                os  << "type traction;" << nl;
                traction.writeEntry("traction", os);
                pressure.writeEntry("pressure", os);
                return lmEntry(os.str());
            }
        },
        {
            "traction", "traction (free surface)",
            fixedEntry("type traction;")
        },
        {
            "rigidWall", "rigidWall (fixed)",
            [](const fvPatch& patch)
            {
                return rigidWallEntry(patch, "(0 0 0)");
            }
        },
        {
            "rigidWall", "rigidWall (moving)",
            [](const fvPatch& patch)
            {
                return rigidWallEntry(patch, "(0.3 -0.7 1.1)");
            }
        },
        {
            "prescribedVelocity", "prescribedVelocity (table)",
            fixedEntry
            (
                "type prescribedVelocity;"
                " velocity table ((0 (0 0 0)) (1e-3 (1 -2 3)));"
            )
        },
        {
            "traction", "traction (table)",
            fixedEntry
            (
                "type traction;"
                " traction table ((0 (0 0 0)) (1e-3 (1e5 -2e4 3e4)));"
                " pressure table ((0 0) (1e-3 5e4));"
            )
        },
        {
            "rigidWall", "rigidWall (table)",
            [](const fvPatch& patch)
            {
                return rigidWallEntry
                (
                    patch, "table ((0 (0 0 0)) (1e-3 (0.3 -0.7 1.1)))"
                );
            }
        }
    });

    // Every registered condition is tested: the ones above must be
    // registered, any other with its type alone
    const wordList types(solidFluxFvPatchVectorField::types());
    Info<< "Solid boundary conditions: " << types << nl;

    wordHashSet tested;
    for (const testCondition& c : conditions)
    {
        tested.insert(c.type);
    }
    for (const word& type : tested.sortedToc())
    {
        report.check
        (
            type + " is registered as a solid boundary condition",
            types.found(type)
        );
    }
    for (const word& type : types)
    {
        if (!tested.found(type))
        {
            Info<< "    " << type << ": no test entry, tested with 'type "
                << type << ";' alone" << nl;
            conditions.append({type, type, fixedEntry("type " + type + ";")});
        }
    }


    // Each condition against its own constraint
    Info<< nl << "Worst residuals over " << mesh.boundary().size()
        << " patches x " << nStates << " random interior states:" << nl;

    for (const testCondition& c : conditions)
    {
        for (const bool spatialNormal : {true, false})
        {
            const string what
            (
                c.label
              + (spatialNormal ? ", n = cof(F) N" : ", n = N") + ": "
            );

            residuals worst;
            bool constructed = true;

            forAll(mesh.boundary(), patchi)
            {
                autoPtr<solidFluxFvPatchVectorField> bc
                (
                    construct(c, mesh.boundary()[patchi], lm)
                );
                if (!bc)
                {
                    constructed = false;
                    break;
                }
                worst.worst(measure(*bc, *bc, spatialNormal, rnd));
            }

            if (!constructed)
            {
                report.check
                (
                    what + "constructed from its test entry (give it one "
                    "in Test-boundaryConstraints)",
                    false
                );
                break;
            }

            report.check
            (
                what + "(I - free)(pC/rho - velocity) = 0",
                worst.kinematic,
                tolerance
            );
            report.check(what + "free symmetric", worst.symmetry, tolerance);
            report.check
            (
                what + "free idempotent",
                worst.idempotency,
                tolerance
            );
            report.check
            (
                what + "free & velocity = 0",
                worst.freeVelocity,
                tolerance
            );
            if (c.type == "rigidWall")
            {
                report.check
                (
                    what + "switches (" + Foam::name(worst.nFixed)
                  + " faces met in contact, " + Foam::name(worst.nFree)
                  + " separated)",
                    worst.nFixed > 0 && worst.nFree > 0
                );
            }
        }
    }


    // The check can fail: a flux against another condition's constraint
    Info<< nl << "Wrong pairings (flux against constraint) must violate the"
        << " constraint by more than " << violation << ":" << nl;

    const Pair<string> wrongPairs[] =
    {
        {"symmetricPlane", "clamped"},
        {"skewSymmetricPlane", "symmetricPlane"},
        {"prescribedVelocity (nonuniform)", "prescribedVelocity (uniform)"},
        {"prescribedVelocity (table)", "prescribedVelocity (uniform)"},
        {"traction (uniform, pressure)", "clamped"},
        {"rigidWall (moving)", "symmetricPlane"},
        {"traction (free surface)", "rigidWall (moving)"},
        {"rigidWall (fixed)", "rigidWall (moving)"}
    };

    auto labelled = [&conditions](const string& label) -> const testCondition&
    {
        for (const testCondition& c : conditions)
        {
            if (c.label == label)
            {
                return c;
            }
        }
        FatalErrorInFunction
            << "No test condition " << label << exit(FatalError);
        return conditions[0];
    };

    for (const Pair<string>& pair : wrongPairs)
    {
        const testCondition& fluxC = labelled(pair.first());
        const testCondition& constraintC = labelled(pair.second());
        const fvPatch& patch = mesh.boundary()[0];

        autoPtr<solidFluxFvPatchVectorField> fluxBC
        (
            construct(fluxC, patch, lm)
        );
        autoPtr<solidFluxFvPatchVectorField> constraintBC
        (
            construct(constraintC, patch, lm)
        );

        if (!fluxBC || !constraintBC)
        {
            report.check
            (
                fluxC.label + " flux against " + constraintC.label
              + " constraint: both constructed",
                false
            );
            continue;
        }

        const scalar measured =
            measure(*fluxBC, *constraintBC, true, rnd).kinematic;

        report.check
        (
            fluxC.label + " flux against " + constraintC.label
          + " constraint: violation " + Foam::name(measured) + " detected",
            measured > violation
        );
    }

    // Exit here: the status must not be lost in argList's destructor
    Pstream::exit(report.result("Test-boundaryConstraints"));

    return 0;
}


// ************************************************************************* //
