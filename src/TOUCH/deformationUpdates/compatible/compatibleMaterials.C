/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update with several materials (one law per cellZone,
    mechanicalLaws::zoned): the point velocities from the cells' velocities
    (each cell's own density) and the points' mobilities from the
    impedances around them (compatible.H); the face loop in velocity with
    the two sides' impedances is compatibleFaceRates.C's
    addFaceRatesOfMaterials (it shares the face loop's inline functions).
    One material takes the paths of compatibleFaceRates.C, which do none of
    this arithmetic.

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::interpolateVelocity
(
    vectorField& pointV
)
{
    // Each cell's velocity, with the neighbour ranks' across processor
    // patches; velocity, not momentum, is continuous across a material
    // interface
    const volVectorField& lm = faces_.lm();

    volVectorField v
    (
        IOobject
        (
            "cellVelocity",
            lm.instance(),
            faces_.mesh(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        faces_.mesh(),
        dimensionedVector("0", dimVelocity, Zero),
        calculatedFvPatchVectorField::typeName
    );

    v.primitiveFieldRef() = lm.primitiveField()/law_.cellRho();
    v.correctBoundaryConditions();

    pointInterpolation_.interpolate(v, 1, pointV);
}


Foam::scalarField
Foam::deformationUpdates::compatible::calcPointMobilityOfMaterials
(
    const linearReconstruction& reconstruction,
    const scalar coefficient
) const
{
    if (!(coefficient > 0))
    {
        return scalarField();
    }

    // As calcPointMobility with 2 Z S_a replaced by the sum of the two
    // sides' impedances over the point's face shares: a traction jump
    // [[t]] across an interface moves the contact at [[t]]/(Z_L + Z_R)
    const fvMesh& mesh = faces_.mesh();
    const faceList& faces = mesh.faces();
    const vectorField& Sf = mesh.faceAreas();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();

    auto Z = [&](const label m)
    {
        return law_.materialRho(m)*law_.materialUp(m);
    };

    scalarField impedanceArea(mesh.nPoints(), Zero);

    forAll(faces, facei)
    {
        scalar share = 1.0/(3*faces[facei].size());
        scalar impedances;

        if (mesh.isInternalFace(facei))
        {
            impedances =
                Z(law_.material(own[facei])) + Z(law_.material(nei[facei]));
        }
        else
        {
            const label patchi = mesh.boundaryMesh().whichPatch(facei);
            const label mL = law_.material(own[facei]);

            if (mesh.boundary()[patchi].coupled())
            {
                share *= 0.5;
                impedances = Z(mL) + Z(rightMaterial(facei, -1));
            }
            else
            {
                if (reconstruction.mirror(patchi))
                {
                    share *= 0.5;
                }
                impedances = 2*Z(mL);
            }
        }

        for (const label pointi : faces[facei])
        {
            impedanceArea[pointi] += share*impedances*mag(Sf[facei]);
        }
    }

    syncTools::syncPointList
    (
        mesh, impedanceArea, plusEqOp<scalar>(), scalar(0)
    );

    return coefficient/impedanceArea;
}


// ************************************************************************* //
