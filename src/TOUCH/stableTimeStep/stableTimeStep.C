/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "stableTimeStep.H"
#include "declaredEntry.H"
#include "mathematicalConstants.H"
#include "compactAddressing.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Smallest eigenvalue of a symmetric tensor, by the trigonometric solution
//  of the characteristic cubic (Smith, Comm. ACM 4 (1961) 168), which stays
//  real for repeated roots where a general cubic solver reports complex ones
static inline scalar minEigenValue(const symmTensor& A)
{
    const scalar q = tr(A)/3;
    const scalar p1 = sqr(A.xy()) + sqr(A.xz()) + sqr(A.yz());
    const scalar p2 =
        sqr(A.xx() - q) + sqr(A.yy() - q) + sqr(A.zz() - q) + 2*p1;
    const scalar p = Foam::sqrt(p2/6);

    if (p <= SMALL*mag(q))
    {
        return q;
    }

    const scalar r = det((A - q*symmTensor::I)/p)/2;
    const scalar phi = Foam::acos(min(max(r, scalar(-1)), scalar(1)))/3;

    return q + 2*p*Foam::cos(phi + constant::mathematical::twoPi/3);
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<scalar> CFLEntry
    (
        "system/fvSolution TOUCH", "CFL",
        "Courant number: dt = CFL min over cells of h/Up (h the cell's"
        " current height between opposite faces)",
        "-", 0.3, entryLimits::between(0, 1, false, true),
        declaredEntry<scalar>::required
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::stableTimeStep::readCFL(const dictionary& controls)
{
    return CFLEntry.read(controls);
}


Foam::scalarField Foam::stableTimeStep::calcCellLengths
(
    const solidFaces& faces
)
{
    const fvMesh& mesh = faces.mesh();
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& X = mesh.C().primitiveField();

    // The distance between neighbouring centres normal to their face:
    // the cell size for hexahedra, the inscribed scale for tetrahedra; at
    // a boundary twice the distance of the centre from the face.  A cell
    // takes the smallest of its faces'
    scalarField h(mesh.nCells(), GREAT);

    faces.forAllCoupled
    (
        [&](const solidFaces::coupledFace& face)
        {
            const scalar hf = mag((face.right.X - face.left.X) & face.N());
            h[face.owner] = min(h[face.owner], hf);
            if (face.neighbour >= 0)
            {
                h[face.neighbour] = min(h[face.neighbour], hf);
            }
        }
    );

    for (const fvPatch& patch : mesh.boundary())
    {
        if (!patch.coupled())
        {
            forAll(patch.faceCells(), i)
            {
                const label facei = patch.start() + i;
                const label celli = patch.faceCells()[i];
                const vector N(Sf[facei]/mag(Sf[facei]));
                h[celli] = min(h[celli], 2*mag((Cf[facei] - X[celli]) & N));
            }
        }
    }

    return h;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stableTimeStep::stableTimeStep
(
    const dictionary& controls,
    const solidFaces& faces,
    const mechanicalLaw& law
)
:
    CFL_(readCFL(controls)),
    hCell_(calcCellLengths(faces)),
    hMin_(gMin(hCell_)),
    Up_(law.maxUp()),
    upRatio_(),
    faces_(faces),
    heightPatch_(faces.mesh().boundary().size())
{
    forAll(faces.mesh().boundary(), patchi)
    {
        heightPatch_[patchi] = faces.mesh().boundary()[patchi].size() > 0;
    }

    // Several materials: a cell's heights count as h Up_max/Up_cell, so
    // that the smallest is the one whose wave crossing is the shortest
    if (!law.uniformMaterial())
    {
        upRatio_.setSize(faces.mesh().nCells());
        forAll(upRatio_, celli)
        {
            upRatio_[celli] = Up_/law.Up(celli);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::stableTimeStep::deltaT(const volTensorField& F) const
{
    const fvMesh& mesh = faces_.mesh();
    const linearReconstruction& reconstruction = faces_.reconstruction();
    const compactAddressing::rows& cellFaces =
        compactAddressing::New(mesh).cellFaces();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const label nInternal = mesh.nInternalFaces();
    const labelList& patchID = mesh.boundaryMesh().patchID();
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& X = reconstruction.X();

    // The smallest current height of any cell: with s = d & S_f for the
    // centres' offset d across face f, h_f = |s|/|S_f| and |F^-T N_f| =
    // |H S_f|/(J |S_f|), so height^2 = min(J, 1)^2 s^2/|H S_f|^2 (no root
    // and no division a face)
    scalar crossing = GREAT;
    scalar crossingSqr = sqr(crossing);
    const bool uniform = upRatio_.empty();

    forAll(F, celli)
    {
        const tensor& Fc = F[celli];
        const scalar ratio = uniform ? 1 : upRatio_[celli];
        const scalar h = ratio*hCell_[celli];
        const scalar J = det(Fc);
        const symmTensor C(symm(Fc.T() & Fc));

        // Gershgorin's lower bound of lambda_min^2: a cell that it puts
        // above the smallest height so far cannot lower it
        const scalar lowest =
            min
            (
                C.xx() - mag(C.xy()) - mag(C.xz()),
                min
                (
                    C.yy() - mag(C.xy()) - mag(C.yz()),
                    C.zz() - mag(C.xz()) - mag(C.yz())
                )
            );
        if
        (
            J > 0
         && lowest > 0
         && sqr(h)*lowest >= crossingSqr*sqr(max(J, scalar(1)))
        )
        {
            continue;
        }

        if (!(J > 0))
        {
            // Inverted or degenerate (caught as invalid by the stage): the
            // stretch alone
            const scalar minStretch =
                Foam::sqrt(max(minEigenValue(C), scalar(0)));
            crossing = min(crossing, h*minStretch);
            crossingSqr = sqr(crossing);
            continue;
        }

        const tensor H(cof(Fc));
        const scalar credit = sqr(min(J, scalar(1)));

        for (const label facei : cellFaces[celli])
        {
            scalar s;
            if (facei < nInternal)
            {
                const label other =
                    own[facei] == celli ? nei[facei] : own[facei];
                s = (X[other] - X[celli]) & Sf[facei];
            }
            else
            {
                const label patchi = patchID[facei - nInternal];
                if (!heightPatch_[patchi])
                {
                    continue;
                }
                const fvPatch& patch = mesh.boundary()[patchi];
                if (patch.coupled())
                {
                    const vector& other =
                        reconstruction.neighbourCentres(patchi)
                        [facei - patch.start()];
                    s = (other - X[celli]) & Sf[facei];
                }
                else
                {
                    s = 2*((Cf[facei] - X[celli]) & Sf[facei]);
                }
            }

            s *= ratio;
            const scalar HSSqr = magSqr(H & Sf[facei]);
            if (credit*sqr(s) < crossingSqr*HSSqr)
            {
                crossingSqr = credit*sqr(s)/HSSqr;
                crossing = Foam::sqrt(crossingSqr);
            }
        }
    }

    return CFL_*returnReduce(crossing, minOp<scalar>())/Up_;
}


// ************************************************************************* //
