/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The rigid wall's fluxes: the wall solution of the faces in contact and
    the traction-free one of the others (flux), the kinematic constraint
    of the points (constraint), and with friction the law's tangential
    traction and the faces' slip (updateFriction).

\*---------------------------------------------------------------------------*/

#include "rigidWallFvPatchVectorField.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rigidWallFvPatchVectorField::updateFriction
(
    const interiorState& s
)
{
    // The compatible update applies the friction at the held points
    if (pointFriction_)
    {
        frictionTraction_ = Zero;
        return;
    }

    const vector wallVelocity(velocity_->value(s.time));
    const scalar wallNormalSpeed = wallVelocity & normal_;
    const tensor tangential(tensor::I - sqr(normal_));
    const scalarField& magSf = patch().magSf();

    // The stage's checks (debug only): the largest |t_t| - mu pN, the
    // largest mu pN, the largest face work rate and their sum
    const scalar mu = friction_->maxCoefficient();
    scalar coneExcess = -GREAT;
    scalar coneLimit = 0;
    scalar facePower = -GREAT;
    scalar power = 0;

    forAll(contact_, facei)
    {
        // The interior's velocity relative to the wall, as momentum
        const vector relative(s.p[facei] - s.rho[facei]*wallVelocity);

        if (!contact_[facei])
        {
            frictionTraction_[facei] = Zero;
            slip_[facei] = tangential & (relative/s.rho[facei]);
            continue;
        }

        // The wall solution: its normal traction (as updateActiveSet's,
        // > 0 in contact) and the tangential traction that holds the face
        // at the wall's tangential velocity
        const scalar pN =
            (s.t[facei] & normal_)
          - s.Up[facei]*((s.p[facei] & normal_) - s.rho[facei]*wallNormalSpeed);
        const vector tStick
        (
            tangential & (s.t[facei] - s.Us[facei]*relative)
        );

        const vector t
        (
            friction_->tangentialTraction(tStick, pN, slip_[facei])
        );

        // The face's tangential velocity on its characteristic, relative
        // to the wall: exactly zero where the law keeps tStick
        frictionTraction_[facei] = t;
        slip_[facei] = (t - tStick)/(s.rho[facei]*s.Us[facei]);

        stageForce_ += t*magSf[facei];

        if (debug)
        {
            const scalar facePowerI = (t & slip_[facei])*magSf[facei];
            coneExcess = max(coneExcess, mag(t) - mu*pN);
            coneLimit = max(coneLimit, mu*pN);
            facePower = max(facePower, facePowerI);
            power += facePowerI;
        }
    }

    if (debug)
    {
        reduce(coneExcess, maxOp<scalar>());
        reduce(coneLimit, maxOp<scalar>());
        reduce(facePower, maxOp<scalar>());
        reduce(power, sumOp<scalar>());

        // Not in contact anywhere: nothing to report
        if (facePower > -GREAT)
        {
            Info<< "rigidWall " << patch().name() << " friction: time "
                << s.time << " stage " << s.stage
                << " max(|t_t| - mu p_N) " << coneExcess
                << " max(mu p_N) " << coneLimit
                << " max face work rate " << facePower
                << " work rate " << power << endl;
        }
    }
}


void Foam::rigidWallFvPatchVectorField::checkUpdate()
{
    updateChecked_ = true;

    const dictionary& controls =
        patch().boundaryMesh().mesh().solutionDict().subDict("TOUCH");
    const word update
    (
        controls.getOrDefault<word>("FUpdate", "compatible")
    );

    // hold touchingPoints is the compatible update's: the others move a
    // face's points by its own constraint, all of them
    if (holdTouching_ && update != "compatible")
    {
        WarningInFunction
            << "Patch " << patch().name() << ": 'hold touchingPoints' acts"
            << " with FUpdate compatible only; with FUpdate " << update
            << " (" << controls.name() << ") a face in contact holds all"
            << " its points, as with 'hold faces'" << endl;
    }

    if (friction_->frictionless())
    {
        return;
    }

    // compatible: the friction acts at the held points, about their
    // reactions (compatible::addWallFriction)
    if (update != "plain" && update != "compatible")
    {
        WarningInFunction
            << "Patch " << patch().name() << ": friction with FUpdate "
            << update << " is not validated (the sliding block's energy"
            << " grew by 2e-7 of its kinetic energy in steps); plain and"
            << " compatible are" << endl;
    }
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rigidWallFvPatchVectorField::flux
(
    const interiorState& s,
    vectorField& pC,
    vectorField& tC
) const
{
    // Traction-free everywhere, then the wall where in contact
    tractionFlux(s, vectorField(pC.size(), Zero), pC, tC);

    const tensor nn(sqr(normal_));
    const vector wallVelocity(velocity_->value(s.time));

    forAll(contact_, facei)
    {
        if (contact_[facei])
        {
            const vector wallMomentum(s.rho[facei]*wallVelocity);
            pC[facei] =
                ((tensor::I - nn) & (s.p[facei] - s.t[facei]/s.Us[facei]))
              + (nn & wallMomentum);
            tC[facei] =
                nn & (s.t[facei] - s.Up[facei]*(s.p[facei] - wallMomentum));
        }
    }

    // Friction: the law's tangential traction, and the momentum of the
    // tangential characteristic that meets it, p + (t^C - t-)/Us
    if (!friction_->frictionless())
    {
        forAll(contact_, facei)
        {
            if (contact_[facei])
            {
                const vector& t = frictionTraction_[facei];
                tC[facei] += t;
                pC[facei] += t/s.Us[facei];
            }
        }
    }
}


void Foam::rigidWallFvPatchVectorField::constraint
(
    const interiorState& s,
    tensorField& free,
    vectorField& velocity
) const
{
    const tensor nn(sqr(normal_));
    const vector wallNormalVelocity(nn & velocity_->value(s.time));

    forAll(contact_, facei)
    {
        if (contact_[facei])
        {
            free[facei] = tensor::I - nn;
            velocity[facei] = wallNormalVelocity;
        }
        else
        {
            free[facei] = tensor::I;
            velocity[facei] = Zero;
        }
    }
}

// ************************************************************************* //
