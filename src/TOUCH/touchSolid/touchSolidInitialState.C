/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The state touchSolid starts from: the linear momentum lm, read from the
    start time's lm or built as rho U from its velocity U [m/s], whichever
    exists (lm first: a restart, and cases set up in momentum), with the
    boundary conditions of the field that was read; and the checks of that
    state (dimensions, solid boundary condition types).

\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
#include "emptyFvPatch.H"
#include "clampedFvPatchVectorField.H"
#include "symmetricPlaneFvPatchVectorField.H"
#include "localIOdictionary.H"
#include "entryDeclaration.H"
#include "FlatOutput.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- IOobject of a field of the start time, read without registering it (the
//  state's own lm is registered under its name)
static IOobject inputIO(const fvMesh& mesh, const word& name)
{
    return IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
}


//- Whether a field file exists at io, of any class; one of another class
//  than volVectorField (a volScalarField U, a pointVectorField) is refused
//  naming the class (OpenFOAM would take it for absent)
template<class FieldType>
static bool fieldExists(const IOobject& io)
{
    IOobject header(io);
    if (!header.typeHeaderOk<FieldType>(false))
    {
        return false;
    }

    if (header.headerClassName() != FieldType::typeName)
    {
        FatalErrorInFunction
            << "Field " << io.objectPath() << " has class "
            << header.headerClassName() << "; touchSolid reads "
            << io.name() << " as a " << FieldType::typeName
            << " (FoamFile class)" << nl
            << exit(FatalError);
    }

    return true;
}


//- Every cell of the mesh has a positive, finite volume: the update
//  divides by it (a zero or inverted cell would give inf or a step that
//  runs backwards)
static void checkVolumes(const fvMesh& mesh)
{
    const scalarField& V = mesh.V().field();
    forAll(V, celli)
    {
        if (!(V[celli] > 0) || !std::isfinite(V[celli]))
        {
            FatalErrorInFunction
                << "Cell " << celli << " of the mesh (constant/polyMesh) at "
                << mesh.C()[celli] << " has volume " << V[celli]
                << ": every cell needs a positive volume (inverted or"
                << " collapsed cell; see checkMesh)" << nl
                << exit(FatalError);
        }
    }
}


//- Before OpenFOAM reads the field: every patch of the mesh that needs a
//  condition has an entry in boundaryField, of a solid type.  OpenFOAM
//  would list its fluid types for a misspelt one, or say 'Cannot find
//  patchField entry' for a missing one without naming what to write
static void checkConditionTypes(const fvMesh& mesh, const IOobject& io)
{
    const localIOdictionary fieldDict
    (
        IOobject
        (
            io.name(),
            io.instance(),
            io.local(),
            io.db(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        ),
        volVectorField::typeName
    );

    const dictionary& conditions = fieldDict.subDict("boundaryField");
    const wordList solidTypes(solidFluxFvPatchVectorField::types());

    for (const fvPatch& patch : mesh.boundary())
    {
        if (patch.coupled() || isA<emptyFvPatch>(patch))
        {
            continue;
        }

        const entry* eptr = conditions.findEntry(patch.name(), keyType::REGEX);
        if (!eptr || !eptr->isDict())
        {
            FatalIOErrorInFunction(conditions)
                << "Patch " << patch.name() << " of the mesh has no entry in"
                << " boundaryField of " << io.objectPath() << nl
                << "    Give it a solid boundary condition, e.g. "
                << patch.name() << " { type traction; }" << nl
                << "    Valid types: " << flatOutput(solidTypes) << nl
                << exit(FatalIOError);
        }

        const word type(eptr->dict().get<word>("type"));
        if (!solidTypes.found(type))
        {
            const word near(entryDeclaration::nearest(type, solidTypes));
            FatalIOErrorInFunction(eptr->dict())
                << "Entry boundaryField/" << patch.name() << "/type '" << type
                << "' in " << io.objectPath()
                << " is not a solid boundary condition"
                << (near.empty() ? "" : ": did you mean '") << near
                << (near.empty() ? "" : "'?") << nl
                << "    Valid types: " << flatOutput(solidTypes) << nl
                << exit(FatalIOError);
        }
    }
}


//- Every boundary of an initial field carries a solid condition
static void checkConditions(const volVectorField& field)
{
    for (const fvPatchVectorField& pf : field.boundaryField())
    {
        if
        (
            !pf.coupled()
         && !isA<emptyFvPatch>(pf.patch())
         && !isA<solidFluxFvPatchVectorField>(pf)
        )
        {
            FatalErrorInFunction
                << "Entry boundaryField/" << pf.patch().name() << "/type '"
                << pf.type() << "' in " << field.objectPath()
                << " is not a solid boundary condition." << nl
                << "Valid types: " << solidFluxFvPatchVectorField::types()
                << nl << exit(FatalError);
        }
    }
}


//- The field has the dimensions the state needs
static void checkDimensions
(
    const volVectorField& field,
    const dimensionSet& dims,
    const char* meaning
)
{
    if (field.dimensions() != dims)
    {
        FatalErrorInFunction
            << "Field " << field.objectPath() << " has dimensions "
            << field.dimensions() << "; " << meaning << " needs " << dims
            << nl << exit(FatalError);
    }
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::touchSolid::cellDensity
(
    const fvMesh& mesh,
    const mechanicalLaw& law
)
{
    return law.cellRho();
}


void Foam::touchSolid::initialiseDisplacementGradient()
{
    const tensorField& F = F_.primitiveField();
    tensorField& gradD = gradD_.primitiveFieldRef();

    IOobject gradDIO(inputIO(mesh_, gradD_.name()));
    if (fieldExists<volTensorField>(gradDIO))
    {
        const volTensorField written(gradDIO, mesh_);

        // The written gradD is the state where it forms the written F to
        // the digits F was written with (touchFoam's 17, decomposePar's
        // writePrecision, binary's all): an F edited since wins
        const scalar digit =
            Foam::pow(10.0, 1 - scalar(IOstream::defaultPrecision()));
        label edited = 0;
        forAll(F, celli)
        {
            const tensor formed(tensor::I + written[celli]);
            if
            (
                formed != F[celli]
             && cmptMax(cmptMag(formed - F[celli]))
              > digit*max(1, cmptMax(cmptMag(F[celli])))
            )
            {
                ++edited;
            }
        }

        if (returnReduce(edited, sumOp<label>()) == 0)
        {
            gradD = written.primitiveField();
            return;
        }

        WarningInFunction
            << gradDIO.objectPath() << " does not form the F read beside it"
            << " in " << returnReduce(edited, sumOp<label>()) << " cells (F"
            << " edited since it was written): gradD is taken as F - I"
            << endl;
    }
}


Foam::tmp<Foam::volVectorField> Foam::touchSolid::initialMomentum
(
    const fvMesh& mesh,
    const mechanicalLaw& law
)
{
    const dimensionSet momentumDims(dimDensity*dimVelocity);

    IOobject lmIO(inputIO(mesh, "lm"));
    IOobject UIO(inputIO(mesh, "U"));
    checkVolumes(mesh);
    const bool haveLm = fieldExists<volVectorField>(lmIO);
    const bool haveU = fieldExists<volVectorField>(UIO);

    // F is read when present (touchSolid's constructor): one of another
    // class would be taken for absent, the identity
    fieldExists<volTensorField>(inputIO(mesh, "F"));

    if (!haveLm && !haveU && mesh.time().value() > 0)
    {
        FatalErrorInFunction
            << "Time folder " << mesh.time().timePath() << " holds neither"
            << " lm nor U: it is incomplete (a run stopped while writing"
            << " it?). touchFoam writes lm, F, gradD, D and pointD at every"
            << " write time." << nl
            << "    Remove it (rm -r " << mesh.time().timeName() << ") to"
            << " restart from the previous write time" << nl
            << exit(FatalError);
    }

    if (!haveLm && !haveU)
    {
        FatalErrorInFunction
            << "No initial state: neither the velocity " << UIO.objectPath()
            << " [m/s] nor the linear momentum " << lmIO.objectPath()
            << " [kg/(m^2 s)] exists." << nl
            << "Write one of them (0/U in a new case; its boundaryField"
            << " carries the solid boundary conditions)" << nl
            << exit(FatalError);
    }

    const scalarField rho(cellDensity(mesh, law));

    if (haveLm)
    {
        checkConditionTypes(mesh, lmIO);
        tmp<volVectorField> tlm(new volVectorField(lmIO, mesh));
        checkDimensions(tlm(), momentumDims, "linear momentum");
        checkConditions(tlm());

        if (haveU)
        {
            // Both: a restart from a time the solver wrote U at as well,
            // or a case set up twice.  They must describe one state; the
            // written digits bound how well they can agree
            const volVectorField U(UIO, mesh);
            checkDimensions(U, dimVelocity, "velocity");

            const vectorField& lm = tlm().primitiveField();
            scalar maxDiff = 0;
            scalar maxLm = 0;
            forAll(lm, celli)
            {
                maxDiff = max(maxDiff, mag(lm[celli] - rho[celli]*U[celli]));
                maxLm = max(maxLm, mag(lm[celli]));
            }
            reduce(maxDiff, maxOp<scalar>());
            reduce(maxLm, maxOp<scalar>());

            const scalar tolerance =
                max(1e-12, pow(10.0, 1 - label(IOstream::defaultPrecision())));

            if (maxDiff > tolerance*maxLm)
            {
                FatalErrorInFunction
                    << "Both " << lmIO.objectPath() << " and "
                    << UIO.objectPath() << " exist and disagree: max |lm -"
                    << " rho U| = " << maxDiff << " kg/(m^2 s), "
                    << (maxLm > 0 ? maxDiff/maxLm : GREAT)
                    << " of max |lm| (allowed " << tolerance << ")." << nl
                    << "Remove one of them: lm is read when present, else U"
                    << nl << exit(FatalError);
            }

            Info<< "touchSolid: initial state: linear momentum "
                << lmIO.objectPath() << "; the velocity U beside it agrees"
                << " (max |lm - rho U|/max |lm| = "
                << (maxLm > 0 ? maxDiff/maxLm : 0) << "), lm is used"
                << endl;
        }
        else
        {
            Info<< "touchSolid: initial state: linear momentum "
                << lmIO.objectPath() << endl;
        }

        return tlm;
    }

    // U only: lm = rho U with U's boundary conditions, the patch values
    // scaled by their cells' density as the internal ones
    checkConditionTypes(mesh, UIO);
    const volVectorField U(UIO, mesh);
    checkDimensions(U, dimVelocity, "velocity");
    checkConditions(U);

    tmp<volVectorField> tlm
    (
        new volVectorField
        (
            IOobject
            (
                "lm",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            U
        )
    );
    volVectorField& lm = tlm.ref();
    lm.dimensions().reset(momentumDims);
    lm.primitiveFieldRef() *= rho;
    forAll(lm.boundaryField(), patchi)
    {
        fvPatchVectorField& pf = lm.boundaryFieldRef()[patchi];
        pf == scalarField(rho, pf.patch().faceCells())*pf;
    }

    Info<< "touchSolid: initial state: velocity " << UIO.objectPath()
        << ", linear momentum lm = rho U" << endl;

    return tlm;
}


template<class GeoField>
Foam::tmp<GeoField> Foam::touchSolid::readDisplacement
(
    const typename GeoField::Mesh& mesh,
    const word& name,
    const word& oldName
)
{
    const objectRegistry& db = mesh.thisDb();

    // Not registered: the state's own field takes the name
    IOobject io
    (
        name, db.time().timeName(), db,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );

    if (!io.typeHeaderOk<GeoField>(true))
    {
        IOobject oldIo
        (
            oldName, db.time().timeName(), db,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );

        if (!oldIo.typeHeaderOk<GeoField>(true))
        {
            io.readOpt() = IOobject::NO_READ;
            return tmp<GeoField>::New
            (
                io,
                mesh,
                dimensionedVector("0", dimLength, Zero),
                GeoField::Patch::calculatedType()
            );
        }

        Info<< "touchSolid: no " << name << " at time "
            << db.time().timeName() << ": the displacement is read from "
            << oldName << ", its former name, and written as " << name
            << endl;

        io = oldIo;
    }

    return tmp<GeoField>::New(io, mesh);
}


// The two displacements the constructor reads (touchSolid.C)
template Foam::tmp<Foam::volVectorField>
Foam::touchSolid::readDisplacement<Foam::volVectorField>
(
    const fvMesh&,
    const word&,
    const word&
);

template Foam::tmp<Foam::pointVectorField>
Foam::touchSolid::readDisplacement<Foam::pointVectorField>
(
    const pointMesh&,
    const word&,
    const word&
);


// ************************************************************************* //
