/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "stableTimeStep.H"
#include "mathematicalConstants.H"

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


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::stableTimeStep::readCFL(const dictionary& controls)
{
    const scalar CFL = controls.get<scalar>("CFL");

    if (!(CFL > 0 && CFL <= 1))
    {
        FatalIOErrorInFunction(controls)
            << "Entry 'CFL' = " << CFL << " in " << controls.name()
            << " is out of range: valid values satisfy 0 < CFL <= 1" << nl
            << exit(FatalIOError);
    }

    return CFL;
}


Foam::scalar Foam::stableTimeStep::calcHmin(const solidFaces& faces)
{
    const fvMesh& mesh = faces.mesh();
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& X = faces.mesh().C().primitiveField();

    // The distance between neighbouring centres normal to their face:
    // the cell size for hexahedra, the inscribed scale for tetrahedra; at
    // a boundary twice the distance of the centre from the face
    scalar h = GREAT;

    faces.forAllCoupled
    (
        [&](const solidFaces::coupledFace& face)
        {
            h = min(h, mag((face.right.X - face.left.X) & face.N));
        }
    );

    for (const fvPatch& patch : mesh.boundary())
    {
        if (!patch.coupled())
        {
            forAll(patch.faceCells(), i)
            {
                const label facei = patch.start() + i;
                const vector N(Sf[facei]/mag(Sf[facei]));
                const vector r(Cf[facei] - X[patch.faceCells()[i]]);
                h = min(h, 2*mag(r & N));
            }
        }
    }

    return returnReduce(h, minOp<scalar>());
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
    hMin_(calcHmin(faces)),
    Up_(law.Up())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::stableTimeStep::deltaT(const volTensorField& F) const
{
    // The fastest wave, Up, in the current configuration: reference lengths
    // shrink by the smallest principal stretch
    scalar minStretch = GREAT;

    forAll(F, celli)
    {
        const tensor& Fc = F[celli];
        minStretch = min(minStretch, minEigenValue(symm(Fc.T() & Fc)));
    }

    minStretch = Foam::sqrt(max(returnReduce(minStretch, minOp<scalar>()), 0));

    return CFL_*hMin_*minStretch/Up_;
}


// ************************************************************************* //
