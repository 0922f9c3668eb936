/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "bodyContactFvPatchVectorField.H"
#include "declaredEntry.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const describedEntry bodyContactPatchesEntry
    (
        "0/U (or 0/lm) boundaryField, type bodyContact", "patches",
        "the bodyContact patches this one may touch (a pair is searched"
        " when either lists the other)",
        "-", "all bodyContact patches, itself included", "(barRightEnd)"
    );

    static const describedEntry bodyContactContactEntry
    (
        "0/U (or 0/lm) boundaryField, type bodyContact", "contact",
        "written by touchFoam with every time: 1 for a face in contact as"
        " the first side of a pair, 0 else (a restart continues with the"
        " same active set)",
        "-", "uniform 0", "nonuniform List<scalar> 4(0 1 1 0)"
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boolList Foam::bodyContactFvPatchVectorField::readContact
(
    const fvPatch& p,
    const dictionary& dict
)
{
    boolList contact(p.size(), false);

    const word& name = bodyContactContactEntry.name();
    if (dict.found(name))
    {
        const scalarField values(name, dict, p.size());
        forAll(values, facei)
        {
            contact[facei] = values[facei] > 0.5;
        }
    }

    return contact;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyContactFvPatchVectorField::bodyContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(p, iF),
    patches_(),
    contact_(p.size(), false),
    traction_(p.size(), Zero),
    touching_(p.size(), false),
    normal_(p.size(), Zero),
    contactVelocity_(p.size(), Zero),
    stageForce_(Zero),
    pointConstrained_(false)
{}


Foam::bodyContactFvPatchVectorField::bodyContactFvPatchVectorField
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
            bodyContactPatchesEntry.name(), bodyContactContactEntry.name()
        })
    ),
    patches_
    (
        dict.getOrDefault<wordList>(bodyContactPatchesEntry.name(), wordList())
    ),
    contact_(readContact(p, dict)),
    traction_(p.size(), Zero),
    touching_(p.size(), false),
    normal_(p.size(), Zero),
    contactVelocity_(p.size(), Zero),
    stageForce_(Zero),
    pointConstrained_(false)
{}


Foam::bodyContactFvPatchVectorField::bodyContactFvPatchVectorField
(
    const bodyContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    solidFluxFvPatchVectorField(ptf, p, iF, mapper),
    patches_(ptf.patches_),
    contact_(p.size(), false),
    traction_(p.size(), Zero),
    touching_(p.size(), false),
    normal_(p.size(), Zero),
    contactVelocity_(p.size(), Zero),
    stageForce_(Zero),
    pointConstrained_(false)
{
    scalarField contact(ptf.contact_.size());
    forAll(contact, facei)
    {
        contact[facei] = ptf.contact_[facei] ? 1 : 0;
    }
    const scalarField mapped(contact, mapper);
    forAll(mapped, facei)
    {
        contact_[facei] = mapped[facei] > 0.5;
    }
}


Foam::bodyContactFvPatchVectorField::bodyContactFvPatchVectorField
(
    const bodyContactFvPatchVectorField& ptf
)
:
    solidFluxFvPatchVectorField(ptf),
    patches_(ptf.patches_),
    contact_(ptf.contact_),
    traction_(ptf.traction_),
    touching_(ptf.touching_),
    normal_(ptf.normal_),
    contactVelocity_(ptf.contactVelocity_),
    stageForce_(ptf.stageForce_),
    pointConstrained_(ptf.pointConstrained_)
{}


Foam::bodyContactFvPatchVectorField::bodyContactFvPatchVectorField
(
    const bodyContactFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    solidFluxFvPatchVectorField(ptf, iF),
    patches_(ptf.patches_),
    contact_(ptf.contact_),
    traction_(ptf.traction_),
    touching_(ptf.touching_),
    normal_(ptf.normal_),
    contactVelocity_(ptf.contactVelocity_),
    stageForce_(ptf.stageForce_),
    pointConstrained_(ptf.pointConstrained_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyContactFvPatchVectorField::flux
(
    const interiorState& s,
    vectorField& pC,
    vectorField& tC
) const
{
    tractionFlux(s, traction_, pC, tC);

    if (!pointConstrained_)
    {
        return;
    }

    // Along the pair's normal, the rigid wall's flux with the contact
    // velocity: with the same normal velocity of the points, two equal
    // bars meet as one bar meets a wall (the update balances the forces)
    forAll(touching_, facei)
    {
        if (touching_[facei])
        {
            const tensor nn(sqr(normal_[facei]));
            const tensor tangential(tensor::I - nn);
            const vector momentum(s.rho[facei]*contactVelocity_[facei]);

            pC[facei] = (tangential & pC[facei]) + (nn & momentum);
            tC[facei] =
                (tangential & tC[facei])
              + (nn & (s.t[facei] - s.Up[facei]*(s.p[facei] - momentum)));
        }
    }
}


void Foam::bodyContactFvPatchVectorField::constraint
(
    const interiorState&,
    tensorField& free,
    vectorField& velocity
) const
{
    forAll(touching_, facei)
    {
        if (touching_[facei])
        {
            free[facei] = tensor::I - sqr(normal_[facei]);
            velocity[facei] = contactVelocity_[facei];
        }
        else
        {
            free[facei] = tensor::I;
            velocity[facei] = Zero;
        }
    }
}


void Foam::bodyContactFvPatchVectorField::autoMap(const fvPatchFieldMapper& m)
{
    solidFluxFvPatchVectorField::autoMap(m);

    scalarField contact(contact_.size());
    forAll(contact, facei)
    {
        contact[facei] = contact_[facei] ? 1 : 0;
    }
    contact.autoMap(m);

    contact_.setSize(contact.size());
    forAll(contact, facei)
    {
        contact_[facei] = contact[facei] > 0.5;
    }
    traction_.setSize(contact.size());
    traction_ = Zero;
    touching_.setSize(contact.size());
    touching_ = false;
    normal_.setSize(contact.size());
    normal_ = Zero;
    contactVelocity_.setSize(contact.size());
    contactVelocity_ = Zero;
}


void Foam::bodyContactFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    solidFluxFvPatchVectorField::rmap(ptf, addr);

    const bodyContactFvPatchVectorField& cptf =
        refCast<const bodyContactFvPatchVectorField>(ptf);

    forAll(addr, i)
    {
        contact_[addr[i]] = cptf.contact_[i];
    }
}


void Foam::bodyContactFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    if (patches_.size())
    {
        os.writeEntry(bodyContactPatchesEntry.name(), patches_);
    }

    scalarField contact(contact_.size());
    forAll(contact, facei)
    {
        contact[facei] = contact_[facei] ? 1 : 0;
    }
    contact.writeEntry(bodyContactContactEntry.name(), os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, bodyContactFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addBodyContactSolidFluxType(bodyContactFvPatchVectorField::typeName_());
}

// ************************************************************************* //
