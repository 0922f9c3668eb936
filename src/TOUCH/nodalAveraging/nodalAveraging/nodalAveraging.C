/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "nodalAveraging.H"
#include "syncTools.H"
#include "compactAddressing.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(nodalAveraging, 0);
    defineRunTimeSelectionTable(nodalAveraging, mesh);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalarField Foam::nodalAveraging::calcPointVolume(const fvMesh& mesh)
{
    const scalarField& V = mesh.V();
    const labelListList& cellPoints = mesh.cellPoints();

    scalarField pointVolume(mesh.nPoints(), Zero);

    forAll(cellPoints, celli)
    {
        const scalar share = V[celli]/cellPoints[celli].size();

        for (const label pointi : cellPoints[celli])
        {
            pointVolume[pointi] += share;
        }
    }

    syncTools::syncPointList(mesh, pointVolume, plusEqOp<scalar>(), scalar(0));

    return pointVolume;
}


Foam::scalarField Foam::nodalAveraging::calcPointShare(const fvMesh& mesh)
{
    scalarField count(mesh.nPoints(), scalar(1));

    syncTools::syncPointList(mesh, count, plusEqOp<scalar>(), scalar(0));

    return 1/count;
}


Foam::label Foam::nodalAveraging::nTetrahedra(const fvMesh& mesh)
{
    // A closed cell of four faces is a tetrahedron
    label n = 0;
    for (const label nFaces : compactAddressing::New(mesh).cellFaces().sizes())
    {
        if (nFaces == 4)
        {
            ++n;
        }
    }

    return returnReduce(n, sumOp<label>());
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::nodalAveraging::pointIntegral(const scalarField& q) const
{
    scalar sum = 0;

    forAll(q, pointi)
    {
        sum += pointShare_[pointi]*pointVolume_[pointi]*q[pointi];
    }

    return returnReduce(sum, sumOp<scalar>());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nodalAveraging::nodalAveraging(const fvMesh& mesh)
:
    mesh_(mesh),
    pointVolume_(calcPointVolume(mesh)),
    pointShare_(calcPointShare(mesh))
{}


// ************************************************************************* //
