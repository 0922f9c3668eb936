/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "nodalAveraging.H"
#include "mechanicalLaw.H"
#include "syncTools.H"

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


void Foam::nodalAveraging::averageToPoints(const tensorField& F) const
{
    const scalarField& V = mesh_.V();
    const labelListList& cellPoints = mesh_.cellPoints();

    pointF_ = Zero;

    forAll(cellPoints, celli)
    {
        const tensor share((V[celli]/cellPoints[celli].size())*F[celli]);

        for (const label pointi : cellPoints[celli])
        {
            pointF_[pointi] += share;
        }
    }

    syncTools::syncPointList(mesh_, pointF_, plusEqOp<tensor>(), tensor::zero);

    pointF_ /= pointVolume_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nodalAveraging::nodalAveraging(const fvMesh& mesh)
:
    mesh_(mesh),
    pointVolume_(calcPointVolume(mesh)),
    pointShare_(calcPointShare(mesh)),
    pointF_(mesh.nPoints()),
    pointP_(mesh.nPoints())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::nodalAveraging::stress
(
    const mechanicalLaw& law,
    const tensorField& F,
    tensorField& P
) const
{
    averageToPoints(F);
    law.stress(pointF_, pointP_);

    const labelListList& cellPoints = mesh_.cellPoints();

    forAll(cellPoints, celli)
    {
        const labelList& points = cellPoints[celli];

        tensor sum(Zero);
        for (const label pointi : points)
        {
            sum += pointP_[pointi];
        }

        P[celli] = sum/points.size();
    }
}


Foam::scalar Foam::nodalAveraging::totalStrainEnergy
(
    const mechanicalLaw& law,
    const tensorField& F
) const
{
    averageToPoints(F);

    scalar energy = 0;

    forAll(pointF_, pointi)
    {
        energy +=
            pointShare_[pointi]*pointVolume_[pointi]
           *law.strainEnergy(pointF_[pointi]);
    }

    return returnReduce(energy, sumOp<scalar>());
}


Foam::label Foam::nodalAveraging::nTetrahedra(const fvMesh& mesh)
{
    // A closed cell of four faces is a tetrahedron
    label n = 0;
    for (const cell& c : mesh.cells())
    {
        if (c.size() == 4)
        {
            ++n;
        }
    }

    return n;
}


// ************************************************************************* //
