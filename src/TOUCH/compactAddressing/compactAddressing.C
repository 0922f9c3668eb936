/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "compactAddressing.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(compactAddressing, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::compactAddressing::rows::rows(const labelUList& sizes)
:
    offsets_(sizes.size() + 1),
    labels_()
{
    offsets_[0] = 0;
    forAll(sizes, i)
    {
        offsets_[i + 1] = offsets_[i] + sizes[i];
    }
    labels_.setSize(offsets_.last());
}


Foam::labelList Foam::compactAddressing::rows::sizes() const
{
    labelList n(size());
    forAll(n, i)
    {
        n[i] = offsets_[i + 1] - offsets_[i];
    }
    return n;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::compactAddressing::rows Foam::compactAddressing::calcCellFaces
(
    const polyMesh& mesh
)
{
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();

    labelList n(mesh.nCells(), Zero);
    forAll(own, facei)
    {
        ++n[own[facei]];
    }
    forAll(nei, facei)
    {
        ++n[nei[facei]];
    }

    rows cf(n);

    // Faces in ascending order: each cell's row fills as the faces go by
    n = Zero;
    forAll(own, facei)
    {
        const label o = own[facei];
        cf.rowStart(o)[n[o]++] = facei;

        if (facei < nei.size())
        {
            const label c = nei[facei];
            cf.rowStart(c)[n[c]++] = facei;
        }
    }

    return cf;
}


Foam::compactAddressing::rows Foam::compactAddressing::calcCellPoints
(
    const polyMesh& mesh,
    const rows& cf
)
{
    const faceList& faces = mesh.faces();

    // The distinct points of a cell's faces, sorted; sized in a first pass
    DynamicList<label> points(32);
    auto collect = [&](const label celli)
    {
        points.clear();
        for (const label facei : cf[celli])
        {
            for (const label pointi : faces[facei])
            {
                points.append(pointi);
            }
        }
        Foam::sort(points);
        label nUnique = 0;
        forAll(points, i)
        {
            if (i == 0 || points[i] != points[i - 1])
            {
                points[nUnique++] = points[i];
            }
        }
        points.setSize(nUnique);
    };

    labelList n(cf.size());
    forAll(n, celli)
    {
        collect(celli);
        n[celli] = points.size();
    }

    rows cp(n);
    forAll(n, celli)
    {
        collect(celli);
        std::copy(points.cbegin(), points.cend(), cp.rowStart(celli));
    }

    return cp;
}


Foam::compactAddressing::rows Foam::compactAddressing::calcPointCells
(
    const label nPoints,
    const rows& cp
)
{
    labelList n(nPoints, Zero);
    for (label celli = 0; celli < cp.size(); ++celli)
    {
        for (const label pointi : cp[celli])
        {
            ++n[pointi];
        }
    }

    rows pc(n);

    n = Zero;
    for (label celli = 0; celli < cp.size(); ++celli)
    {
        for (const label pointi : cp[celli])
        {
            pc.rowStart(pointi)[n[pointi]++] = celli;
        }
    }

    return pc;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::compactAddressing::compactAddressing(const fvMesh& mesh)
:
    MeshObject<fvMesh, TopologicalMeshObject, compactAddressing>(mesh),
    cellFaces_(calcCellFaces(mesh)),
    cellPoints_(calcCellPoints(mesh, cellFaces_)),
    pointCells_(calcPointCells(mesh.nPoints(), cellPoints_))
{}


// ************************************************************************* //
