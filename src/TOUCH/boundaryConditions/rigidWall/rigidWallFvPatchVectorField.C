/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "rigidWallFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace Foam
{
    //- A face within this fraction of its size of the wall touches it
    static const scalar touchingTolerance = 1e-6;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::rigidWallFvPatchVectorField::readNormal
(
    const fvPatch& p,
    const dictionary& dict
)
{
    const vector n(dict.get<vector>("normal"));

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


Foam::boolList Foam::rigidWallFvPatchVectorField::readContact
(
    const fvPatch& p,
    const dictionary& dict
)
{
    if (dict.found("contact"))
    {
        return toBool(scalarField("contact", dict, p.size()));
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


Foam::scalar Foam::rigidWallFvPatchVectorField::stageTime
(
    const label stage
) const
{
    // touchFoam advances the time before the step's stages: stage 1 works
    // on the state of the step's start, the others on states at its end
    // (RK2; see the header for RK3)
    const Time& time = db().time();

    return stage == 1 ? time.value() - time.deltaTValue() : time.value();
}


void Foam::rigidWallFvPatchVectorField::checkSide() const
{
    if (returnReduce(patch().size(), sumOp<label>()) == 0)
    {
        return;
    }

    const vector wallPoint(point_ + velocity_*db().time().value());
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
    velocity_(Zero),
    contact_(p.size(), false),
    stepContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero)
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
        p, iF, dict, wordList({"point", "normal", "velocity", "contact"})
    ),
    point_(dict.get<vector>("point")),
    normal_(readNormal(p, dict)),
    velocity_(dict.getOrDefault<vector>("velocity", Zero)),
    contact_(readContact(p, dict)),
    stepContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero)
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
    velocity_(ptf.velocity_),
    contact_(toBool(scalarField(toScalar(ptf.contact_), mapper))),
    stepContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero)
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
    velocity_(ptf.velocity_),
    contact_(ptf.contact_),
    stepContact_(ptf.stepContact_),
    stepForce_(ptf.stepForce_),
    nStages_(ptf.nStages_),
    stageForce_(ptf.stageForce_)
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
    const vector wallPoint(point_ + velocity_*stageTime(s.stage));
    const scalar wallNormalSpeed = velocity_ & normal_;
    const scalarField& magSf = patch().magSf();

    if (s.stage == 1)
    {
        stepContact_ = false;
        stepForce_ = Zero;
        nStages_ = 0;
    }
    ++nStages_;
    stageForce_ = Zero;

    forAll(contact_, facei)
    {
        // The normal traction of the wall solution: > 0 if the wall pushes
        const scalar tW =
            (s.t[facei] & normal_)
          - s.Up*((s.p[facei] & normal_) - s.rho*wallNormalSpeed);

        const bool compressive = tW > 0;

        if (contact_[facei])
        {
            contact_[facei] = compressive;
        }
        else
        {
            const scalar gap = (s.xPoints[facei] - wallPoint) & normal_;
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
    const vector wallMomentum(s.rho*velocity_);

    forAll(contact_, facei)
    {
        if (contact_[facei])
        {
            pC[facei] =
                ((tensor::I - nn) & (s.p[facei] - s.t[facei]/s.Us))
              + (nn & wallMomentum);
            tC[facei] =
                nn & (s.t[facei] - s.Up*(s.p[facei] - wallMomentum));
        }
    }
}


void Foam::rigidWallFvPatchVectorField::constraint
(
    const interiorState&,
    tensorField& free,
    vectorField& velocity
) const
{
    const tensor nn(sqr(normal_));
    const vector wallNormalVelocity(nn & velocity_);

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
}


void Foam::rigidWallFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    os.writeEntry("point", point_);
    os.writeEntry("normal", normal_);
    os.writeEntry("velocity", velocity_);
    toScalar(contact_).writeEntry("contact", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, rigidWallFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addRigidWallSolidFluxType(rigidWallFvPatchVectorField::typeName_());
}

// ************************************************************************* //
