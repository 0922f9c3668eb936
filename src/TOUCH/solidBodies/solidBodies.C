/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "solidBodies.H"
#include "regionSplit.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- a before b in (x, y, z) order
static inline bool lexicalLess(const point& a, const point& b)
{
    if (a.x() != b.x())
    {
        return a.x() < b.x();
    }
    if (a.y() != b.y())
    {
        return a.y() < b.y();
    }
    return a.z() < b.z();
}

//- Keep the first point in (x, y, z) order (a combine op over the ranks)
struct lexicalMinEqOp
{
    void operator()(point& a, const point& b) const
    {
        if (lexicalLess(b, a))
        {
            a = b;
        }
    }
};

//- The zone of a region: unset, mixed, -1 (no zone) or the zone's index
static const label unsetZone = -3;
static const label mixedZones = -2;

struct zoneEqOp
{
    void operator()(label& a, const label b) const
    {
        if (a == unsetZone)
        {
            a = b;
        }
        else if (b != unsetZone && a != b)
        {
            a = mixedZones;
        }
    }
};

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::solidBodies::orderAndName
(
    const fvMesh& mesh,
    const labelList& region
)
{
    const label nRegions = names_.size();
    const vectorField& C = mesh.C().primitiveField();

    // Each region's first cell centre and its zone, over all ranks
    pointField first(nRegions, point::uniform(GREAT));
    labelList zone(nRegions, unsetZone);
    forAll(region, celli)
    {
        lexicalMinEqOp()(first[region[celli]], C[celli]);
        zoneEqOp()(zone[region[celli]], mesh.cellZones().whichZone(celli));
    }
    Pstream::listCombineGather(first, lexicalMinEqOp());
    Pstream::listCombineScatter(first);
    Pstream::listCombineGather(zone, zoneEqOp());
    Pstream::listCombineScatter(zone);

    labelList order(identity(nRegions));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [&](const label a, const label b)
        {
            return lexicalLess(first[a], first[b]);
        }
    );

    labelList bodyOfRegion(nRegions);
    forAll(order, bodyi)
    {
        bodyOfRegion[order[bodyi]] = bodyi;
    }
    forAll(region, celli)
    {
        cellBody_[celli] = bodyOfRegion[region[celli]];
    }

    // A zone names a body when it is that body's only zone and no other
    // body's cells are in it
    labelList bodiesOfZone(mesh.cellZones().size(), Zero);
    for (const label z : zone)
    {
        if (z >= 0)
        {
            ++bodiesOfZone[z];
        }
    }
    forAll(order, bodyi)
    {
        const label z = zone[order[bodyi]];
        names_[bodyi] =
            (z >= 0 && bodiesOfZone[z] == 1)
          ? mesh.cellZones()[z].name()
          : word("body" + Foam::name(bodyi));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidBodies::solidBodies(const fvMesh& mesh)
:
    cellBody_(mesh.nCells()),
    names_()
{
    // Global region numbers in a decomposed run (regions cut by processor
    // faces are one)
    const regionSplit region(mesh);
    names_.setSize(region.nRegions());

    orderAndName(mesh, region);
}


// ************************************************************************* //
