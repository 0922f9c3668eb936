/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "averagedDeformation.H"
#include "mechanicalLaw.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace nodalAveragings
{
    defineTypeNameAndDebug(averagedDeformation, 0);
    addToRunTimeSelectionTable(nodalAveraging, averagedDeformation, mesh);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nodalAveragings::averagedDeformation::averagedDeformation
(
    const fvMesh& mesh
)
:
    nodalAveraging(mesh),
    pointF_(mesh.nPoints()),
    pointP_(mesh.nPoints())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::nodalAveragings::averagedDeformation::suits
(
    const mechanicalLaw& law
) const
{
    return !law.hasState();
}


void Foam::nodalAveragings::averagedDeformation::correct
(
    const mechanicalLaw& law,
    const tensorField& F,
    tensorField& P
) const
{
    averageToPoints(F, pointF_);
    law.stress(pointF_, pointP_);

    forAll(P, celli)
    {
        P[celli] = cellMean(celli, pointP_);
    }
}


Foam::scalar Foam::nodalAveragings::averagedDeformation::totalStrainEnergy
(
    const mechanicalLaw& law,
    const volTensorField& F
) const
{
    averageToPoints(F.primitiveField(), pointF_);

    scalarField psi(pointF_.size());
    forAll(psi, pointi)
    {
        psi[pointi] = law.strainEnergy(pointF_[pointi]);
    }

    return pointIntegral(psi);
}


// ************************************************************************* //
