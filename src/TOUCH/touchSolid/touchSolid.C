/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
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


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::touchSolid::checkInput() const
{
    checkPatchTypes(mesh_);
    checkTwoD();

    if (lm_.dimensions() != dimDensity*dimVelocity)
    {
        FatalErrorInFunction
            << "Field " << lm_.objectPath() << " has dimensions "
            << lm_.dimensions() << "; linear momentum needs "
            << dimDensity*dimVelocity << " [kg/(m^2 s)]" << nl
            << exit(FatalError);
    }

    for (const fvPatchVectorField& pf : lm_.boundaryField())
    {
        if
        (
            !pf.coupled()
         && !isA<emptyFvPatch>(pf.patch())
         && !isA<solidFluxFvPatchVectorField>(pf)
        )
        {
            FatalErrorInFunction
                << "Entry boundaryField/" << pf.patch().name() << "/type '"
                << pf.type() << "' in " << lm_.objectPath()
                << " is not a solid boundary condition." << nl
                << "Valid types: " << solidFluxFvPatchVectorField::types()
                << nl << exit(FatalError);
        }
    }
}


bool Foam::touchSolid::readMirrorPlanes(const dictionary& controls)
{
    const word planes
    (
        controls.getOrDefault<word>("symmetricPlanes", "oneSided")
    );

    if (planes != "oneSided" && planes != "mirror")
    {
        FatalIOErrorInFunction(controls)
            << "Unknown symmetricPlanes '" << planes << "' in "
            << controls.name() << ": valid choices are oneSided (the"
            << " default) and mirror" << nl << exit(FatalIOError);
    }

    return planes == "mirror";
}


Foam::scalarList Foam::touchSolid::mirrorPatches
(
    const volVectorField& lm,
    const bool mirrorPlanes
)
{
    scalarList signs(lm.boundaryField().size(), scalar(0));
    if (!mirrorPlanes)
    {
        return signs;
    }

    forAll(lm.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = lm.boundaryField()[patchi];
        if (isA<emptyFvPatch>(pf.patch()))
        {
            // A 2D case is its one-cell slab between symmetric planes
            signs[patchi] = 1;
        }
        else if (isA<solidFluxFvPatchVectorField>(pf))
        {
            const solidFluxFvPatchVectorField& condition =
                refCast<const solidFluxFvPatchVectorField>(pf);
            if (condition.mirror())
            {
                signs[patchi] = condition.mirrorSign();
            }
        }
    }

    return signs;
}


Foam::tmp<Foam::vectorField> Foam::touchSolid::cellPositions
(
    const vectorField& u
) const
{
    return mesh_.C().primitiveField() + u;
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
        u_.correctBoundaryConditions();
    }
    law_->correct(F_, P_);
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
                cellPositions(u_.primitiveField()), lm_.primitiveField()
            ),
            pointU_.primitiveField()
        );
    }

    update_->rates(stage, lmRate_, FRate_, pointV_.primitiveFieldRef(), torque_);

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
        const scalar kinetic =
            gSum(lm_.primitiveField() & lmRate_)/law_->rho();
        const scalar stored = gSum(P_.primitiveField() && FRate_);

        Info<< "touchSolid: stage " << stage << " energy rate: kinetic "
            << kinetic << ", stored " << stored << endl;
    }
}


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
    controls_(mesh.solutionDict().subDict("TOUCH")),
    law_(mechanicalLaw::New(mesh)),
    riemann_(riemannSolver::New(controls_, *law_)),
    angularMomentum_(mesh),
    preserveAngularMomentum_
    (
        controls_.get<Switch>("angularMomentumPreservation")
    ),
    nodalAveraging_(nodalAveraging::New(mesh, controls_, *law_)),
    rungeKutta_(controls_),
    lm_
    (
        fieldIO(mesh, "lm", IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    F_
    (
        fieldIO(mesh, "F", IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        mesh,
        dimensionedTensor("I", dimless, tensor::I),
        calculatedFvPatchTensorField::typeName
    ),
    u_
    (
        fieldIO(mesh, "u", IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        mesh,
        dimensionedVector("0", dimLength, Zero),
        calculatedFvPatchVectorField::typeName
    ),
    pointU_
    (
        fieldIO(mesh, "pointU", IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        pointMesh::New(mesh),
        dimensionedVector("0", dimLength, Zero),
        calculatedPointPatchVectorField::typeName
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
    faces_(mesh, reconstruction_, lm_, F_, P_, u_, pointU_),
    update_
    (
        deformationUpdate::New(controls_, faces_, *law_, *riemann_, reconstruction_)
    ),
    timeStep_(controls_, faces_, *law_),
    lm0_(mesh.nCells()),
    F0_(mesh.nCells()),
    u0_(mesh.nCells()),
    pointU0_(mesh.nPoints()),
    lmRate_(mesh.nCells()),
    FRate_(mesh.nCells()),
    inverseVolumes_(1/mesh.V().field()),
    invalidCell_(-1),
    torque_(Zero),
    power_(0),
    L0_(Zero),
    Lstage_(Zero),
    E0_(0),
    Estage_(0)
{
    checkInput();

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
            const label celli = invalidCell_;
            if (celli >= 0)
            {
                Pout<< "touchSolid: cell " << celli << " at "
                    << mesh_.C()[celli] + u_[celli] << " (reference "
                    << mesh_.C()[celli] << "): det F = " << det(F_[celli])
                    << ", |lm| = " << mag(lm_[celli]) << endl;
            }

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
    F0_ = F_.primitiveField();
    u0_ = u_.primitiveField();
    pointU0_ = pointU_.primitiveField();
    law_->storeOldTime();

    if (preserveAngularMomentum_)
    {
        L0_ = angularMomentum_.total(cellPositions(u0_), lm0_);
        Lstage_ = L0_;
        E0_ = kineticEnergy() + strainEnergy();
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
    const scalar rho = law_->rho();

    vectorField& lm = lm_.primitiveFieldRef();
    tensorField& F = F_.primitiveFieldRef();
    vectorField& u = u_.primitiveFieldRef();
    vectorField& pointU = pointU_.primitiveFieldRef();
    const vectorField& pointV = pointV_.primitiveField();

    // The rates are the cells' totals: 1/V is applied here, in the pass
    // that uses them, rather than in passes of their own. u advances with
    // the stage momentum, so before lm
    const scalarField& invV = inverseVolumes_;
    const scalar dtByRho = dt/rho;

    forAll(F, celli)
    {
        u[celli] = alpha*u0_[celli] + beta*(u[celli] + dtByRho*lm[celli]);
        F[celli] =
            alpha*F0_[celli]
          + beta*(F[celli] + (dt*invV[celli])*FRate_[celli]);
    }
    forAll(pointU, pointi)
    {
        pointU[pointi] =
            alpha*pointU0_[pointi] + beta*(pointU[pointi] + dt*pointV[pointi]);
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
                cellPositions(u),
                alpha*lm0_ + beta*lm,
                beta*dt,
                Lstage_,
                rho,
                Estage_ - strainEnergy(),
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


bool Foam::touchSolid::valid() const
{
    return returnReduce(firstInvalidCell() < 0, andOp<bool>());
}


void Foam::touchSolid::restoreOldTime()
{
    lm_.primitiveFieldRef() = lm0_;
    F_.primitiveFieldRef() = F0_;
    u_.primitiveFieldRef() = u0_;
    pointU_.primitiveFieldRef() = pointU0_;
    law_->restoreOldTime();
}


// ************************************************************************* //
