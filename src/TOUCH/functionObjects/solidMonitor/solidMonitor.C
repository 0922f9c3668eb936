/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "solidMonitor.H"
#include "declaredEntry.H"
#include "touchSolid.H"
#include "rigidWallFvPatchVectorField.H"
#include "bodyContactFvPatchVectorField.H"
#include "emptyFvPatch.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(solidMonitor, 0);
    addToRunTimeSelectionTable(functionObject, solidMonitor, dictionary);
}
}


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<vector> originEntry
    (
        "system/controlDict functions, type solidMonitor", "origin",
        "the point the total angular momentum is taken about (current"
        " positions)",
        "m", vector::zero
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::labelList Foam::functionObjects::solidMonitor::findWallPatches() const
{
    if (!mesh_.foundObject<touchSolid>(touchSolid::typeName))
    {
        return labelList();
    }

    const touchSolid& solid =
        mesh_.lookupObject<touchSolid>(touchSolid::typeName);

    DynamicList<label> walls;
    forAll(solid.lm().boundaryField(), patchi)
    {
        if (isA<rigidWallFvPatchVectorField>(solid.lm().boundaryField()[patchi]))
        {
            walls.append(patchi);
        }
    }
    return labelList(std::move(walls));
}


Foam::boolList
Foam::functionObjects::solidMonitor::findExchangePatches() const
{
    boolList exchange(workPatches_.size(), false);
    if (!mesh_.foundObject<touchSolid>(touchSolid::typeName))
    {
        return exchange;
    }

    const touchSolid& solid =
        mesh_.lookupObject<touchSolid>(touchSolid::typeName);
    forAll(workPatches_, i)
    {
        exchange[i] = isA<bodyContactFvPatchVectorField>
        (
            solid.lm().boundaryField()[workPatches_[i]]
        );
    }
    return exchange;
}


Foam::labelList Foam::functionObjects::solidMonitor::findWorkPatches() const
{
    DynamicList<label> patches;
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (!patch.coupled() && !isA<emptyFvPatch>(patch))
        {
            patches.append(patchi);
        }
    }
    return labelList(std::move(patches));
}


Foam::tmp<Foam::scalarField>
Foam::functionObjects::solidMonitor::cellPlasticWork() const
{
    auto tWork = tmp<scalarField>::New(mesh_.nCells(), Zero);

    if (dissipates_)
    {
        const touchSolid& solid =
            mesh_.lookupObject<touchSolid>(touchSolid::typeName);
        solid.law().addPlasticWork(tWork.ref());
        tWork.ref() *= mesh_.V().field();
    }

    return tWork;
}


Foam::scalarField Foam::functionObjects::solidMonitor::bodySums() const
{
    const touchSolid& solid =
        mesh_.lookupObject<touchSolid>(touchSolid::typeName);
    const mechanicalLaw& law = solid.law();
    const gravity* g = solid.gravityForce();
    const scalarField& V = mesh_.V();
    const labelList& cellBody = bodies_.cellBody();
    const vectorField& lm = solid.lm().primitiveField();
    const vectorField x
    (
        mesh_.C().primitiveField() + solid.D().primitiveField()
    );

    scalarField strain(V.size());
    law.cellStrainEnergy(solid.F(), solid.gradD(), strain);
    const tmp<scalarField> tPlastic(cellPlasticWork());
    const scalarField& plastic = tPlastic();

    scalarField sums(nValues*bodies_.size(), Zero);
    forAll(V, celli)
    {
        scalar* s = &sums[nValues*cellBody[celli]];
        const vector p(V[celli]*lm[celli]);
        const vector L(x[celli] ^ p);

        for (direction d = 0; d < vector::nComponents; ++d)
        {
            s[d] += p[d];
            s[3 + d] += L[d];
        }
        s[6] += 0.5*(p & lm[celli])/law.rho(celli);
        s[7] += strain[celli];
        if (g)
        {
            s[8] -= g->weight()[celli] & x[celli];
        }
        s[9] += plastic[celli];
    }

    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);

    return sums;
}


void Foam::functionObjects::solidMonitor::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Invariants and energy balance of the solid");
    writeHeaderValue(os, "Angular momentum about", origin_);
    writeHeaderValue
    (
        os, "E0 (kinetic + strain + potential energy at the start)", E0_
    );
    writeHeaderValue(os, "Bodies", bodies_.size());
    forAll(bodies_.names(), bodyi)
    {
        writeHeaderValue(os, "Body " + bodies_.names()[bodyi] + " E0",
            bodies_.size() > 1 ? bodyE0_[bodyi] : E0_);
    }
    writeCommented(os, "Time");
    for
    (
        const char* title
      : {"px", "py", "pz", "Lx", "Ly", "Lz", "kineticEnergy", "strainEnergy"}
    )
    {
        writeTabbed(os, title);
    }
    if (gravity_)
    {
        writeTabbed(os, "potentialEnergy");
    }
    writeTabbed(os, "totalEnergy");
    for (const label patchi : wallPatches_)
    {
        const word& name = mesh_.boundary()[patchi].name();
        writeTabbed(os, "contactFaces(" + name + ")");
        writeTabbed(os, "wallForce(" + name + ")");
    }
    if (dissipates_)
    {
        writeTabbed(os, "plasticDissipation");
    }
    if (friction_)
    {
        writeTabbed(os, "frictionDissipation");
    }
    writeTabbed(os, "boundaryWork");
    writeTabbed(os, "numericalDissipation");
    writeTabbed(os, "numericalDissipationFraction");
    for (const label patchi : workPatches_)
    {
        writeTabbed
        (
            os, "boundaryWork(" + mesh_.boundary()[patchi].name() + ")"
        );
    }
    if (bodies_.size() > 1)
    {
        for (const word& body : bodies_.names())
        {
            for
            (
                const char* title
              : {"px", "py", "pz", "Lx", "Ly", "Lz", "kineticEnergy",
                 "strainEnergy"}
            )
            {
                writeTabbed(os, word(title) + "(" + body + ")");
            }
            if (gravity_)
            {
                writeTabbed(os, "potentialEnergy(" + body + ")");
            }
            if (dissipates_)
            {
                writeTabbed(os, "plasticDissipation(" + body + ")");
            }
            writeTabbed(os, "boundaryWork(" + body + ")");
            writeTabbed(os, "numericalDissipation(" + body + ")");
        }
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::solidMonitor::solidMonitor
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    origin_(Zero),
    wallPatches_(findWallPatches()),
    gravity_
    (
        mesh_.lookupObject<touchSolid>(touchSolid::typeName).hasGravity()
    ),
    dissipates_
    (
        mesh_.lookupObject<touchSolid>(touchSolid::typeName).law()
       .dissipates()
    ),
    friction_(false),
    bodies_(mesh_),
    workPatches_(findWorkPatches()),
    exchangePatch_(findExchangePatches()),
    E0_(0),
    bodyE0_(),
    bodyPlastic0_(),
    plastic0_(0)
{
    read(dict);

    // The balance starts now: the energy of the present state, the work
    // of the boundaries from zero, the law's plastic work so far
    touchSolid& solid =
        mesh_.lookupObjectRef<touchSolid>(touchSolid::typeName);
    solid.accountBoundaryWork(bodies_.cellBody(), bodies_.size());
    friction_ = solid.boundaryWorkAccount()->friction();

    E0_ =
        solid.kineticEnergy() + solid.strainEnergy() + solid.potentialEnergy();
    plastic0_ = gSum(cellPlasticWork()());

    if (bodies_.size() > 1)
    {
        const scalarField sums(bodySums());
        bodyE0_.setSize(bodies_.size());
        bodyPlastic0_.setSize(bodies_.size());
        forAll(bodyE0_, bodyi)
        {
            const scalar* s = &sums[nValues*bodyi];
            bodyE0_[bodyi] = s[6] + s[7] + s[8];
            bodyPlastic0_[bodyi] = s[9];
        }
    }

    if (Pstream::master() && writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::solidMonitor::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    // Every entry is solidMonitor's or one OpenFOAM reads for any function
    // object: a misspelt one would otherwise be ignored
    entryDeclaration::checkEntries
    (
        dict,
        originEntry.where(),
        {
            "type", "libs", "functionObjectLibs", "enabled", "log",
            "region", "writeControl", "writeInterval", "executeControl",
            "executeInterval", "outputControl", "outputInterval",
            "evaluateControl", "evaluateInterval", "timeStart", "timeEnd",
            "deltaTCoeff", "nStepsToStartTimeChange", "writePrecision",
            "writeToFile", "useUserTime", "updateHeader"
        }
    );

    origin_ = originEntry.read(dict);

    return true;
}


bool Foam::functionObjects::solidMonitor::execute()
{
    // The solver's own totals: one definition for the log, the tests and
    // this file
    const touchSolid& solid =
        mesh_.lookupObject<touchSolid>(touchSolid::typeName);

    const vector p(solid.totalLinearMomentum());
    const vector L(solid.totalAngularMomentum(origin_));
    const scalar kinetic = solid.kineticEnergy();
    const scalar stored = solid.strainEnergy();
    const scalar potential = solid.potentialEnergy();

    // Every rank takes part in the sums of the walls
    labelList contactFaces(wallPatches_.size());
    scalarField wallForce(wallPatches_.size());
    forAll(wallPatches_, i)
    {
        const rigidWallFvPatchVectorField& wall =
            refCast<const rigidWallFvPatchVectorField>
            (
                solid.lm().boundaryField()[wallPatches_[i]]
            );
        contactFaces[i] = wall.nContactFaces();
        wallForce[i] = wall.contactForce() & wall.normal();
    }

    // The energy balance: the boundaries' work per patch and per body
    // (this rank's, reduced here), the plastic work since the start
    const boundaryWork& account = *solid.boundaryWorkAccount();
    // (the patches of every rank: not its processor patches, which
    // differ between ranks and do no work)
    scalarField patchWork
    (
        UIndirectList<scalar>(account.patchWork(), workPatches_)
    );
    scalarField bodyWork(account.bodyWork());
    Pstream::listCombineGather(patchWork, plusEqOp<scalar>());
    Pstream::listCombineScatter(patchWork);
    Pstream::listCombineGather(bodyWork, plusEqOp<scalar>());
    Pstream::listCombineScatter(bodyWork);

    // The friction between bodies, out of the boundaries' work
    const scalar friction =
        friction_ ? -returnReduce(account.frictionWork(), sumOp<scalar>()) : 0;

    // The boundaries' work, without the contact between bodies: its two
    // sides exchange energy and do no net work, so what their works do
    // not cancel beyond the friction's is the exchange's numerical loss,
    // which the remainder below then holds
    scalar work = 0;
    forAll(patchWork, i)
    {
        if (!exchangePatch_[i])
        {
            work += patchWork[i];
        }
    }
    const scalar plastic =
        dissipates_ ? gSum(cellPlasticWork()()) - plastic0_ : 0;
    const scalar numerical =
        E0_ + work - (kinetic + stored + potential + plastic + friction);
    const scalar reference = E0_ > 0 ? E0_ : E0_ + work;

    const scalarField sums
    (
        bodies_.size() > 1 ? bodySums() : scalarField()
    );

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        // The time to the same 16 digits as the values (writeCurrentTime
        // gives the time name, to timePrecision, 6 digits by default): the
        // steps' lengths, and so the impulse of the wall force over a
        // run, are then exact to round-off
        os.precision(16);
        os  << setw(charWidth()) << mesh_.time().value();
        os  << tab << p.x() << tab << p.y() << tab << p.z()
            << tab << L.x() << tab << L.y() << tab << L.z()
            << tab << kinetic << tab << stored;
        if (gravity_)
        {
            os  << tab << potential;
        }
        os  << tab << kinetic + stored + potential;
        forAll(wallPatches_, i)
        {
            os  << tab << contactFaces[i] << tab << wallForce[i];
        }
        if (dissipates_)
        {
            os  << tab << plastic;
        }
        if (friction_)
        {
            os  << tab << friction;
        }
        os  << tab << work << tab << numerical
            << tab << (reference > 0 ? numerical/reference : 0);
        for (const scalar w : patchWork)
        {
            os  << tab << w;
        }
        forAll(bodyE0_, bodyi)
        {
            const scalar* s = &sums[nValues*bodyi];
            const vector pb(s[0], s[1], s[2]);
            const vector Lb(vector(s[3], s[4], s[5]) - (origin_ ^ pb));
            const scalar plasticb = s[9] - bodyPlastic0_[bodyi];

            os  << tab << pb.x() << tab << pb.y() << tab << pb.z()
                << tab << Lb.x() << tab << Lb.y() << tab << Lb.z()
                << tab << s[6] << tab << s[7];
            if (gravity_)
            {
                os  << tab << s[8];
            }
            if (dissipates_)
            {
                os  << tab << plasticb;
            }
            os  << tab << bodyWork[bodyi]
                << tab
                << bodyE0_[bodyi] + bodyWork[bodyi]
                 - (s[6] + s[7] + s[8] + plasticb);
        }
        os  << endl;
    }

    return true;
}


bool Foam::functionObjects::solidMonitor::write()
{
    return true;
}


// ************************************************************************* //
