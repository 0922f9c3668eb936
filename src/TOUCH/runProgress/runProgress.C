/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "runProgress.H"
#include "declaredEntry.H"
#include "touchSolid.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- x to n significant digits: a rate is known to a few digits only
static scalar significant(const scalar x, const int n)
{
    if (x == 0 || !std::isfinite(x))
    {
        return x;
    }

    const scalar scale =
        std::pow(10.0, n - 1 - std::floor(std::log10(std::abs(x))));

    return std::round(x*scale)/scale;
}


//- Seconds of wall time to the hundredth
static scalar seconds(const scalar t)
{
    return std::round(100*t)/100;
}


//- Six significant digits on the log while in scope: its precision is the
//  controlDict's writePrecision, 12 in the tutorials, which would double
//  the length of a progress line for digits that are noise
class logPrecision
{
    OSstream& os_;
    const int old_;

public:

    logPrecision()
    :
        os_(Info),
        old_(os_.precision(6))
    {}

    ~logPrecision()
    {
        os_.precision(old_);
    }
};

} // End namespace Foam


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<scalar> progressIntervalEntry
    (
        "system/controlDict", "progressInterval",
        "seconds of wall time between the log's progress lines (0: a line"
        " every step)",
        "s", 10, entryLimits::between(0, GREAT, true, false)
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::runProgress::readInterval(const Time& runTime)
{
    const dictionary& dict = runTime.controlDict();
    return progressIntervalEntry.read(dict);
}


Foam::scalar Foam::runProgress::remaining(const scalar wall) const
{
    const scalar t = runTime_.value();

    // Wall time per simulated time since the end of the first step, which
    // also paid for the start-up; the present step would be a worse guide:
    // on the twisting column it swings by +-15 % with the twist, and the
    // estimate from it was 22 % short at 62 % of the run
    const scalar wallPerTime =
        steps_ > 1
      ? (wall - firstStepWall_)/max(t - firstStepTime_, VSMALL)
      : wall/max(t - startTime_, VSMALL);

    scalar left =
        wallPerTime*max(runTime_.endTime().value() - t, scalar(0));

    if (maxSteps_ > 0)
    {
        const scalar wallPerStep =
            steps_ > 1 ? (wall - firstStepWall_)/(steps_ - 1) : wall;

        left = min(left, wallPerStep*(maxSteps_ - steps_));
    }

    return left;
}


void Foam::runProgress::writeLine(const scalar wall) const
{
    // Global sums: every rank computes them, the master writes
    const scalar energy = solid_.kineticEnergy() + solid_.strainEnergy();
    const vector p(solid_.totalLinearMomentum());
    const vector L(solid_.totalAngularMomentum());
    const scalar left = remaining(wall);

    const logPrecision precision;
    const scalar endTime = runTime_.endTime().value();
    const scalar sinceLast = wall - lastWall_;
    const scalar rate =
        scalar(nCells_)*(steps_ - lastSteps_)/max(sinceLast, VSMALL);

    Info<< "Progress: t " << runTime_.timeName() << " ("
        << std::round(1000*runTime_.value()/endTime)/10
        << " % of endTime " << endTime << "), step " << steps_
        << ", dt " << runTime_.deltaTValue()
        << ", wall " << seconds(wall) << " s, remaining " << seconds(left)
        << " s, " << significant(rate, 3) << " cell-steps/s (last "
        << seconds(sinceLast) << " s), energy " << energy
        << ", p " << p << ", L " << L << nl << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::runProgress::runProgress
(
    const fvMesh& mesh,
    const touchSolid& solid,
    const label maxSteps
)
:
    runTime_(mesh.time()),
    solid_(solid),
    maxSteps_(maxSteps),
    interval_(readInterval(runTime_)),
    nCells_(returnReduce(mesh.nCells(), sumOp<label>())),
    clock_(),
    startTime_(runTime_.value()),
    steps_(0),
    firstStepWall_(0),
    firstStepTime_(startTime_),
    lastWall_(0),
    lastSteps_(0)
{
    const scalar dt = solid_.stableDeltaT();
    const scalar endTime = runTime_.endTime().value();
    const scalar toGo = max(endTime - runTime_.value(), scalar(0));

    const logPrecision precision;

    Info<< "Run summary" << nl
        << "    cells           " << nCells_ << nl;

    solid_.writeSummary(Info);

    Info<< "    first dt        " << dt << " (the stable step at t = "
        << runTime_.timeName() << "; " << label(std::ceil(toGo/dt))
        << " such steps to endTime " << endTime;

    if (maxSteps_ > 0)
    {
        Info<< "; maxSteps " << maxSteps_;
    }

    Info<< ')' << nl
        << "    progress        a line every " << interval_
        << " s of wall time (controlDict progressInterval)" << nl << endl;

    clock_.resetTime();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::runProgress::step()
{
    ++steps_;

    // The master's clock for every rank: whether a line is due must be
    // decided alike, its totals are global sums
    scalar wall = clock_.elapsedTime();
    Pstream::scatter(wall);

    if (steps_ == 1)
    {
        firstStepWall_ = wall;
        firstStepTime_ = runTime_.value();
    }

    // The last step (endTime or maxSteps, which moves endTime to the
    // present time) has the final line instead
    const bool last =
        runTime_.value()
     >= runTime_.endTime().value() - 0.5*runTime_.deltaTValue();

    if (wall - lastWall_ >= interval_ && !last)
    {
        writeLine(wall);
        lastWall_ = wall;
        lastSteps_ = steps_;
    }
}


void Foam::runProgress::end() const
{
    const scalar wall = clock_.elapsedTime();

    const logPrecision precision;

    Info<< "Time loop: " << steps_ << " steps of " << nCells_
        << " cells in " << seconds(wall) << " s, "
        << significant(scalar(nCells_)*steps_/max(wall, VSMALL), 4)
        << " cell-steps/s" << nl << endl;
}


// ************************************************************************* //
