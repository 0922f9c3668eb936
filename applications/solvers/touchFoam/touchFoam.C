/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    touchFoam

Group
    grpSolidSolvers

Description
    Explicit large-strain solid dynamics with the TOUCH scheme: a Total
    Lagrangian Upwind Cell-centred finite volume method for the first-order
    system in linear momentum p and deformation gradient F, advanced by the
    two-stage TVD Runge-Kutta method at the CFL time step (Haider, Lee, Gil,
    Bonet, IJNME 109 (2017) 407-456).

    Reads the velocity 0/U [m/s] or the linear momentum 0/lm (lm when both
    exist and agree: a restart), which carries the boundary conditions,
    optionally 0/F, constant/mechanicalProperties and the TOUCH entries of
    system/fvSolution.  Writes the state lm, F, D (cell displacement) and
    pointD (point displacement), and U, P, sigma, sigmaEq, pressure, J and,
    with a rigidWall patch, contact (touchSolid).

    A run that produces an inverted cell or a non-finite value stops with a
    message naming the cell, its position, J, the law's state, the nearest
    boundary and body, the time, the Runge-Kutta stage and dt, after
    writing the last good state (the law's state included) to a time folder
    of its own (never overwriting one).  A run killed at any moment
    restarts (startFrom latestTime) from the latest complete time folder:
    an incomplete one is moved to <time>.incomplete.  The optional controlDict
    entry maxSteps stops (and writes) after that many steps.

    The log starts with a summary of the run, has a progress line (time,
    step, wall time, estimated remaining time, cell-steps/s, energy and
    momenta) every controlDict progressInterval seconds of wall time
    (default 10; 0: every step) besides the per-step time lines, and ends
    with the steps, wall time and cell-steps/s of the time loop
    (runProgress).

Usage
    touchFoam [-parallel] [-case dir]
    touchFoam -listEntries [-markdown]   (every entry it reads, and exit)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "touchSolid.H"
#include "runProgress.H"
#include "declaredEntry.H"
#include "sigFpe.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<label> maxStepsEntry
    (
        "system/controlDict", "maxSteps",
        "stop (and write) after this many steps (-1: no limit)",
        "-", -1, entryLimits::above(-1, true)
    );
}

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Whether the field file exists (compressed or not) and was written to
//  its end: its last non-blank line is OpenFOAM's closing divider
//  '// ***...*** //', which every field file ends with, ascii or binary
static bool completeFile(const fileName& path)
{
    if (!isFile(path))
    {
        return false;
    }

    IFstream is(path);
    if (!is.good())
    {
        return false;
    }

    std::string line;
    std::string last;
    while (is.good())
    {
        is.getLine(line);
        if (line.find_first_not_of(" \t\r") != std::string::npos)
        {
            last = line;
        }
    }

    return last.compare(0, 8, "// *****") == 0
        && last.find(" //", 8) != std::string::npos;
}


//- The step dt shortened (or lengthened, up to twice) to land on the next
//  write time of writeControl adjustableRunTime, as OpenFOAM's Time does,
//  but counting the write times from t = 0, not from the run's start time:
//  OpenFOAM's time to the next write, (index + 1) interval - (t - start),
//  rounds otherwise after a restart than in the uninterrupted run, and the
//  restarted run's steps then differ in the last bit (measured on the bar
//  rebound tutorial: lm 2.6e-15 off at 50 us after a restart at 30 us).
//  writeIndex is the index of the latest write time reached.
static scalar stepToWrites
(
    const Time& runTime,
    const scalar dt,
    const label writeIndex
)
{
    const scalar interval =
        runTime.controlDict().get<scalar>("writeInterval");
    // The product rounded before the difference, as in OpenFOAM's library
    // (built without fused multiply-add; -march=native would fuse them)
    const volatile scalar nextWrite = (writeIndex + 1)*interval;
    const scalar toNextWrite = max(scalar(0), nextWrite - runTime.value());

    const scalar nSteps = toNextWrite/dt;
    if (!(nSteps < scalar(labelMax)))
    {
        return dt;
    }

    const scalar newDt = toNextWrite/max(label(1), label(std::round(nSteps)));

    return newDt >= dt ? min(newDt, 2*dt) : max(newDt, 0.2*dt);
}


//- The index of the latest write time of adjustableRunTime that a step of
//  dt ending at runTime's time reached, counted from t = 0 (a time within
//  half a step of a write time is that write time, as in OpenFOAM)
static label reachedWriteIndex(const Time& runTime, const scalar dt)
{
    const scalar interval =
        runTime.controlDict().get<scalar>("writeInterval");
    return label((runTime.value() + 0.5*dt)/interval);
}


} // End namespace Foam


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit large-strain solid dynamics with the TOUCH scheme"
    );

    argList::addBoolOption
    (
        "listEntries",
        "print every dictionary entry touchFoam reads (where, meaning, unit,"
        " default or example, valid values) and exit"
    );
    argList::addBoolOption
    (
        "markdown",
        "with -listEntries: write the list as the Markdown page"
        " doc/entries.md"
    );

    // -listEntries needs no case: answer it before the case is checked,
    // without the banner (its output is a page of its own)
    for (int argi = 1; argi < argc; ++argi)
    {
        if (std::string(argv[argi]) == "-listEntries")
        {
            argList::noBanner();
            argList::noJobInfo();
        }
    }
    Foam::argList args(argc, argv);
    if (args.found("listEntries"))
    {
        if (args.found("markdown"))
        {
            entryDeclaration::writeMarkdown(Info);
        }
        else
        {
            entryDeclaration::writeText(Info);
        }
        return 0;
    }
    if (!args.checkRootCase())
    {
        Foam::FatalError.exit();
    }
    #include "foamDlOpenLibs.H"

    // While the input is read, a number that overflows (1e999 in a field
    // or dictionary) is inf, not a floating-point trap inside OpenFOAM's
    // parser: the checks of the entries and of the initial state name it
    sigFpe::ignore readingInput;

    // A run killed while writing leaves its last time folder cut short:
    // touchFoam writes the state (lm, F, D, pointD, the law's state) first
    // and the fields for viewing after it, U last, every file ending with
    // OpenFOAM's closing divider line.  Before the run's Time selects the
    // latest folder, set aside (rename to <time>.incomplete) every latest
    // folder that is incomplete on some rank, saying so: the run starts
    // from the latest complete one and writes the time again when it gets
    // there.  Complete: U ends with the divider, or (no U: a folder made
    // or edited by hand) lm, F, D and pointD all do, or the folder holds
    // lm but no uniform/time (no run wrote it)
    {
        Foam::Time probe
        (
            Foam::Time::controlDictName,
            args.rootPath(),
            args.caseName(),
            "system",
            "constant",
            false,
            false
        );
        auto holdsState = [&](const word& timeName)
        {
            const fileName dir(probe.path()/timeName);
            bool complete = false;
            if (isFile(dir/"U"))
            {
                complete = completeFile(dir/"U");
            }
            else if (isFile(dir/"lm"))
            {
                // A run writes uniform/time before the fields: with it, a
                // folder without U is complete if its state is; without
                // it, the folder was made by hand, and the checks of the
                // fields read judge it
                // (D and pointD, or their former names u and pointU)
                complete =
                    !isFile(dir/"uniform"/"time")
                 || (
                        completeFile(dir/"lm") && completeFile(dir/"F")
                     && (completeFile(dir/"D") || completeFile(dir/"u"))
                     && (
                            completeFile(dir/"pointD")
                         || completeFile(dir/"pointU")
                        )
                    );
            }
            return returnReduce(complete, andOp<bool>());
        };

        for (instantList times(probe.times()); times.size(); )
        {
            const instant& latest = times.last();
            if
            (
                latest.value() <= 0
             || latest.name() != probe.timeName()
             || holdsState(latest.name())
            )
            {
                break;
            }

            const fileName cut(probe.path()/latest.name());
            const fileName aside(cut + ".incomplete");
            rmDir(aside);
            mv(cut, aside);

            WarningInFunction
                << "Time folder " << latest.name() << " is incomplete: its"
                << " U, written last, is missing or cut short (a run"
                << " stopped while writing it). Moved to " << aside.name()
                << "; the run starts from the latest complete time folder"
                << endl;

            times = probe.times();
            if (times.size())
            {
                probe.setTime(times.last(), 0);
            }
        }
    }

    #include "createTime.H"
    #include "createMesh.H"

    // A restart continues from the exact time of the run that wrote it:
    // the time folder's name is rounded to timePrecision, its
    // uniform/time value is not (OpenFOAM takes the name when they agree
    // to that precision, and a restarted run's times then drift from the
    // uninterrupted one's by up to half a unit of the last digit)
    {
        IOdictionary timeDict
        (
            IOobject
            (
                "time",
                runTime.timeName(),
                "uniform",
                runTime,
                IOobject::READ_IF_PRESENT,
                IOobject::NO_WRITE,
                false
            )
        );

        scalar storedValue = 0;
        if (timeDict.readIfPresent("value", storedValue))
        {
            runTime.setTime(storedValue, runTime.timeIndex());
        }

        // And with the dt of the last step taken, whatever adjustTimeStep
        // says: OpenFOAM restores it only with adjustTimeStep and
        // otherwise judges the end (run(): t < endTime - dt/2) and the
        // write index with the controlDict's deltaT, so a run restarted
        // within half a step of its end took one step more than the
        // uninterrupted run (test killRestart)
        scalar lastDt = 0;
        if (timeDict.readIfPresent("deltaT", lastDt) && lastDt > 0)
        {
            runTime.setDeltaT(lastDt, false);
        }
    }

    // An entry of controlDict neither OpenFOAM's Time nor touchFoam reads
    // (maxCo, adjustTimeStep of a fluid solver, a misspelt one): OpenFOAM
    // ignores it; say so, naming the nearest valid one
    entryDeclaration::checkEntries
    (
        runTime.controlDict(),
        "system/controlDict",
        {
            "application", "startFrom", "startTime", "stopAt", "endTime",
            "deltaT", "writeControl", "writeInterval", "purgeWrite",
            "secondaryWriteControl", "secondaryWriteInterval",
            "secondaryPurgeWrite", "writeFormat", "writeVersion",
            "writeCompression", "writePrecision", "timeFormat",
            "timePrecision", "graphFormat", "runTimeModifiable", "libs",
            "functions", "DebugSwitches", "InfoSwitches",
            "OptimisationSwitches", "DimensionedConstants", "DimensionSets",
            "fileHandler"
        },
        false
    );

    // A decomposed case runs on as many ranks as it has processor folders:
    // OpenFOAM itself accepts stale extra folders (ignored) and, when the
    // decomposeParDict was changed, a decomposition for more ranks than
    // run, whose processor patches name ranks that do not exist
    if (Pstream::parRun())
    {
        label nFolders = 0;
        if (Pstream::master())
        {
            const fileNameList dirs
            (
                readDir(runTime.globalPath(), fileName::DIRECTORY)
            );
            for (const fileName& dir : dirs)
            {
                const std::string name(dir);
                if
                (
                    name.size() > 9 && name.compare(0, 9, "processor") == 0
                 && name.find_first_not_of("0123456789", 9)
                 == std::string::npos
                )
                {
                    ++nFolders;
                }
            }
        }
        Pstream::scatter(nFolders);

        if (nFolders != Pstream::nProcs())
        {
            FatalErrorInFunction
                << "The case " << runTime.globalPath() << " has " << nFolders
                << " processor folders (processor0 ...) but runs on "
                << Pstream::nProcs() << " ranks: decompose it again for "
                << Pstream::nProcs() << " (decomposePar -force) or run on "
                << nFolders << nl << exit(FatalError);
        }
    }

    // Before the fields are read: a patch type the solid cannot use is
    // named with what to use instead
    touchSolid::checkPatchTypes(mesh);

    touchSolid solid(mesh);

    const label maxSteps = maxStepsEntry.read(runTime.controlDict());

    if (!solid.valid())
    {
        FatalErrorInFunction
            << "The initial state at time " << runTime.timeName()
            << " has an inverted cell (det F <= 0) or a non-finite value"
            << " (in lm, F or an input that overflowed)" << nl
            << exit(FatalError);
    }

    readingInput.restore();

    // A run stopped after the state of its last write time and before the
    // fields for viewing (U last) leaves that folder without them; the
    // restart from it writes them, from the state read
    if
    (
        runTime.value() > 0
     && returnReduce(!isFile(runTime.timePath()/"U"), orOp<bool>())
    )
    {
        Info<< "Time folder " << runTime.timeName() << " holds the state but"
            << " not U (a run stopped while writing it): writing U and the"
            << " other fields for viewing there" << nl << endl;
        solid.prepareWrite();
        solid.writeOutputFields();
    }

    // The state a restart reads (lm, F, gradD, D, pointD, the law's state: the
    // objects that write themselves with the time) is written with at
    // least 17 significant digits whatever writePrecision says, so that a
    // restart continues exactly; the fields written for viewing (U, J,
    // sigma, ...) keep writePrecision (read again with the controlDict)
    const unsigned int statePrecision = 17;

    runProgress progress(mesh, solid, maxSteps);

    // The steps of writeControl adjustableRunTime land on the write times
    // counted from t = 0, whatever time the run starts from (a restart
    // takes the steps of the uninterrupted run, bit for bit); the write
    // index of the start from the last step's dt (uniform/time)
    const bool adjustableWrites =
        runTime.controlDict().get<word>("writeControl") == "adjustableRunTime";
    label writeIndex =
        adjustableWrites && runTime.value() > 0
      ? reachedWriteIndex(runTime, runTime.deltaTValue())
      : 0;

    Info<< "Starting time loop\n" << endl;

    for (label step = 1; runTime.run(); ++step)
    {
        if (adjustableWrites)
        {
            runTime.setDeltaT
            (
                stepToWrites(runTime, solid.stableDeltaT(), writeIndex),
                false
            );
        }
        else
        {
            runTime.setDeltaT(solid.stableDeltaT());
        }
        ++runTime;
        if (adjustableWrites)
        {
            writeIndex = max
            (
                writeIndex, reachedWriteIndex(runTime, runTime.deltaTValue())
            );
        }
        const scalar dt = runTime.deltaTValue();

        Info<< "Time = " << runTime.timeName() << "  deltaT = " << dt << nl;

        if (!solid.advance(dt))
        {
            // The state of the step's start is restored: write it, unless
            // its time folder exists (the start time, or a write time of
            // this run holding the same state): never overwrite one
            runTime.setTime(runTime.value() - dt, runTime.timeIndex() - 1);
            const bool written = isDir(runTime.timePath());
            if (!written)
            {
                const unsigned int viewPrecision =
                    IOstream::defaultPrecision();
                solid.prepareWrite();
                IOstream::defaultPrecision(max(viewPrecision, statePrecision));
                runTime.writeNow();
                IOstream::defaultPrecision(viewPrecision);
                solid.writeOutputFields();
            }

            FatalErrorInFunction
                << "Inverted cell (det F <= 0) or non-finite value during"
                << " the step " << runTime.value() << " -> "
                << runTime.value() + dt << " (dt = " << dt << "; the cell,"
                << " its position, J and the Runge-Kutta stage are named"
                << " above)" << nl
                << "    The last good state is "
                << (written ? "the existing time folder " : "written at time ")
                << runTime.timeName() << nl
                << exit(FatalError);
        }

        const unsigned int viewPrecision = IOstream::defaultPrecision();

        // The state first, then the fields for viewing with U last: a
        // folder whose U is complete holds a complete state (the check
        // of the latest folder above)
        const bool writing = step == maxSteps || runTime.writeTime();
        if (writing)
        {
            solid.prepareWrite();
        }

        IOstream::defaultPrecision(max(viewPrecision, statePrecision));
        if (step == maxSteps)
        {
            Info<< "Reached maxSteps " << maxSteps << nl;
            runTime.writeAndEnd();
        }
        else
        {
            runTime.write();
        }
        IOstream::defaultPrecision(viewPrecision);

        if (writing)
        {
            solid.writeOutputFields();
        }

        runTime.printExecutionTime(Info);

        progress.step();
    }

    progress.end();

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
