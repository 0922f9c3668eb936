/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    Where the compatible update's upwindings take the energy out, a
    diagnostic (DebugSwitches { compatible 1; }): the energy each cell has
    lost since the start to the momentum upwinding of its faces (half of
    each interior face's to either cell) and of its boundary conditions,
    upwindLoss [J] (a condition's whole force on its cell: the work of a
    prescribed traction or motion counts too, with its sign), and each
    point to the point upwinding,
    pointUpwindLoss [J], written with the fields.  The first stage's power
    times the step (a tally, not the scheme's quadrature); serial runs of
    one material (others say so in the log and tally nothing).  Nothing is
    allocated or computed without the switch.

\*---------------------------------------------------------------------------*/

#include "compatible.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::initLosses()
{
    const fvMesh& mesh = faces_.mesh();
    if (!debug)
    {
        return;
    }

    if (Pstream::parRun() || !law_.uniformMaterial())
    {
        WarningInFunction
            << "DebugSwitches compatible: the losses are tallied in serial"
            << " runs of one material only; none written" << endl;
        return;
    }

    upwindLoss_.reset
    (
        new volScalarField
        (
            IOobject
            (
                "upwindLoss", mesh.time().timeName(), mesh,
                IOobject::NO_READ, IOobject::AUTO_WRITE
            ),
            mesh,
            dimensionedScalar("0", dimEnergy, Zero)
        )
    );
    pointUpwindLoss_.reset
    (
        new pointScalarField
        (
            IOobject
            (
                "pointUpwindLoss", mesh.time().timeName(), mesh,
                IOobject::NO_READ, IOobject::AUTO_WRITE
            ),
            pointMesh::New(mesh),
            dimensionedScalar("0", dimEnergy, Zero)
        )
    );
}


void Foam::deformationUpdates::compatible::tallyFaceLosses()
{
    const fvMesh& mesh = faces_.mesh();
    const scalar dt = mesh.time().deltaTValue();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const vectorField& X = faces_.reconstructionCentres();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& Sf = mesh.faceAreas();
    const scalarField& magSf = mesh.magSf().primitiveField();
    const vectorField& p = faces_.lm().primitiveField();
    const tensorField& F = faces_.F().primitiveField();
    const tensorField& gradp =
        faces_.reconstruction().gradp().primitiveField();
    scalarField& loss = upwindLoss_->primitiveFieldRef();
    const vectorField& u = faces_.u().primitiveField();
    const scalar invRho = 1/law_.rho();

    // As addFaceRates: with preservation the jumps less the body's spin
    const bool spinning = magSqr(rigidSpin_) > 0;

    forAll(own, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        vector jump(p[n] - p[o]);
        if (spinning)
        {
            jump -= rigidSpin_ ^ ((X[n] + u[n]) - (X[o] + u[o]));
        }
        const vector tC
        (
            riemannUpwindForce
            (
                jump,
                linearReconstruction::p(p[n], gradp[n], Cf[facei] - X[n])
              - linearReconstruction::p(p[o], gradp[o], Cf[facei] - X[o]),
                F[o] + F[n],
                Sf[facei],
                magSf[facei]
            )
        );

        // The power the face takes out, tC . (v_n - v_o) (>= 0 but for
        // the spin's share with preservation)
        const scalar half = 0.5*dt*invRho*(tC & (p[n] - p[o]));
        loss[o] += half;
        loss[n] += half;
    }
}


void Foam::deformationUpdates::compatible::tallyCellLosses
(
    const vectorField& before,
    const vectorField& after
)
{
    // The boundary conditions' force on their cells, the power it takes
    const scalar dt = faces_.mesh().time().deltaTValue();
    const vectorField& p = faces_.lm().primitiveField();
    scalarField& loss = upwindLoss_->primitiveFieldRef();
    const scalar invRho = 1/law_.rho();

    forAll(loss, celli)
    {
        loss[celli] -= dt*invRho*((after[celli] - before[celli]) & p[celli]);
    }
}


void Foam::deformationUpdates::compatible::tallyPointLosses
(
    const vectorField& before,
    const vectorField& after
)
{
    // The point upwinding moved each point by w = -kappa phi Pi f: its
    // stress power f . w <= 0 (the nodal forces still complete here)
    const scalar dt = faces_.mesh().time().deltaTValue();
    scalarField& loss = pointUpwindLoss_->primitiveFieldRef();

    forAll(loss, pointi)
    {
        vector f(pointForce_[pointi]);
        constraints_.constrainOne(pointi, f);
        loss[pointi] -= dt*((after[pointi] - before[pointi]) & f);
    }
}


// ************************************************************************* //
