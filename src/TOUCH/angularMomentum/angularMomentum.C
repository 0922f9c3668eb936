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


Foam::vector Foam::angularMomentum::spin
(
    const vectorField& x,
    const vectorField& p
) const
{
    scalar volume = 0;
    vector moment(Zero);
    symmTensor second(Zero);
    vector Q(Zero);
    vector L(Zero);

    forAll(V_, a)
    {
        volume += V_[a];
        moment += V_[a]*x[a];
        second += V_[a]*sqr(x[a]);
        Q += V_[a]*p[a];
        L += V_[a]*(x[a] ^ p[a]);
    }

    reduce(volume, sumOp<scalar>());
    reduce(moment, sumOp<vector>());
    reduce(second, sumOp<symmTensor>());
    reduce(Q, sumOp<vector>());
    reduce(L, sumOp<vector>());

    const vector xbar(moment/volume);
    const symmTensor dd(second - volume*sqr(xbar));

    return inv(symmTensor(tr(dd)*symmTensor::I - dd)) & (L - (xbar ^ Q));
}


Foam::vector Foam::angularMomentum::updateMomentum
(
    const vectorField& x,
    const vectorField& pBase,
    const scalar c,
    const vectorField& r
) const
{
    vector L(Zero);

    forAll(V_, a)
    {
        L += V_[a]*(x[a] ^ (pBase[a] + c*r[a]));
    }

    return returnReduce(L, sumOp<vector>());
}


void Foam::angularMomentum::correct
(
    const vectorField& x,
    const vectorField& pBase,
    const scalar c,
    const vector& L,
    const scalar rho,
    const scalar kineticLimit,
    vectorField& r
) const
{
    // Global sums: volume, first and second moments of the lever arms, the
    // linear momentum and twice rho times the kinetic energy of the
    // uncorrected update q = pBase + c r
    scalar volume = 0;
    vector moment(Zero);
    symmTensor second(Zero);
    vector Q(Zero);
    scalar Q2 = 0;

    forAll(V_, a)
    {
        const vector q(pBase[a] + c*r[a]);
        volume += V_[a];
        moment += V_[a]*x[a];
        second += V_[a]*sqr(x[a]);
        Q += V_[a]*q;
        Q2 += V_[a]*magSqr(q);
    }

    reduce(volume, sumOp<scalar>());
    reduce(moment, sumOp<vector>());
    reduce(second, sumOp<symmTensor>());
    reduce(Q, sumOp<vector>());
    reduce(Q2, sumOp<scalar>());

    const vector xbar(moment/volume);

    // J = sum V (|d|^2 I - d d) about the centroid
    const symmTensor dd(second - volume*sqr(xbar));
    const symmTensor Jinv(inv(symmTensor(tr(dd)*symmTensor::I - dd)));

    vector Lupdate(updateMomentum(x, pBase, c, r));

    // The rigid part of q (its mean and its spin about the centroid); the
    // rest, w, carries neither linear nor angular momentum. Its mean is
    // taken out again so that round-off cannot move the linear momentum.
    const vector Lq(Lupdate - (xbar ^ Q));
    const vector pMean(Q/volume);
    const vector spin(Jinv & Lq);

    vector wSum(Zero);
    scalar W = 0;
    forAll(V_, a)
    {
        const vector w
        (
            deformationPart(pBase[a] + c*r[a], pMean, spin, x[a] - xbar)
        );
        wSum += V_[a]*w;
        W += V_[a]*magSqr(w);
    }
    reduce(wSum, sumOp<vector>());
    reduce(W, sumOp<scalar>());

    const vector wMean(wSum/volume);
    W = max(W - volume*magSqr(wMean), scalar(0));

    // The rotation's gain (times 2 rho): 2 c lambda.Lq + c^2 lambda.J lambda
    // = 2 Lq.dL + dL.Jinv.dL with dL = L - Lupdate, lambda = Jinv dL/c
    const vector dL(L - Lupdate);
    const scalar rotationGain = 2*(Lq & (Jinv & dL)) + (dL & (Jinv & dL));
    const scalar allowed = max(2*rho*kineticLimit - Q2, scalar(0));
    const scalar s = deformationShare(rotationGain - allowed, W);

    if (s != 0)
    {
        forAll(r, a)
        {
            r[a] +=
                (s/c)
               *(
                    deformationPart
                    (
                        pBase[a] + c*r[a], pMean, spin, x[a] - xbar
                    )
                  - wMean
                );
        }

        Lupdate = updateMomentum(x, pBase, c, r);
    }

    // The rigid rotation onto the target, about the centroid
    const vector lambda(Jinv & ((L - Lupdate)/c));

    forAll(r, a)
    {
        r[a] += lambda ^ (x[a] - xbar);
    }
}


Foam::scalar Foam::angularMomentum::deformationShare
(
    const scalar excess,
    const scalar W
)
{
    if (excess <= 0)
    {
        return 0;
    }
    if (excess >= W)
    {
        // Not enough deformation to pay for the rotation: remove all of it
        // (the least energy the angular momentum allows)
        return -1;
    }

    // The root of W (s^2 + 2 s) + excess = 0 nearest to zero, in the form
    // that does not cancel when excess << W
    return -(excess/W)/(1 + Foam::sqrt(1 - excess/W));
}


// ************************************************************************* //
