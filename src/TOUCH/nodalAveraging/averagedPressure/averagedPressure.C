/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "averagedPressure.H"
#include "mechanicalLaw.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace nodalAveragings
{
    defineTypeNameAndDebug(averagedPressure, 0);
    addToRunTimeSelectionTable(nodalAveraging, averagedPressure, mesh);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::nodalAveragings::averagedPressure::volumeRatios
(
    const tensorField& F
) const
{
    forAll(cellJ_, celli)
    {
        cellJ_[celli] = det(F[celli]);
    }

    averageToPoints(cellJ_, pointJ_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nodalAveragings::averagedPressure::averagedPressure(const fvMesh& mesh)
:
    nodalAveraging(mesh),
    cellJ_(mesh.nCells()),
    pointJ_(mesh.nPoints()),
    pointPressure_(mesh.nPoints())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::nodalAveragings::averagedPressure::suits
(
    const mechanicalLaw& law
) const
{
    return law.hasVolumetricPart();
}


void Foam::nodalAveragings::averagedPressure::correct
(
    const mechanicalLaw& law,
    const tensorField& F,
    tensorField& P
) const
{
    volumeRatios(F);

    forAll(pointJ_, pointi)
    {
        pointPressure_[pointi] = law.volumetricStress(pointJ_[pointi]);
    }

    forAll(P, celli)
    {
        P[celli] +=
            (
                cellMean(celli, pointPressure_)
              - law.volumetricStress(cellJ_[celli])
            )
           *cof(F[celli]);
    }
}


Foam::scalar Foam::nodalAveragings::averagedPressure::totalStrainEnergy
(
    const mechanicalLaw& law,
    const volTensorField& F
) const
{
    volumeRatios(F.primitiveField());

    const scalarField& V = mesh_.V();
    scalar cellVolumetric = 0;
    forAll(cellJ_, celli)
    {
        cellVolumetric += V[celli]*law.volumetricEnergy(cellJ_[celli]);
    }

    scalarField pointU(pointJ_.size());
    forAll(pointU, pointi)
    {
        pointU[pointi] = law.volumetricEnergy(pointJ_[pointi]);
    }

    return
        law.totalStrainEnergy(F)
      - returnReduce(cellVolumetric, sumOp<scalar>())
      + pointIntegral(pointU);
}


// ************************************************************************* //
