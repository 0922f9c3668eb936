/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "zoned.H"
#include "fvMesh.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(zoned, 0);
}
}


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const describedEntry materialsEntry
    (
        "constant/mechanicalProperties", "materials",
        "one law per cellZone, instead of the single law's entries: a"
        " sub-dictionary per zone holding a single law's entries (model,"
        " rho, E, nu, the model's Coeffs); every cell in exactly one listed"
        " zone",
        "-", "none (one law: model, rho, E, nu)",
        "{ steel { model linearElastic; rho 7800; E 200e9; nu 0.3; } }"
    );
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

const Foam::word& Foam::mechanicalLaws::zoned::materialsKeyword()
{
    return materialsEntry.name();
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- At most the first ten labels of a list, for a message
static labelList firstLabels(const labelUList& labels)
{
    return labelList(SubList<label>(labels, min(labels.size(), label(10))));
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::tmp<Foam::volTensorField> Foam::mechanicalLaws::zoned::zoneF
(
    const volTensorField& F,
    const label m
) const
{
    auto tFm = tmp<volTensorField>::New
    (
        IOobject
        (
            F.name() + '.' + zoneNames_[m],
            F.instance(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        F
    );

    tensorField& Fm = tFm.ref().primitiveFieldRef();
    Fm = tensor::I;
    for (const label celli : zoneCells_[m])
    {
        Fm[celli] = F[celli];
    }

    return tFm;
}


void Foam::mechanicalLaws::zoned::copyZone
(
    const label m,
    const tensorField& Pm,
    tensorField& P
) const
{
    for (const label celli : zoneCells_[m])
    {
        P[celli] = Pm[celli];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaws::zoned::zoned
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    // No single material: rho(), Up(), Us() refuse (the callers take the
    // cell's); the base's E and nu are placeholders nobody reads
    mechanicalLaw(mesh, dict, 1, 1, 0),
    zoneNames_(),
    laws_(),
    zoneCells_()
{
    const dictionary& materials = subDict(materialsEntry.name());
    const cellZoneMesh& zones = mesh.cellZones();

    labelList count(mesh.nCells(), Zero);
    cellMaterial_.setSize(mesh.nCells(), -1);

    for (const entry& e : materials)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(materials)
                << "Entry '" << e.keyword() << "' of '"
                << materialsEntry.name() << "' is not a sub-dictionary:"
                << " each cellZone's law is one, e.g. " << e.keyword()
                << " { model linearElastic; rho 7800; E 200e9; nu 0.3; }"
                << nl << "The mesh's cellZones: " << zones.names()
                << exit(FatalIOError);
        }

        const word& zoneName = e.keyword();
        const label zonei = zones.findZoneID(zoneName);

        if (zonei < 0)
        {
            FatalIOErrorInFunction(materials)
                << "Entry '" << materialsEntry.name() << "': '" << zoneName
                << "' is not a cellZone of the mesh" << nl
                << "The mesh's cellZones: " << zones.names()
                << exit(FatalIOError);
        }

        if (e.dict().found(materialsEntry.name()))
        {
            FatalIOErrorInFunction(e.dict())
                << "Entry '" << materialsEntry.name() << "' inside the"
                << " material of zone '" << zoneName << "': materials do not"
                << " nest" << exit(FatalIOError);
        }

        const label m = laws_.size();

        zoneNames_.append(zoneName);
        laws_.append(mechanicalLaw::New(mesh, e.dict()));
        zoneCells_.append(zones[zonei]);

        for (const label celli : zones[zonei])
        {
            ++count[celli];
            cellMaterial_[celli] = m;
        }

    }

    if (laws_.empty())
    {
        FatalIOErrorInFunction(materials)
            << "Entry '" << materialsEntry.name() << "' lists no material"
            << nl << "The mesh's cellZones: " << zones.names()
            << exit(FatalIOError);
    }

    // Every cell in exactly one listed zone
    DynamicList<label> uncovered;
    DynamicList<label> overlapping;
    forAll(count, celli)
    {
        if (count[celli] == 0)
        {
            uncovered.append(celli);
        }
        else if (count[celli] > 1)
        {
            overlapping.append(celli);
        }
    }

    const label nUncovered = returnReduce(uncovered.size(), sumOp<label>());
    const label nOverlapping =
        returnReduce(overlapping.size(), sumOp<label>());

    if (nUncovered || nOverlapping)
    {
        FatalIOErrorInFunction(materials)
            << "Entry '" << materialsEntry.name() << "' must give every cell"
            << " exactly one material (one listed cellZone): "
            << nUncovered << " cells are in no listed zone"
            << (uncovered.size() ? ", e.g. cells " : "")
            << (uncovered.size() ? firstLabels(uncovered) : labelList())
            << ", " << nOverlapping << " in more than one"
            << (overlapping.size() ? ", e.g. cells " : "")
            << (overlapping.size() ? firstLabels(overlapping) : labelList())
            << nl << "The listed zones: " << zoneNames_
            << nl << "The mesh's cellZones: " << zones.names()
            << exit(FatalIOError);
    }

    const label nMat = laws_.size();
    materialRho_.setSize(nMat);
    materialUp_.setSize(nMat);
    materialUs_.setSize(nMat);
    forAll(laws_, m)
    {
        materialRho_[m] = laws_[m].materialRho(0);
        materialUp_[m] = laws_[m].materialUp(0);
        materialUs_[m] = laws_[m].materialUs(0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mechanicalLaws::zoned::writeConstants(Ostream& os) const
{
    os  << type() << ", " << laws_.size() << " materials";
    forAll(laws_, m)
    {
        os  << nl << "        zone " << zoneNames_[m] << " ("
            << returnReduce(zoneCells_[m].size(), sumOp<label>())
            << " cells): ";
        laws_[m].writeConstants(os);
        os  << "; Up " << materialUp_[m] << ", Us " << materialUs_[m]
            << ", rho Up " << materialRho_[m]*materialUp_[m];
    }
}


Foam::tensor Foam::mechanicalLaws::zoned::P(const tensor&) const
{
    FatalErrorInFunction
        << "A law of several materials has no pointwise stress: the"
        << " caller must take the law of the cell's zone"
        << abort(FatalError);

    return tensor::zero;
}


Foam::scalar Foam::mechanicalLaws::zoned::strainEnergy(const tensor&) const
{
    FatalErrorInFunction
        << "A law of several materials has no pointwise energy: the"
        << " caller must take the law of the cell's zone"
        << abort(FatalError);

    return 0;
}


void Foam::mechanicalLaws::zoned::stress
(
    const tensorField& F,
    tensorField& P
) const
{
    stress(F, F - tensor::I, P);
}


void Foam::mechanicalLaws::zoned::stress
(
    const tensorField& F,
    const tensorField& gradD,
    tensorField& P
) const
{
    forAll(laws_, m)
    {
        const mechanicalLaw& law = laws_[m];

        if (law.hasState())
        {
            tensorField Fm(F.size(), tensor::I);
            for (const label celli : zoneCells_[m])
            {
                Fm[celli] = F[celli];
            }
            tensorField Pm(F.size());
            law.stress(Fm, Pm);
            copyZone(m, Pm, P);
        }
        else
        {
            for (const label celli : zoneCells_[m])
            {
                P[celli] = law.P(F[celli], gradD[celli]);
            }
        }
    }
}


void Foam::mechanicalLaws::zoned::correct
(
    const volTensorField& F,
    volTensorField& P
)
{
    correct(F, F.primitiveField() - tensor::I, P);
}


void Foam::mechanicalLaws::zoned::correct
(
    const volTensorField& F,
    const tensorField& gradD,
    volTensorField& P
)
{
    tensorField& PI = P.primitiveFieldRef();

    forAll(laws_, m)
    {
        mechanicalLaw& law = laws_[m];

        if (law.hasState())
        {
            volTensorField Pm
            (
                IOobject
                (
                    P.name() + '.' + zoneNames_[m],
                    P.instance(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                P
            );
            law.correct(zoneF(F, m)(), Pm);
            copyZone(m, Pm.primitiveField(), PI);
        }
        else
        {
            const tensorField& FI = F.primitiveField();
            for (const label celli : zoneCells_[m])
            {
                PI[celli] = law.P(FI[celli], gradD[celli]);
            }
        }
    }

    // The processor values exchanged, as the single law does
    P.correctBoundaryConditions();
}


Foam::scalar Foam::mechanicalLaws::zoned::totalStrainEnergy
(
    const volTensorField& F
) const
{
    return totalStrainEnergy(F, F.primitiveField() - tensor::I);
}


Foam::scalar Foam::mechanicalLaws::zoned::totalStrainEnergy
(
    const volTensorField& F,
    const tensorField& gradD
) const
{
    const scalarField& V = mesh_.V();
    scalar withState = 0;
    scalar local = 0;

    forAll(laws_, m)
    {
        const mechanicalLaw& law = laws_[m];

        if (law.hasState())
        {
            // Reduced by the law; zero outside its zone (identity F)
            withState += law.totalStrainEnergy(zoneF(F, m)());
        }
        else
        {
            for (const label celli : zoneCells_[m])
            {
                local += V[celli]*law.strainEnergy(F[celli], gradD[celli]);
            }
        }
    }

    return withState + returnReduce(local, sumOp<scalar>());
}


void Foam::mechanicalLaws::zoned::cellStrainEnergy
(
    const volTensorField& F,
    scalarField& energy
) const
{
    cellStrainEnergy(F, F.primitiveField() - tensor::I, energy);
}


void Foam::mechanicalLaws::zoned::cellStrainEnergy
(
    const volTensorField& F,
    const tensorField& gradD,
    scalarField& energy
) const
{
    const scalarField& V = mesh_.V();
    scalarField zoneEnergy;

    forAll(laws_, m)
    {
        const mechanicalLaw& law = laws_[m];

        if (law.hasState())
        {
            // The law's state covers the mesh: its cells of the zone
            zoneEnergy.setSize(V.size());
            law.cellStrainEnergy(zoneF(F, m)(), zoneEnergy);
            for (const label celli : zoneCells_[m])
            {
                energy[celli] = zoneEnergy[celli];
            }
        }
        else
        {
            for (const label celli : zoneCells_[m])
            {
                energy[celli] =
                    V[celli]*law.strainEnergy(F[celli], gradD[celli]);
            }
        }
    }
}


bool Foam::mechanicalLaws::zoned::dissipates() const
{
    for (const mechanicalLaw& law : laws_)
    {
        if (law.dissipates())
        {
            return true;
        }
    }
    return false;
}


void Foam::mechanicalLaws::zoned::addPlasticWork(scalarField& work) const
{
    // A law's state covers the mesh, with no flow outside its zone (F = I
    // there)
    for (const mechanicalLaw& law : laws_)
    {
        law.addPlasticWork(work);
    }
}


bool Foam::mechanicalLaws::zoned::hasState() const
{
    for (const mechanicalLaw& law : laws_)
    {
        if (law.hasState())
        {
            return true;
        }
    }
    return false;
}


void Foam::mechanicalLaws::zoned::storeOldTime()
{
    for (mechanicalLaw& law : laws_)
    {
        law.storeOldTime();
    }
}


void Foam::mechanicalLaws::zoned::advanceStage(const scalar alpha)
{
    for (mechanicalLaw& law : laws_)
    {
        law.advanceStage(alpha);
    }
}


void Foam::mechanicalLaws::zoned::commitStep(const volTensorField& F)
{
    forAll(laws_, m)
    {
        if (laws_[m].hasState())
        {
            laws_[m].commitStep(zoneF(F, m)());
        }
    }
}


void Foam::mechanicalLaws::zoned::restoreOldTime()
{
    for (mechanicalLaw& law : laws_)
    {
        law.restoreOldTime();
    }
}


// ************************************************************************* //
