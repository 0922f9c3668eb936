/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "cellVolume.H"
#include "mechanicalLaw.H"
#include "facePointShares.H"
#include "pointFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace nodalAveragings
{
    defineTypeNameAndDebug(cellVolume, 0);
    addToRunTimeSelectionTable(nodalAveraging, cellVolume, mesh);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Apply op(face, sign) to each face of cell celli, sign +1 where the
//  face's area vector points out of it
template<class Op>
void forAllCellFaces(const Foam::fvMesh& mesh, const Foam::label celli, Op op)
{
    for (const Foam::label facei : mesh.cells()[celli])
    {
        op(mesh.faces()[facei], mesh.faceOwner()[facei] == celli ? 1.0 : -1.0);
    }
}


//- Six times the volume of cell celli (faces split about the mean of their
//  points, positions taken from the cell's first point against round-off)
//  and, with a non-null grad, w times its derivative by each point added
Foam::scalar sixVolume
(
    const Foam::fvMesh& mesh,
    const Foam::label celli,
    const Foam::pointField& x,
    const Foam::scalar w,
    Foam::vectorField* grad
)
{
    using namespace Foam;

    const point origin(x[mesh.faces()[mesh.cells()[celli][0]][0]]);
    scalar v6 = 0;

    forAllCellFaces
    (
        mesh, celli,
        [&](const face& f, const scalar sign)
        {
            const label n = f.size();
            vector c(Zero);
            for (const label pointi : f)
            {
                c += x[pointi] - origin;
            }
            c /= n;

            vector cGrad(Zero);
            forAll(f, fp)
            {
                const label i = f[fp];
                const label j = f.fcIndex(fp);
                const vector ri(x[i] - origin);
                const vector rj(x[f[j]] - origin);
                const vector rij(ri ^ rj);

                v6 += sign*(c & rij);

                if (grad)
                {
                    // d(c . ri x rj) by ri, rj and, through c, every point
                    const scalar ws = w*sign/6;
                    (*grad)[i] += ws*(rj ^ c);
                    (*grad)[f[j]] += ws*(c ^ ri);
                    cGrad += (ws/n)*rij;
                }
            }

            if (grad)
            {
                for (const label pointi : f)
                {
                    (*grad)[pointi] += cGrad;
                }
            }
        }
    );

    return v6;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::tmp<Foam::pointField>
Foam::nodalAveragings::cellVolume::currentPoints() const
{
    tmp<pointField> tx(new pointField(mesh_.points()));

    if (mesh_.foundObject<pointVectorField>("pointD"))
    {
        tx.ref() +=
            mesh_.lookupObject<pointVectorField>("pointD").primitiveField();
    }

    return tx;
}


Foam::tmp<Foam::scalarField> Foam::nodalAveragings::cellVolume::volumes
(
    const pointField& x
) const
{
    tmp<scalarField> tv(new scalarField(mesh_.nCells()));
    scalarField& v = tv.ref();

    forAll(v, celli)
    {
        v[celli] = sixVolume(mesh_, celli, x, 0, nullptr)/6;
    }

    return tv;
}


Foam::tmp<Foam::tensorField>
Foam::nodalAveragings::cellVolume::meanDilatation
(
    const tensorField& F,
    const pointField& x
) const
{
    const scalarField J(volumes(x)/referenceVolume_);

    tmp<tensorField> tFbar(new tensorField(F.size()));
    tensorField& Fbar = tFbar.ref();

    forAll(Fbar, celli)
    {
        Fbar[celli] = cbrt(J[celli]/det(F[celli]))*F[celli];
    }

    return tFbar;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nodalAveragings::cellVolume::cellVolume(const fvMesh& mesh)
:
    nodalAveraging(mesh),
    referenceVolume_(volumes(mesh.points())),
    weight_(mesh.nCells(), Zero),
    cofactorStress_(mesh.nCells(), Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::nodalAveragings::cellVolume::suits
(
    const mechanicalLaw& law
) const
{
    return !law.hasState();
}


void Foam::nodalAveragings::cellVolume::correct
(
    const mechanicalLaw& law,
    const tensorField& F,
    tensorField& P
) const
{
    const pointField x(currentPoints());
    const scalarField J(volumes(x)/referenceVolume_);
    const scalarField& V = mesh_.V();

    tensorField Fbar(F.size());
    forAll(Fbar, celli)
    {
        Fbar[celli] = cbrt(J[celli]/det(F[celli]))*F[celli];
    }

    tensorField Pbar(F.size());
    law.stress(Fbar, Pbar);

    forAll(P, celli)
    {
        const tensor& Fi = F[celli];
        const scalar a = cbrt(J[celli]/det(Fi));
        const scalar PF = Pbar[celli] && Fi;
        const tensor cofF(cof(Fi));
        const tensor invFT(cofF/det(Fi));

        // P_dev, work conjugate to dF/dt at fixed J, and the mean Cauchy
        // stress, conjugate to dJ/dt
        const scalar sigma = a*PF/(3*J[celli]);
        const tensor Pdev(a*(Pbar[celli] - (PF/3)*invFT));

        cofactorStress_[celli] = sigma*cofF;
        weight_[celli] = sigma*V[celli]/referenceVolume_[celli];
        P[celli] = Pdev + cofactorStress_[celli];
    }
}


void Foam::nodalAveragings::cellVolume::addPointForces
(
    const facePointShares& shares,
    vectorField& pointForce
) const
{
    const pointField x(currentPoints());

    // sigma (V_e/v_e(X)) dv_e/dx_a of every cell
    forAll(weight_, celli)
    {
        sixVolume(mesh_, celli, x, weight_[celli], &pointForce);
    }

    // Less what the cofactor part of P gives through the faces: the same
    // shares and faces as the compatible update's nodal forces
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const faceList& faces = mesh_.faces();
    const tensorField& Q = cofactorStress_;

    forAll(nei, facei)
    {
        const tensor QJump(Q[own[facei]] - Q[nei[facei]]);
        shares.forAllPoints
        (
            faces[facei], facei, Sf[facei],
            [&](const label pointi, const vector& s)
            {
                pointForce[pointi] -= QJump & s;
            }
        );
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& faceCells = patch.faceCells();
        forAll(faceCells, i)
        {
            const label facei = patch.start() + i;
            const tensor& Qi = Q[faceCells[i]];
            shares.forAllPoints
            (
                faces[facei], facei, Sf[facei],
                [&](const label pointi, const vector& s)
                {
                    pointForce[pointi] -= Qi & s;
                }
            );
        }
    }
}


Foam::scalar Foam::nodalAveragings::cellVolume::totalStrainEnergy
(
    const mechanicalLaw& law,
    const volTensorField& F
) const
{
    volTensorField Fbar("Fbar", F);
    Fbar.primitiveFieldRef() =
        meanDilatation(F.primitiveField(), currentPoints());

    return law.totalStrainEnergy(Fbar);
}


// ************************************************************************* //
