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

    static const declaredEntry<word> bodyContactSideEntry
    (
        "0/U (or 0/lm) boundaryField, type bodyContact", "side",
        "with FUpdate compatible, which side's points are held in a contact"
        " of this patch: both (each side holds its faces' points at the"
        " pair's contact velocity; faces that match) or nodes (this patch's"
        " points follow the partner surface under them and load its points"
        " with their reactions; faces that do not match: the softer side,"
        " or the finer where the two are alike) or auto (the update gives"
        " this patch side nodes where a patch it may touch is stiffer, or"
        " alike and coarser)",
        "-", word("both"), entryLimits::oneOf({"both", "nodes", "auto"})
    );

    static const describedEntry bodyContactContactEntry
    (
        "0/U (or 0/lm) boundaryField, type bodyContact", "contact",
        "written by touchFoam with every time: 1 for a face in contact as"
        " the first side of a pair, 0 else (a restart continues with the"
        " same active set)",
        "-", "uniform 0", "nonuniform List<scalar> 4(0 1 1 0)"
    );

    static const describedEntry bodyContactSlipEntry
    (
        "0/U (or 0/lm) boundaryField, type bodyContact", "slip",
        "with friction, written by touchFoam with every time: each face's"
        " relative sliding velocity as the first side of a pair at the last"
        " decision, zero where it sticks (a restart continues with the same"
        " stick/slip state)",
        "m/s", "uniform (0 0 0)", "nonuniform List<vector> 2((0 0 0) (1 0 0))"
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


Foam::vectorField Foam::bodyContactFvPatchVectorField::readSlip
(
    const dictionary& dict
) const
{
    if (friction_->frictionless())
    {
        return vectorField();
    }

    const word& name = bodyContactSlipEntry.name();
    if (dict.found(name, keyType::LITERAL))
    {
        return vectorField(name, dict, patch().size());
    }

    return vectorField(patch().size(), Zero);
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
    friction_(frictionLaw::New(dictionary())),
    slip_(),
    frictionPower_(0),
    moment_(p.size(), Zero),
    touching_(p.size(), false),
    normal_(p.size(), Zero),
    contactVelocity_(p.size(), Zero),
    nodalForce_(p.size(), Zero),
    stageForce_(Zero),
    pointConstrained_(false),
    nodes_(false),
    autoSide_(false),
    nodePower_(0),
    nodePowerSet_(false)
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
            bodyContactPatchesEntry.name(), bodyContactContactEntry.name(),
            "friction", bodyContactSlipEntry.name(),
            bodyContactSideEntry.name()
        })
    ),
    patches_
    (
        dict.getOrDefault<wordList>(bodyContactPatchesEntry.name(), wordList())
    ),
    contact_(readContact(p, dict)),
    traction_(p.size(), Zero),
    friction_(frictionLaw::New(dict)),
    slip_(readSlip(dict)),
    frictionPower_(0),
    moment_(p.size(), Zero),
    touching_(p.size(), false),
    normal_(p.size(), Zero),
    contactVelocity_(p.size(), Zero),
    nodalForce_(p.size(), Zero),
    stageForce_(Zero),
    pointConstrained_(false),
    nodes_(bodyContactSideEntry.read(dict) == "nodes"),
    autoSide_(bodyContactSideEntry.read(dict) == "auto"),
    nodePower_(0),
    nodePowerSet_(false)
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
    friction_(ptf.friction_->clone()),
    slip_
    (
        ptf.friction_->frictionless()
      ? vectorField()
      : vectorField(ptf.slip_, mapper)
    ),
    frictionPower_(0),
    moment_(p.size(), Zero),
    touching_(p.size(), false),
    normal_(p.size(), Zero),
    contactVelocity_(p.size(), Zero),
    nodalForce_(p.size(), Zero),
    stageForce_(Zero),
    pointConstrained_(false),
    nodes_(ptf.nodes_),
    autoSide_(ptf.autoSide_),
    nodePower_(0),
    nodePowerSet_(false)
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
    friction_(ptf.friction_->clone()),
    slip_(ptf.slip_),
    frictionPower_(ptf.frictionPower_),
    moment_(ptf.moment_),
    touching_(ptf.touching_),
    normal_(ptf.normal_),
    contactVelocity_(ptf.contactVelocity_),
    nodalForce_(ptf.nodalForce_),
    stageForce_(ptf.stageForce_),
    pointConstrained_(ptf.pointConstrained_),
    nodes_(ptf.nodes_),
    autoSide_(ptf.autoSide_),
    nodePower_(0),
    nodePowerSet_(false)
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
    friction_(ptf.friction_->clone()),
    slip_(ptf.slip_),
    frictionPower_(ptf.frictionPower_),
    moment_(ptf.moment_),
    touching_(ptf.touching_),
    normal_(ptf.normal_),
    contactVelocity_(ptf.contactVelocity_),
    nodalForce_(ptf.nodalForce_),
    stageForce_(ptf.stageForce_),
    pointConstrained_(ptf.pointConstrained_),
    nodes_(ptf.nodes_),
    autoSide_(ptf.autoSide_),
    nodePower_(0),
    nodePowerSet_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyContactFvPatchVectorField::setPointConstrained()
{
    pointConstrained_ = true;
}


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

    // With side nodes the points follow the partner surface and the
    // reactions alone carry the contact force, which the partner takes:
    // the flux damps nothing (the cell's own normal momentum), so that no
    // force acts on one side only
    const tmp<vectorField> tlmCell
    (
        nodes_ ? patchInternalField() : tmp<vectorField>(new vectorField())
    );

    // Along the pair's normal, the rigid wall's flux with the contact
    // velocity: with the same normal velocity of the points, two equal
    // bars meet as one bar meets a wall (the update balances the forces)
    forAll(touching_, facei)
    {
        if (touching_[facei])
        {
            const tensor nn(sqr(normal_[facei]));
            const tensor tangential(tensor::I - nn);
            const vector momentum
            (
                nodes_
              ? tlmCell()[facei]
              : vector(s.rho[facei]*contactVelocity_[facei])
            );

            pC[facei] = (tangential & pC[facei]) + (nn & momentum);
            tC[facei] =
                (tangential & tC[facei])
              + (nn & (s.t[facei] - s.Up[facei]*(s.p[facei] - momentum)));

            // Side nodes: the damping of the cells' approach
            // (contactSurfaces), whole
            if (nodes_)
            {
                tC[facei] += nn & traction_[facei];
            }
        }
    }
}


void Foam::bodyContactFvPatchVectorField::addTorque
(
    const interiorState& s,
    const vectorField& tC,
    vector& torque
) const
{
    if (pointConstrained_)
    {
        // The faces of side nodes' pairs (this patch's with side nodes,
        // the partner's untouched ones) carry only the pairs' damping of
        // the cells' approach, whose torque is taken at the pairs' contact
        // points, where its opposite acts; at the faces' centres the two
        // sides' levers part where the faces do not match (an oblique
        // collision's angular momentum drifted by 3e-5 of a block's).  The
        // faces held on both sides keep the flux's torque at the face
        const scalarField& magSf = patch().magSf();
        forAll(tC, i)
        {
            if (nodes_ || !touching_[i])
            {
                torque +=
                    (s.x[i] ^ ((tC[i] - traction_[i])*magSf[i]))
                  + moment_[i];
            }
            else
            {
                torque += s.x[i] ^ (tC[i]*magSf[i]);
            }
        }
        return;
    }

    // The flux's force is the faces' contact forces (tC = traction_)
    for (const vector& m : moment_)
    {
        torque += m;
    }
}


void Foam::bodyContactFvPatchVectorField::constraint
(
    const interiorState& s,
    tensorField& free,
    vectorField& velocity
) const
{
    // With side nodes the update prescribes each point's normal velocity
    // from the partner surface (compatible::holdNodesOnSurfaces); the
    // face's is the cell's own, so that its damping takes nothing
    const tmp<vectorField> tlmCell
    (
        nodes_ ? patchInternalField() : tmp<vectorField>(new vectorField())
    );

    forAll(touching_, facei)
    {
        if (touching_[facei])
        {
            const tensor nn(sqr(normal_[facei]));
            free[facei] = tensor::I - nn;
            velocity[facei] =
                nodes_
              ? vector((nn & tlmCell()[facei])/s.rho[facei])
              : contactVelocity_[facei];
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
    nodalForce_.setSize(contact.size());
    nodalForce_ = Zero;
    moment_.setSize(contact.size());
    moment_ = Zero;
    if (!friction_->frictionless())
    {
        slip_.autoMap(m);
    }
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
    if (!friction_->frictionless())
    {
        slip_.rmap(cptf.slip_, addr);
    }
}


void Foam::bodyContactFvPatchVectorField::write(Ostream& os) const
{
    solidFluxFvPatchVectorField::write(os);
    if (patches_.size())
    {
        os.writeEntry(bodyContactPatchesEntry.name(), patches_);
    }
    if (autoSide_ || nodes_)
    {
        os.writeEntry
        (
            bodyContactSideEntry.name(), word(autoSide_ ? "auto" : "nodes")
        );
    }

    scalarField contact(contact_.size());
    forAll(contact, facei)
    {
        contact[facei] = contact_[facei] ? 1 : 0;
    }
    contact.writeEntry(bodyContactContactEntry.name(), os);

    if (!friction_->frictionless())
    {
        friction_->write(os);
        slip_.writeEntry(bodyContactSlipEntry.name(), os);
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchVectorField, bodyContactFvPatchVectorField);

    static const solidFluxFvPatchVectorField::addType
        addBodyContactSolidFluxType(bodyContactFvPatchVectorField::typeName_());
}

// ************************************************************************* //
