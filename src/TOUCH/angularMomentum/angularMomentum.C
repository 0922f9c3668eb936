/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "angularMomentum.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::angularMomentum::angularMomentum(const fvMesh& mesh)
:
    V_(mesh.V())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::angularMomentum::total
(
    const vectorField& x,
    const vectorField& p
) const
{
    vector L(Zero);

    forAll(V_, a)
    {
        L += V_[a]*(x[a] ^ p[a]);
    }

    return returnReduce(L, sumOp<vector>());
}


void Foam::angularMomentum::correct
(
    const vectorField& x,
    const vectorField& pBase,
    const scalar c,
    const vector& L,
    vectorField& r
) const
{
    // Global sums: volume, first and second moments of the lever arms,
    // and the angular momentum the uncorrected update would have
    scalar volume = 0;
    vector moment(Zero);
    symmTensor second(Zero);
    vector Lupdate(Zero);

    forAll(V_, a)
    {
        volume += V_[a];
        moment += V_[a]*x[a];
        second += V_[a]*sqr(x[a]);
        Lupdate += V_[a]*(x[a] ^ (pBase[a] + c*r[a]));
    }

    reduce(volume, sumOp<scalar>());
    reduce(moment, sumOp<vector>());
    reduce(second, sumOp<symmTensor>());
    reduce(Lupdate, sumOp<vector>());

    const vector xbar(moment/volume);

    // J = sum V (|d|^2 I - d d) about the centroid
    const symmTensor dd(second - volume*sqr(xbar));
    const symmTensor J(tr(dd)*symmTensor::I - dd);

    const vector lambda(inv(J) & ((L - Lupdate)/c));
    const vector beta(-(lambda ^ xbar));

    forAll(r, a)
    {
        r[a] += (lambda ^ x[a]) + beta;
    }
}


// ************************************************************************* //
