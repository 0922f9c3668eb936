/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "symmetricEigen.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A unit vector orthogonal to the unit vector u
vector orthogonalUnit(const vector& u)
{
    // Cross u with the axis it is least aligned with
    const vector a(cmptMag(u));
    const vector axis
    (
        a.x() <= a.y() && a.x() <= a.z() ? vector(1, 0, 0)
      : a.y() <= a.z() ? vector(0, 1, 0)
      : vector(0, 0, 1)
    );
    const vector w(u ^ axis);
    return w/mag(w);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::symmetricEigen
(
    const symmTensor& A,
    vector& values,
    tensor& vectors
)
{
    const scalar mean = tr(A)/3;
    const symmTensor s(A - mean*symmTensor::I);
    const scalar J2 = 0.5*magSqr(s);

    // A multiple of I, or so near it that the Lode angle's cube of
    // sqrt(J2) would underflow: the diagonal, exact for A = a I. The bound
    // is VSMALL^(2/3), not VSMALL: (J2/3)^(3/2) is 0 below about 1e-205,
    // and a cell just ahead of a wave (F - I of 1e-110, the scheme's
    // decaying precursor) divided by it (found 2026-12-04 with an elastic
    // zone next to a vonMisesPlastic one)
    static const scalar tiny = Foam::pow(VSMALL, 2.0/3.0);
    if (J2 <= tiny)
    {
        values = vector(A.xx(), A.yy(), A.zz());
        vectors = tensor::I;
        return;
    }

    // The eigenvalue of s farthest from the other two (Lode angle)
    const scalar r = Foam::sqrt(J2/3);
    const scalar cos3Alpha = min(max(0.5*det(s)/(r*r*r), scalar(-1)), 1);
    const scalar alpha = Foam::acos(cos3Alpha)/3;
    const scalar eta1 =
        alpha < constant::mathematical::pi/6
      ? 2*r*Foam::cos(alpha)
      : 2*r*Foam::cos(alpha + constant::mathematical::twoPi/3);

    // Its eigenvector, orthogonal to the rows of s - eta1 I
    const symmTensor R(s - eta1*symmTensor::I);
    const vector rows[3] =
    {
        vector(R.xx(), R.xy(), R.xz()),
        vector(R.xy(), R.yy(), R.yz()),
        vector(R.xz(), R.yz(), R.zz())
    };
    label k = 0;
    scalar largest = magSqr(rows[0]);
    for (label i = 1; i < 3; ++i)
    {
        const scalar m = magSqr(rows[i]);
        if (m > largest)
        {
            largest = m;
            k = i;
        }
    }
    const vector u1(rows[k]/Foam::sqrt(largest));

    const vector ta(rows[(k + 1) % 3] - (rows[(k + 1) % 3] & u1)*u1);
    const vector tb(rows[(k + 2) % 3] - (rows[(k + 2) % 3] & u1)*u1);
    const scalar ma = magSqr(ta);
    const scalar mb = magSqr(tb);
    const vector u2
    (
        max(ma, mb) > 0
      ? (ma > mb ? ta/Foam::sqrt(ma) : tb/Foam::sqrt(mb))
      : orthogonalUnit(u1)
    );
    const vector v1(u1 ^ u2);

    // The other two: one Jacobi rotation of the projection on (u1, u2)
    const vector su1(s & u1);
    const vector su2(s & u2);
    const scalar a11 = u1 & su1;
    const scalar a22 = u2 & su2;
    const scalar a12 = u1 & su2;

    scalar t = 0;
    if (a12 != 0)
    {
        const scalar theta = 0.5*(a22 - a11)/a12;
        t = 1/(mag(theta) + Foam::sqrt(1 + sqr(theta)));
        if (theta < 0)
        {
            t = -t;
        }
    }
    const scalar c = 1/Foam::sqrt(1 + sqr(t));
    const scalar sn = t*c;

    values = vector(eta1, a11 - t*a12, a22 + t*a12) + mean*vector::one;

    const vector v2(c*u1 - sn*u2);
    const vector v3(sn*u1 + c*u2);
    vectors = tensor
    (
        v1.x(), v1.y(), v1.z(),
        v2.x(), v2.y(), v2.z(),
        v3.x(), v3.y(), v3.z()
    );
}


// ************************************************************************* //
