/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The rigid wall's contact decisions: the wall's position (its velocity
    integrated exactly), the gaps of the faces and of their free points,
    the active set of each Runge-Kutta stage (updateActiveSet), the release
    of the faces that pull (releaseTensile) and the force the monitor
    reads.

\*---------------------------------------------------------------------------*/

#include "rigidWallFvPatchVectorField.H"
#include "TableBase.H"
#include "fvMesh.H"
#include "pointFields.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace Foam
{
    //- A face within this fraction of its size of the wall touches it
    static const scalar touchingTolerance = 1e-6;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::rigidWallFvPatchVectorField::wallDisplacement
(
    const scalar t
) const
{
    const auto* table =
        isA<Function1Types::TableBase<vector>>(velocity_());

    if (!table)
    {
        return velocity_->integrate(0, t);
    }

    // v1912's TableBase::integrate fails for the integrals a wall needs:
    // from the table's first row (integrate(0, t) with a row at 0 and
    // t <= 0 writes past its index list: the run aborted in free()) and
    // beyond its last row ("Integrating outside table").  The table is
    // linear between its rows and held outside them: the trapezoidal rule
    // over the rows inside (0, t) is exact
    const scalarField rows(table->x());

    vector sum(Zero);
    scalar a = 0;
    vector va(velocity_->value(a));

    for (const scalar b : rows)
    {
        if (b <= a)
        {
            continue;
        }
        if (b >= t)
        {
            break;
        }

        const vector vb(velocity_->value(b));
        sum += (0.5*(b - a))*(va + vb);
        a = b;
        va = vb;
    }

    if (t > a)
    {
        sum += (0.5*(t - a))*(va + velocity_->value(t));
    }

    return sum;
}


Foam::vector Foam::rigidWallFvPatchVectorField::wallPoint
(
    const scalar t
) const
{
    return point_ + wallDisplacement(t);
}


Foam::tmp<Foam::scalarField> Foam::rigidWallFvPatchVectorField::pointGaps
(
    const vector& wallPoint
) const
{
    const polyMesh& mesh = patch().boundaryMesh().mesh();
    const labelList& meshPoints = patch().patch().meshPoints();

    // The points' displacement is the solver's pointD
    const word pointDName("pointD");
    if (!db().foundObject<pointVectorField>(pointDName))
    {
        FatalErrorInFunction
            << "Patch " << patch().name() << ": 'touching lowestFreePoint'"
            << " and 'hold touchingPoints' need the point displacement"
            << " field " << pointDName << " (touchFoam's)" << exit(FatalError);
    }
    const vectorField& pointU =
        db().lookupObject<pointVectorField>(pointDName).primitiveField();
    const pointField& X = mesh.points();

    tmp<scalarField> tgaps(new scalarField(meshPoints.size()));
    scalarField& gaps = tgaps.ref();
    forAll(meshPoints, pointj)
    {
        const label pointi = meshPoints[pointj];
        gaps[pointj] = ((X[pointi] + pointU[pointi]) - wallPoint) & normal_;
    }

    return tgaps;
}


Foam::boolList Foam::rigidWallFvPatchVectorField::pointsOfContactFaces() const
{
    const polyMesh& mesh = patch().boundaryMesh().mesh();
    const labelList& meshPoints = patch().patch().meshPoints();
    const faceList& localFaces = patch().patch().localFaces();

    boolList inContact(meshPoints.size(), false);
    forAll(contact_, facei)
    {
        if (contact_[facei])
        {
            for (const label pointj : localFaces[facei])
            {
                inContact[pointj] = true;
            }
        }
    }
    syncTools::syncPointList
    (
        mesh, meshPoints, inContact, orEqOp<bool>(), false
    );

    return inContact;
}


Foam::tmp<Foam::scalarField> Foam::rigidWallFvPatchVectorField::lowestFreeGaps
(
    const vector& wallPoint
) const
{
    const faceList& localFaces = patch().patch().localFaces();
    const scalarField gaps(pointGaps(wallPoint));

    // The points some face in contact holds, on any rank: every point of
    // such a face, or with hold touchingPoints those that reached the wall
    const boolList held
    (
        holdTouching_ ? pointHeld_ : pointsOfContactFaces()
    );

    tmp<scalarField> tlowest(new scalarField(localFaces.size(), GREAT));
    scalarField& lowest = tlowest.ref();
    forAll(localFaces, facei)
    {
        for (const label pointj : localFaces[facei])
        {
            if (!held[pointj])
            {
                lowest[facei] = min(lowest[facei], gaps[pointj]);
            }
        }
    }

    return tlowest;
}


void Foam::rigidWallFvPatchVectorField::updateHeld(const vector& wallPoint)
{
    if (!holdTouching_)
    {
        return;
    }

    // One tolerance for the patch, the same on every rank
    const scalar tolerance =
        touchingTolerance*gMax(sqrt(patch().magSf()));

    const scalarField gaps(pointGaps(wallPoint));
    pointHeld_ = pointsOfContactFaces();
    forAll(pointHeld_, pointj)
    {
        pointHeld_[pointj] = pointHeld_[pointj] && gaps[pointj] <= tolerance;
    }
}


void Foam::rigidWallFvPatchVectorField::checkSide() const
{
    if (returnReduce(patch().size(), sumOp<label>()) == 0)
    {
        return;
    }

    const vector wallPoint(this->wallPoint(db().time().value()));
    const scalarField gap((patch().Cf() - wallPoint) & normal_);
    const scalar tolerance =
        touchingTolerance*gMax(sqrt(patch().magSf()));

    const scalar largest = gMax(gap);

    if (largest < -tolerance)
    {
        WarningInFunction
            << "Every face of patch " << patch().name() << " lies behind"
            << " the rigid wall (largest gap " << largest << "): is"
            << " 'normal' " << normal_ << " pointing from the wall into the"
            << " solid?" << endl;
    }

    // A face can come into contact only while its outward normal points
    // towards the wall (against 'normal'): a patch every face of which
    // faces away from the wall touches it only if the body turns over
    const scalar mostFacing = gMax(-(patch().nf() & normal_));
    if (mostFacing <= 0)
    {
        WarningInFunction
            << "Every face of patch " << patch().name() << " faces away"
            << " from the rigid wall (its outward normals make"
            << " n.normal >= 0 with 'normal' " << normal_ << "): the wall"
            << " cannot be touched unless the body turns over. Is the"
            << " condition on the patch meant to meet the wall?" << endl;
    }
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::rigidWallFvPatchVectorField::nContactFaces() const
{
    label n = 0;
    for (const bool inContact : stepContact_)
    {
        n += inContact;
    }
    return returnReduce(n, sumOp<label>());
}


Foam::vector Foam::rigidWallFvPatchVectorField::contactForce() const
{
    // Every rank has the same number of stages, except one whose part of
    // the patch is empty (never visited): the largest is the step's
    const label nStages = returnReduce(nStages_, maxOp<label>());

    return returnReduce(stepForce_, sumOp<vector>())/max(nStages, 1);
}


void Foam::rigidWallFvPatchVectorField::updateActiveSet
(
    const interiorState& s
)
{
    const vector wallPoint(this->wallPoint(s.time));
    const scalar wallNormalSpeed = velocity_->value(s.time) & normal_;
    const scalarField& magSf = patch().magSf();
    stageWallPoint_ = wallPoint;

    // The points the last decision holds, at their present positions
    updateHeld(wallPoint);

    if (s.stage == 1)
    {
        stepContact_ = false;
        stepForce_ = Zero;
        nStages_ = 0;
    }
    earlierContact_ = stepContact_;
    ++nStages_;
    stageForce_ = Zero;

    const scalarField lowest
    (
        lowestFreePoint_
      ? lowestFreeGaps(wallPoint)
      : tmp<scalarField>(new scalarField())
    );

    forAll(contact_, facei)
    {
        // The normal traction of the wall solution: > 0 if the wall pushes
        const scalar tW =
            (s.t[facei] & normal_)
          - s.Up[facei]*((s.p[facei] & normal_) - s.rho[facei]*wallNormalSpeed);

        const bool compressive = tW > 0;

        if (contact_[facei])
        {
            contact_[facei] = compressive;
        }
        else
        {
            const scalar gap =
                lowestFreePoint_
              ? min(lowest[facei], (s.xPoints[facei] - wallPoint) & normal_)
              : (s.xPoints[facei] - wallPoint) & normal_;
            contact_[facei] =
                compressive
             && gap <= touchingTolerance*sqrt(magSf[facei]);
        }

        if (contact_[facei])
        {
            stepContact_[facei] = true;
            stageForce_ += (tW*magSf[facei])*normal_;
        }
    }

    if (!updateChecked_ && (holdTouching_ || !friction_->frictionless()))
    {
        checkUpdate();
    }
    if (!friction_->frictionless())
    {
        updateFriction(s);
    }

    updateHeld(wallPoint);

    stepForce_ += stageForce_;
}


void Foam::rigidWallFvPatchVectorField::correctStageForce
(
    const vector& force
)
{
    stepForce_ += force - stageForce_;
    stageForce_ = force;
}


Foam::label Foam::rigidWallFvPatchVectorField::releaseTensile
(
    const vectorField& faceForce
)
{
    // The wall pushes as a whole: nothing to release.  Else every face
    // whose force pulls is released at once: a mirror-symmetric body
    // keeps its symmetry (releasing only the face that pulls most chose
    // one of two mirror faces, and the falling ring spun up to 2e-4
    // |p| R; ringAngularMomentum).  Releasing every face that pulls
    // whatever the total let the Taylor bar's impact face chatter
    // (contactGeometry)
    scalar total = 0;
    forAll(contact_, facei)
    {
        if (contact_[facei])
        {
            total += faceForce[facei] & normal_;
        }
    }
    if (returnReduce(total, sumOp<scalar>()) >= 0)
    {
        return 0;
    }

    label released = 0;
    forAll(contact_, facei)
    {
        if (contact_[facei] && (faceForce[facei] & normal_) < 0)
        {
            contact_[facei] = false;
            stepContact_[facei] = earlierContact_[facei];
            if (!friction_->frictionless())
            {
                frictionTraction_[facei] = Zero;
            }
            ++released;
        }
    }

    updateHeld(stageWallPoint_);

    return released;
}

// ************************************************************************* //
