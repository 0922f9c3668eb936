/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
#include "declaredEntry.H"
#include "modelCoeffs.H"
#include "emptyFvPatch.H"
#include "calculatedFvPatchFields.H"
#include "calculatedPointPatchFields.H"
#include "Switch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(touchSolid, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- IOobject of a field of the solid at the present time
static IOobject fieldIO
(
    const fvMesh& mesh,
    const word& name,
    const IOobject::readOption read,
    const IOobject::writeOption write
)
{
    return IOobject(name, mesh.time().timeName(), mesh, read, write);
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<Switch> angularMomentumEntry
    (
        "system/fvSolution TOUCH", "angularMomentumPreservation",
        "correct the momentum rate so that the total angular momentum"
        " follows the boundary torques exactly (free bodies)",
        "-", Switch(Switch::ON), entryLimits::any(),
        declaredEntry<Switch>::required
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField> Foam::touchSolid::cellPositions
(
    const vectorField& D
) const
{
    return mesh_.C().primitiveField() + D;
}


void Foam::touchSolid::computeRates(const label stage)
{
    // Neighbour values across processor patches, then the stress and the
    // limited gradients (exchanged as well)
    lm_.correctBoundaryConditions();
    F_.correctBoundaryConditions();
    if (preserveAngularMomentum_)
    {
        // The cell positions across processor faces (the rigid spin)
        D_.correctBoundaryConditions();
    }
    law_->correct(F_, gradD_.primitiveField(), P_);
    if (nodalAveraging_)
    {
        nodalAveraging_->correct
        (
            *law_, F_.primitiveField(), P_.primitiveFieldRef()
        );
        P_.correctBoundaryConditions();
    }
    update_->reconstruct(reconstruction_, lm_, P_);
    faces_.update();

    lmRate_ = Zero;
    FRate_ = Zero;
    torque_ = Zero;

    if (preserveAngularMomentum_)
    {
        // The body's spin, with which the update turns the points' drift
        // and which its upwinding leaves alone
        update_->setRigidSpin
        (
            angularMomentum_.spin
            (
                cellPositions(D_.primitiveField()), lm_.primitiveField()
            ),
            pointD_.primitiveField()
        );
    }

    // The time of the stage's state: the mesh's time is the step's end
    // (advanced before the stages)
    const Time& time = mesh_.time();
    const scalar c = rungeKutta_.stageTime(stage);
    faces_.setStageTime
    (
        c == 1
      ? time.value()
      : time.value() - time.deltaTValue() + c*time.deltaTValue()
    );

    update_->rates(stage, lmRate_, FRate_, pointV_.primitiveFieldRef(), torque_);
    if (gravity_)
    {
        gravity_->addRates
        (
            cellPositions(D_.primitiveField()), lmRate_, torque_
        );
    }

    reduce(torque_, sumOp<vector>());

    if (preserveAngularMomentum_)
    {
        power_ = returnReduce(update_->boundaryPower(), sumOp<scalar>());
    }

    if (debug)
    {
        // The semi-discrete energy balance: the compatible update's rate is
        // the upwind dissipation plus the work of prescribed motion and
        // tractions
        const scalarField rho(law_->cellRho());
        const scalar kinetic =
            gSum((lm_.primitiveField() & lmRate_)/rho);
        const scalar stored = gSum(P_.primitiveField() && FRate_);

        Info<< "touchSolid: stage " << stage << " energy rate: kinetic "
            << kinetic << ", stored " << stored << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::touchSolid::touchSolid(const fvMesh& mesh)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    mesh_(mesh),
    controls_(readControls(mesh)),
    law_(mechanicalLaw::New(mesh)),
    riemann_(riemannSolver::New(controls_, *law_)),
    gravity_(gravity::New(mesh, cellDensity(mesh, *law_))),
    angularMomentum_(mesh),
    preserveAngularMomentum_
    (
        angularMomentumEntry.read(controls_)
    ),
    nodalAveraging_(nodalAveraging::New(mesh, controls_, *law_)),
    rungeKutta_(controls_),
    lm_
    (
        fieldIO(mesh, "lm", IOobject::NO_READ, IOobject::AUTO_WRITE),
        initialMomentum(mesh, *law_)
    ),
    F_
    (
        fieldIO(mesh, "F", IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        mesh,
        dimensionedTensor("I", dimless, tensor::I),
        calculatedFvPatchTensorField::typeName
    ),
    gradD_
    (
        fieldIO(mesh, "gradD", IOobject::NO_READ, IOobject::AUTO_WRITE),
        F_ - dimensionedTensor("I", dimless, tensor::I)
    ),
    D_
    (
        fieldIO(mesh, "D", IOobject::NO_READ, IOobject::AUTO_WRITE),
        readDisplacement<volVectorField>(mesh, "D", "u")
    ),
    pointD_
    (
        fieldIO(mesh, "pointD", IOobject::NO_READ, IOobject::AUTO_WRITE),
        readDisplacement<pointVectorField>
        (
            pointMesh::New(mesh), "pointD", "pointU"
        )
    ),
    P_
    (
        fieldIO(mesh, "P", IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedTensor("0", dimPressure, Zero),
        calculatedFvPatchTensorField::typeName
    ),
    pointV_
    (
        fieldIO(mesh, "pointV", IOobject::NO_READ, IOobject::NO_WRITE),
        pointMesh::New(mesh),
        dimensionedVector("0", dimVelocity, Zero),
        calculatedPointPatchVectorField::typeName
    ),
    mirrorPlanes_(readMirrorPlanes(controls_)),
    reconstruction_(mesh, controls_, mirrorPatches(lm_, mirrorPlanes_)),
    faces_(mesh, reconstruction_, lm_, F_, P_, D_, pointD_),
    update_
    (
        deformationUpdate::New(controls_, faces_, *law_, *riemann_, reconstruction_)
    ),
    timeStep_(controls_, faces_, *law_),
    lm0_(mesh.nCells()),
    gradD0_(mesh.nCells()),
    D0_(mesh.nCells()),
    pointD0_(mesh.nPoints()),
    lmRate_(mesh.nCells()),
    FRate_(mesh.nCells()),
    inverseVolumes_(1/mesh.V().field()),
    invalidCell_(-1),
    torque_(Zero),
    power_(0),
    L0_(Zero),
    Lstage_(Zero),
    E0_(0),
    Estage_(0),
    boundaryWork_(nullptr)
{
    checkTwoD();
    initialiseDisplacementGradient();

    // The correction's inertia and energy are those of one density
    if (preserveAngularMomentum_ && !law_->uniformMaterial())
    {
        FatalIOErrorInFunction(controls_)
            << "Entry '" << angularMomentumEntry.name() << "' on with"
            << " several materials ('materials' in constant/"
            << "mechanicalProperties): the preservation assumes one density;"
            << " set " << angularMomentumEntry.name() << " off"
            << exit(FatalIOError);
    }

    checkInput();
    update_->setNodalAveraging(nodalAveraging_.get(), controls_);

    if (mesh.time().value() == 0)
    {
        checkInitialVelocity();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::touchSolid::stableDeltaT() const
{
    return timeStep_.deltaT(F_);
}


bool Foam::touchSolid::advance(const scalar dt)
{
    storeOldTime();

    for (label stage = 1; stage <= nStages(); ++stage)
    {
        advanceStage(stage, dt);

        // Every rank restores, so that all of them retry the step alike
        if (!returnReduce(invalidCell_ < 0, andOp<bool>()))
        {
            // Every rank takes part (the nearest boundary and the body
            // are searched across ranks); the ranks with a cell report
            reportInvalidCell(invalidCell_, stage, dt);

            restoreOldTime();
            return false;
        }
    }

    law_->commitStep(F_);

    return true;
}


void Foam::touchSolid::storeOldTime()
{
    lm0_ = lm_.primitiveField();
    gradD0_ = gradD_.primitiveField();
    D0_ = D_.primitiveField();
    pointD0_ = pointD_.primitiveField();
    law_->storeOldTime();
    if (boundaryWork_)
    {
        boundaryWork_->storeOldTime();
    }

    if (preserveAngularMomentum_)
    {
        L0_ = angularMomentum_.total(cellPositions(D0_), lm0_);
        Lstage_ = L0_;
        E0_ = kineticEnergy() + strainEnergy() + potentialEnergy();
        Estage_ = E0_;
    }
}


void Foam::touchSolid::advanceStage(const label stage, const scalar dt)
{
    computeRates(stage);

    // Stage k of the SSP Runge-Kutta scheme in Shu-Osher form:
    //     U <- alpha U^n + (1 - alpha)(U + dt L(U))
    const scalar alpha = rungeKutta_.alpha(stage);
    const scalar beta = 1 - alpha;
    if (boundaryWork_)
    {
        boundaryWork_->addStage(alpha, dt, *update_, *law_);
    }

    vectorField& lm = lm_.primitiveFieldRef();
    tensorField& F = F_.primitiveFieldRef();
    tensorField& gradD = gradD_.primitiveFieldRef();
    vectorField& D = D_.primitiveFieldRef();
    vectorField& pointD = pointD_.primitiveFieldRef();
    const vectorField& pointV = pointV_.primitiveField();

    // The rates are the cells' totals: 1/V is applied here, in the pass
    // that uses them, rather than in passes of their own. D advances with
    // the stage momentum, so before lm
    const scalarField& invV = inverseVolumes_;

    // One material: dt/rho once (bit for bit as before); several: each
    // cell's own density
    const bool uniform = law_->uniformMaterial();
    const scalar dtByRho = dt/law_->materialRho(0);

    forAll(F, celli)
    {
        const scalar dtByRhoi = uniform ? dtByRho : dt/law_->rho(celli);
        D[celli] = alpha*D0_[celli] + beta*(D[celli] + dtByRhoi*lm[celli]);
        gradD[celli] =
            alpha*gradD0_[celli]
          + beta*(gradD[celli] + (dt*invV[celli])*FRate_[celli]);
        F[celli] = tensor::I + gradD[celli];
    }
    forAll(pointD, pointi)
    {
        pointD[pointi] =
            alpha*pointD0_[pointi] + beta*(pointD[pointi] + dt*pointV[pointi]);
    }

    law_->advanceStage(alpha);

    bool ratePerVolume = false;

    if (preserveAngularMomentum_)
    {
        // The targets are the same combinations of the step's start and of
        // the boundary torques and work as the scheme makes of the states.
        // They are imposed at the end of the step only: a stage of an
        // explicit scheme moves the lever arms with the stage's start
        // velocity, so its own angular momentum is off by O(dt^2) even in
        // a rigid rotation, and forcing every stage onto its target
        // exchanged that much kinetic energy in each of them (measured: a
        // free spinning cube gained 7e-5 E0 a step). The step's result is
        // off by O(dt^3) only.
        Lstage_ = alpha*L0_ + beta*(Lstage_ + dt*torque_);
        Estage_ = alpha*E0_ + beta*(Estage_ + dt*power_);

        if (stage == rungeKutta_.nStages())
        {
            // The correction works on the rate per volume
            lmRate_ *= invV;
            ratePerVolume = true;

            // F and the law's state are at the step's end: what is left
            // of the energy budget is the kinetic energy the correction
            // may reach
            angularMomentum_.correct
            (
                cellPositions(D),
                alpha*lm0_ + beta*lm,
                beta*dt,
                Lstage_,
                law_->rho(),
                Estage_ - strainEnergy() - potentialEnergy(),
                lmRate_
            );
        }
    }

    // The last pass of the stage checks the cells too (J > 0, finite)
    invalidCell_ = -1;
    forAll(lm, celli)
    {
        const scalar scale = ratePerVolume ? dt : dt*invV[celli];
        lm[celli] = alpha*lm0_[celli] + beta*(lm[celli] + scale*lmRate_[celli]);

        if (invalidCell_ < 0 && !validCell(F[celli], lm[celli]))
        {
            invalidCell_ = celli;
        }
    }

    if (mesh_.nSolutionD() < 3)
    {
        constrainEmptyDirections();
    }
}


void Foam::touchSolid::restoreOldTime()
{
    lm_.primitiveFieldRef() = lm0_;
    gradD_.primitiveFieldRef() = gradD0_;
    F_.primitiveFieldRef() = tensor::I + gradD0_;
    D_.primitiveFieldRef() = D0_;
    pointD_.primitiveFieldRef() = pointD0_;
    law_->restoreOldTime();
    if (boundaryWork_)
    {
        boundaryWork_->restoreOldTime();
    }
}


// ************************************************************************* //
