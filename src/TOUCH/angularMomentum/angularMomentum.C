/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "angularMomentum.H"
#include "symmetricEigen.H"
#include "volFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::symmTensor Foam::angularMomentum::inverseOnRange(const symmTensor& J)
{
    // A body whose cell centres lie on one line (a bar of N x 1 x 1 cells)
    // has no moment of inertia about that line: J is singular, and so is
    // the angular momentum about the line, which the lever arms x - xbar
    // cannot change. The inverse on J's range leaves that axis alone
    const scalar size = tr(J);
    if (det(J) > 1e-12*pow3(size))
    {
        return inv(J);
    }

    vector values;
    tensor vectors;
    symmetricEigen(J, values, vectors);

    symmTensor Jinv(Zero);
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (values[i] > 1e-9*size)
        {
            Jinv += symm(sqr(vectors.row(i)))/values[i];
        }
    }
    return Jinv;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::symmTensor Foam::angularMomentum::rotationAxes(const fvMesh& mesh)
{
    if (mesh.nSolutionD() == 3)
    {
        return symmTensor::I;
    }

    // The empty directions: a 2D mesh turns about its one, a 1D mesh about
    // none of its two (a turn about the line moves nothing)
    symmTensor axes(Zero);
    if (mesh.nSolutionD() == 2)
    {
        const Vector<label>& solutionD = mesh.solutionD();
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (solutionD[d] < 0)
            {
                vector e(Zero);
                e[d] = 1;
                axes = sqr(e);
            }
        }
    }
    return axes;
}


Foam::angularMomentum::angularMomentum(const fvMesh& mesh)
:
    V_(mesh.V()),
    axes_(rotationAxes(mesh))
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


Foam::vector Foam::angularMomentum::total
(
    const vectorField& X,
    const vectorField& u,
    const vectorField& p
) const
{
    vector L(Zero);

    forAll(V_, a)
    {
        L += V_[a]*((X[a] + u[a]) ^ p[a]);
    }

    return returnReduce(L, sumOp<vector>());
}


template<class Momentum>
Foam::angularMomentum::rigidMoments Foam::angularMomentum::moments
(
    const vectorField& x,
    const Momentum& q
) const
{
    scalar volume = 0;
    vector moment(Zero);
    symmTensor second(Zero);
    rigidMoments m{0, Zero, Zero, Zero, Zero, 0};

    forAll(V_, a)
    {
        const vector qa(q(a));
        volume += V_[a];
        moment += V_[a]*x[a];
        second += V_[a]*sqr(x[a]);
        m.Q += V_[a]*qa;
        m.L += V_[a]*(x[a] ^ qa);
        m.Q2 += V_[a]*magSqr(qa);
    }

    reduce(volume, sumOp<scalar>());
    reduce(moment, sumOp<vector>());
    reduce(second, sumOp<symmTensor>());
    reduce(m.Q, sumOp<vector>());
    reduce(m.L, sumOp<vector>());
    reduce(m.Q2, sumOp<scalar>());

    m.volume = volume;
    m.xbar = moment/volume;

    // J = sum V (|d|^2 I - d d) about the centroid; on a 2D mesh the
    // inverse of its part about the plane's normal e, e e/(e.J.e)
    const symmTensor dd(second - volume*sqr(m.xbar));
    const symmTensor J(tr(dd)*symmTensor::I - dd);
    if (axes_ == symmTensor::I)
    {
        m.Jinv = inverseOnRange(J);
    }
    else
    {
        const scalar Jaxis = axes_ && J;
        m.Jinv = Jaxis > 0 ? axes_/Jaxis : symmTensor(Zero);
    }

    return m;
}


Foam::vector Foam::angularMomentum::spin
(
    const vectorField& x,
    const vectorField& p
) const
{
    const rigidMoments m(moments(x, [&](const label a) { return p[a]; }));

    return m.Jinv & (m.L - (m.xbar ^ m.Q));
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
    // linear and angular momenta and twice rho times the kinetic energy of
    // the uncorrected update q = pBase + c r
    const rigidMoments m
    (
        moments(x, [&](const label a) { return pBase[a] + c*r[a]; })
    );
    const scalar volume = m.volume;
    const vector& xbar = m.xbar;
    const symmTensor& Jinv = m.Jinv;
    const vector& Q = m.Q;
    const scalar Q2 = m.Q2;
    vector Lupdate(m.L);

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
    // What the update may still add; negative where the uncorrected update
    // is already above the limit (the momentum upwinding less the body's
    // spin jump is not dissipative in every step: a tetrahedral free body
    // gained 3.5e-7 E0 a step with the quadratic jump share when this was
    // clipped at zero), so that the share pays for that excess too
    const scalar allowed = 2*rho*kineticLimit - Q2;
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
