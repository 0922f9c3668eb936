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


void Foam::functionObjects::solidMonitor::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Invariants of the solid");
    writeHeaderValue(os, "Angular momentum about", origin_);
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
    )
{
    read(dict);

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
        os  << endl;
    }

    return true;
}


bool Foam::functionObjects::solidMonitor::write()
{
    return true;
}


// ************************************************************************* //
