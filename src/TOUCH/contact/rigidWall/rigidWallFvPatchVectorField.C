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

    static const declaredEntry<word> wallHoldEntry
    (
        "0/U (or 0/lm) boundaryField, type rigidWall", "hold",
        "which points of a face in contact the wall holds (compatible"
        " update): faces (all of them, from the stage the face enters) or"
        " touchingPoints (each from the stage it reaches the wall; curved"
        " bodies)",
        "-", word("faces"),
        entryLimits::oneOf({"faces", "touchingPoints"})
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
    holdTouching_(false),
    pointHeld_(),
    stageWallPoint_(Zero),
    contact_(p.size(), false),
    stepContact_(contact_),
    earlierContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero),
    friction_(frictionLaw::New(dictionary())),
    frictionTraction_(),
    slip_(),
    updateChecked_(false),
    pointFriction_(false),
    pointPower_()
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
            "hold", "contact", "friction", "slip"
        })
    ),
    point_(wallPointEntry.read(dict)),
    normal_(readNormal(p, dict)),
    velocity_(readVelocity(p, dict)),
    lowestFreePoint_(wallTouchingEntry.read(dict) == "lowestFreePoint"),
    holdTouching_(wallHoldEntry.read(dict) == "touchingPoints"),
    pointHeld_(),
    stageWallPoint_(Zero),
    contact_(readContact(p, dict)),
    stepContact_(contact_),
    earlierContact_(contact_),
    stepForce_(Zero),
    nStages_(0),
    stageForce_(Zero),
    friction_(frictionLaw::New(dict)),
    frictionTraction_(friction_->frictionless() ? 0 : p.size(), Zero),
    slip_(readSlip(dict)),
    updateChecked_(false),
    pointFriction_(false),
    pointPower_()
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
    holdTouching_(ptf.holdTouching_),
    pointHeld_(),
    stageWallPoint_(ptf.stageWallPoint_),
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
    updateChecked_(false),
    pointFriction_(false),
    pointPower_()
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
    holdTouching_(ptf.holdTouching_),
    pointHeld_(ptf.pointHeld_),
    stageWallPoint_(ptf.stageWallPoint_),
    contact_(ptf.contact_),
    stepContact_(ptf.stepContact_),
    earlierContact_(ptf.earlierContact_),
    stepForce_(ptf.stepForce_),
    nStages_(ptf.nStages_),
    stageForce_(ptf.stageForce_),
    friction_(ptf.friction_->clone()),
    frictionTraction_(ptf.frictionTraction_),
    slip_(ptf.slip_),
    updateChecked_(ptf.updateChecked_),
    pointFriction_(ptf.pointFriction_),
    pointPower_()
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
    holdTouching_(ptf.holdTouching_),
    pointHeld_(ptf.pointHeld_),
    stageWallPoint_(ptf.stageWallPoint_),
    contact_(ptf.contact_),
    stepContact_(ptf.stepContact_),
    earlierContact_(ptf.earlierContact_),
    stepForce_(ptf.stepForce_),
    nStages_(ptf.nStages_),
    stageForce_(ptf.stageForce_),
    friction_(ptf.friction_->clone()),
    frictionTraction_(ptf.frictionTraction_),
    slip_(ptf.slip_),
    updateChecked_(ptf.updateChecked_),
    pointFriction_(ptf.pointFriction_),
    pointPower_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
    if (holdTouching_)
    {
        os.writeEntry(wallHoldEntry.name(), word("touchingPoints"));
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
