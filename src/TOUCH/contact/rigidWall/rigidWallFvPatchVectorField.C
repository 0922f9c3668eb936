/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "rigidWallFvPatchVectorField.H"
#include "declaredEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"
#include "Constant.H"
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


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<vector> wallPointEntry
    (
        "0/U (or 0/lm) boundaryField, type rigidWall", "point", "a point of the wall plane at t = 0", "m",
        vector::zero, entryLimits::any(), declaredEntry<vector>::required
    );

    static const declaredEntry<vector> wallNormalEntry
    (
        "0/U (or 0/lm) boundaryField, type rigidWall", "normal",
        "the wall's normal, from the wall into the solid (normalised)", "-",
        vector(0, 1, 0), entryLimits::any(), declaredEntry<vector>::required
    );

    static const declaredEntry<word> wallTouchingEntry
    (
        "0/U (or 0/lm) boundaryField, type rigidWall", "touching",
        "when a face not in contact touches the wall: faceMean (the mean of"
        " its points reaches it) or lowestFreePoint (a point of it that no"
        " face in contact holds reaches it; curved bodies)",
        "-", word("faceMean"),
        entryLimits::oneOf({"faceMean", "lowestFreePoint"})
    );

    static const describedEntry wallContactEntry
    (
        "0/U (or 0/lm) boundaryField, type rigidWall", "contact",
        "written by touchFoam with every time: 1 for a face in contact, 0"
        " else (a restart continues with the same active set)",
        "-", "uniform 0", "nonuniform List<scalar> 4(0 1 1 0)"
    );

    static const describedEntry wallVelocityEntry
    (
        "0/U (or 0/lm) boundaryField, type rigidWall", "velocity",
        "the wall's velocity, a Function1 of time with an exact integral"
        " (constant, polynomial, table, tableFile, csvFile)",
        "m/s", "(0 0 0)", "table ((0 (0 0 0)) (1e-4 (0 0.1 0)))"
    );

    static const describedEntry wallSlipEntry
    (
        "0/U (or 0/lm) boundaryField, type rigidWall", "slip",
        "with friction, written by touchFoam with every time: each face's"
        " sliding velocity relative to the wall at the last decision, zero"
        " where it sticks (a restart continues with the same stick/slip"
        " state)",
        "m/s", "uniform (0 0 0)", "nonuniform List<vector> 2((0 0 0) (0.1 0 0))"
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::rigidWallFvPatchVectorField::readNormal
(
    const fvPatch& p,
    const dictionary& dict
)
{
    const vector n(wallNormalEntry.read(dict));

    if (mag(n) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'normal' = " << n << " of patch " << p.name()
            << " in " << dict.name() << " is zero: give the wall's normal,"
            << " pointing from the wall into the solid" << nl
            << exit(FatalIOError);
    }

    return n/mag(n);
}


Foam::autoPtr<Foam::Function1<Foam::vector>>
Foam::rigidWallFvPatchVectorField::readVelocity
(
    const fvPatch& p,
    const dictionary& dict
)
{
    const word& name = wallVelocityEntry.name();
    if (!dict.found(name, keyType::LITERAL))
    {
        return autoPtr<Function1<vector>>
        (
            new Function1Types::Constant<vector>(name, Zero)
        );
    }

    autoPtr<Function1<vector>> velocity(Function1<vector>::New(name, dict));

    // The wall's position is the integral of its velocity: the forms that
    // integrate exactly
    const wordList integrable
    ({
        "constant", "uniform", "zero", "one", "polynomial", "table",
        "tableFile", "csvFile"
    });

    if (!integrable.found(velocity->type()))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'velocity' of patch " << p.name() << " in "
            << dict.name() << " is a '" << velocity->type() << "', whose"
            << " integral (the wall's position) OpenFOAM does not give" << nl
            << "Valid velocity types for a rigid wall: " << integrable << nl
            << exit(FatalIOError);
    }

    // A table is integrated here row by row (wallDisplacement), which is
    // exact for the linear interpolation between its rows and the values
    // held outside them, not for a repeated table or another scheme
    if (isA<Function1Types::TableBase<vector>>(velocity()))
    {
        const dictionary& coeffs = dict.optionalSubDict("velocityCoeffs");
        const word bounding
        (
            coeffs.getOrDefault<word>("outOfBounds", "clamp")
        );
        const word scheme
        (
            coeffs.getOrDefault<word>("interpolationScheme", "linear")
        );

        if (bounding == "repeat" || scheme != "linear")
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'velocity' of patch " << p.name() << " in "
                << dict.name() << ": a rigid wall's velocity table is"
                << " integrated for its position with linear interpolation"
                << " and the end values held outside it" << nl
                << "Valid: outOfBounds (clamp warn error), interpolationScheme"
                << " linear; found outOfBounds " << bounding
                << ", interpolationScheme " << scheme << nl
                << exit(FatalIOError);
        }
    }

    return velocity;
}


Foam::boolList Foam::rigidWallFvPatchVectorField::readContact
(
    const fvPatch& p,
    const dictionary& dict
)
{
    const word& name = wallContactEntry.name();
    if (dict.found(name))
    {
        return toBool(scalarField(name, dict, p.size()));
    }

    return boolList(p.size(), false);
}


Foam::scalarField Foam::rigidWallFvPatchVectorField::toScalar
(
    const boolList& contact
)
{
    scalarField values(contact.size());
    forAll(contact, facei)
    {
        values[facei] = contact[facei] ? 1 : 0;
    }
    return values;
}


Foam::boolList Foam::rigidWallFvPatchVectorField::toBool
(
    const scalarField& contact
)
{
    boolList values(contact.size());
    forAll(contact, facei)
    {
        values[facei] = contact[facei] > 0.5;
    }
    return values;
}


Foam::vectorField Foam::rigidWallFvPatchVectorField::readSlip
(
    const dictionary& dict
) const
{
    if (friction_->frictionless())
    {
        return vectorField();
    }

    const word& name = wallSlipEntry.name();
    if (dict.found(name, keyType::LITERAL))
    {
        return vectorField(name, dict, patch().size());
    }

    return vectorField(patch().size(), Zero);
}


void Foam::rigidWallFvPatchVectorField::updateFriction
(
    const interiorState& s
)
{
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

    if (update == "compatible")
    {
        FatalIOErrorInFunction(controls)
            << "Patch " << patch().name() << " is a rigidWall with friction"
            << " and FUpdate is compatible (" << controls.name() << "):"
            << " its normal wall force is the point constraint's reaction,"
            << " which the friction law does not see (a sliding block"
            << " decelerated 4 % too little, or lifted off and gained"
            << " energy)" << nl
            << "Valid FUpdate with friction: plain (constrained: with a"
            << " warning)" << nl
            << exit(FatalIOError);
    }

    if (update != "plain")
    {
        WarningInFunction
            << "Patch " << patch().name() << ": friction with FUpdate "
            << update << " is not validated (the sliding block's energy"
            << " grew by 2e-7 of its kinetic energy in steps); plain is"
            << endl;
    }
}


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


Foam::tmp<Foam::scalarField> Foam::rigidWallFvPatchVectorField::lowestFreeGaps
(
    const vector& wallPoint
) const
{
    const polyMesh& mesh = patch().boundaryMesh().mesh();
    const labelList& meshPoints = patch().patch().meshPoints();
    const faceList& localFaces = patch().patch().localFaces();

    // The points' displacement is the solver's pointD
    const word pointDName("pointD");
    if (!db().foundObject<pointVectorField>(pointDName))
    {
        FatalErrorInFunction
            << "Patch " << patch().name() << ": 'touching lowestFreePoint'"
            << " needs the point displacement field " << pointDName
            << " (touchFoam's)" << exit(FatalError);
    }
    const vectorField& pointU =
        db().lookupObject<pointVectorField>(pointDName).primitiveField();
    const pointField& X = mesh.points();

    // The points some face in contact holds, on any rank
    boolList held(meshPoints.size(), false);
    forAll(contact_, facei)
    {
        if (contact_[facei])
        {
            for (const label pointj : localFaces[facei])
            {
                held[pointj] = true;
            }
        }
    }
    syncTools::syncPointList(mesh, meshPoints, held, orEqOp<bool>(), false);

    tmp<scalarField> tgaps(new scalarField(localFaces.size(), GREAT));
    scalarField& gaps = tgaps.ref();
    forAll(localFaces, facei)
    {
        for (const label pointj : localFaces[facei])
        {
            if (!held[pointj])
            {
                const label pointi = meshPoints[pointj];
                gaps[facei] = min
                (
                    gaps[facei],
                    ((X[pointi] + pointU[pointi]) - wallPoint) & normal_
                );
            }
        }
    }

    return tgaps;
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidWallFvPatchVectorField::rigidWallFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF),
    point_(Zero),
    normal_(Zero),
    velocity_(new Function1Types::Constant<vector>("velocity", Zero)),
    lowestFreePoint_(false),
    contact_(p.size(), false),
    stepContact_(contact_),
    earlierContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero),
    friction_(frictionLaw::New(dictionary())),
    frictionTraction_(),
    slip_(),
    updateChecked_(false)
{}


Foam::rigidWallFvPatchVectorField::rigidWallFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    solidFluxFvPatchVectorField
    (
        p, iF, dict,
        wordList
        ({
            "point", "normal", "velocity", "velocityCoeffs", "touching",
            "contact", "friction", "slip"
        })
    ),
    point_(wallPointEntry.read(dict)),
    normal_(readNormal(p, dict)),
    velocity_(readVelocity(p, dict)),
    lowestFreePoint_(wallTouchingEntry.read(dict) == "lowestFreePoint"),
    contact_(readContact(p, dict)),
    stepContact_(contact_),
    earlierContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero),
    friction_(frictionLaw::New(dict)),
    frictionTraction_(friction_->frictionless() ? 0 : p.size(), Zero),
    slip_(readSlip(dict)),
    updateChecked_(false)
{
    checkSide();
}


Foam::rigidWallFvPatchVectorField::rigidWallFvPatchVectorField
(
    const rigidWallFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    solidFluxFvPatchVectorField(ptf, p, iF, mapper),
    point_(ptf.point_),
    normal_(ptf.normal_),
    velocity_(ptf.velocity_.clone()),
    lowestFreePoint_(ptf.lowestFreePoint_),
    // Faces the mapper does not reach (reconstructPar builds the patch
    // from one processor's part, the rest comes by rmap) are not in
    // contact, rather than left unset: an unset value compared in toBool
    // stopped reconstructPar with a floating point exception
    contact_(toBool(scalarField(toScalar(ptf.contact_), mapper, scalar(0)))),
    stepContact_(contact_),
    earlierContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero),
    friction_(ptf.friction_->clone()),
    frictionTraction_
    (
        ptf.friction_->frictionless() ? 0 : p.size(), Zero
    ),
    slip_
    (
        ptf.friction_->frictionless()
      ? vectorField()
      : vectorField(ptf.slip_, mapper)
    ),
    updateChecked_(false)
{}


Foam::rigidWallFvPatchVectorField::rigidWallFvPatchVectorField
(
    const rigidWallFvPatchVectorField& ptf
)
:
    solidFluxFvPatchVectorField(ptf),
    point_(ptf.point_),
    normal_(ptf.normal_),
    velocity_(ptf.velocity_.clone()),
    lowestFreePoint_(ptf.lowestFreePoint_),
    contact_(ptf.contact_),
    stepContact_(ptf.stepContact_),
    earlierContact_(ptf.earlierContact_),
    stepForce_(ptf.stepForce_),
    nStages_(ptf.nStages_),
    stageForce_(ptf.stageForce_),
    friction_(ptf.friction_->clone()),
    frictionTraction_(ptf.frictionTraction_),
    slip_(ptf.slip_),
    updateChecked_(ptf.updateChecked_)
{}


Foam::rigidWallFvPatchVectorField::rigidWallFvPatchVectorField
(
    const rigidWallFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF),
    point_(ptf.point_),
    normal_(ptf.normal_),
    velocity_(ptf.velocity_.clone()),
    lowestFreePoint_(ptf.lowestFreePoint_),
    contact_(ptf.contact_),
    stepContact_(ptf.stepContact_),
    earlierContact_(ptf.earlierContact_),
    stepForce_(ptf.stepForce_),
    nStages_(ptf.nStages_),
    stageForce_(ptf.stageForce_),
    friction_(ptf.friction_->clone()),
    frictionTraction_(ptf.frictionTraction_),
    slip_(ptf.slip_),
    updateChecked_(ptf.updateChecked_)
{}


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

    if (!friction_->frictionless())
    {
        if (!updateChecked_)
        {
            checkUpdate();
        }
        updateFriction(s);
    }

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

    return released;
}


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


void Foam::rigidWallFvPatchVectorField::autoMap(const fvPatchFieldMapper& m)
{
    solidFluxFvPatchVectorField::autoMap(m);

    scalarField contact(toScalar(contact_));
    contact.autoMap(m);
    contact_ = toBool(contact);
    stepContact_ = contact_;
    earlierContact_ = contact_;

    if (!friction_->frictionless())
    {
        slip_.autoMap(m);
        frictionTraction_.autoMap(m);
    }
}


void Foam::rigidWallFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    solidFluxFvPatchVectorField::rmap(ptf, addr);

    const rigidWallFvPatchVectorField& wptf =
        refCast<const rigidWallFvPatchVectorField>(ptf);

    scalarField contact(toScalar(contact_));
    contact.rmap(toScalar(wptf.contact_), addr);
    contact_ = toBool(contact);
    stepContact_ = contact_;
    earlierContact_ = contact_;

    if (!friction_->frictionless())
    {
        slip_.rmap(wptf.slip_, addr);
        frictionTraction_.rmap(wptf.frictionTraction_, addr);
    }
}


void Foam::rigidWallFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    os.writeEntry("point", point_);
    os.writeEntry("normal", normal_);
    velocity_->writeData(os);
    if (lowestFreePoint_)
    {
        os.writeEntry(wallTouchingEntry.name(), word("lowestFreePoint"));
    }
    toScalar(contact_).writeEntry("contact", os);

    if (!friction_->frictionless())
    {
        friction_->write(os);
        slip_.writeEntry(wallSlipEntry.name(), os);
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, rigidWallFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addRigidWallSolidFluxType(rigidWallFvPatchVectorField::typeName_());
}

// ************************************************************************* //
