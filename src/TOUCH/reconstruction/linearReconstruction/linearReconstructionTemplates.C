/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearReconstruction.H"
#include "compactAddressing.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

inline Foam::scalar Foam::linearReconstruction::factor
(
    const scalar up,
    const scalar down,
    const scalar largestUp,
    const scalar largestDown,
    const scalar tolerance
) const
{
    // The ratio is non-increasing in the increment, and min(1, limiter)
    // non-decreasing in the ratio (gradientLimiter)
    const scalar unit = unitRatio_;
    if
    (
        (largestUp <= tolerance || up >= unit*largestUp)
     && (largestDown >= -tolerance || down <= unit*largestDown)
    )
    {
        return 1;
    }

    scalar r = GREAT;

    if (largestUp > tolerance)
    {
        r = up/largestUp;
    }
    if (largestDown < -tolerance)
    {
        r = min(r, down/largestDown);
    }

    return min(scalar(1), limiter_->limiter(r));
}


template<class Type>
inline Type Foam::linearReconstruction::factors
(
    const Type& up,
    const Type& down,
    const Type& largestUp,
    const Type& largestDown,
    const scalar tolerance
) const
{
    Type phi;
    for (direction i = 0; i < pTraits<Type>::nComponents; ++i)
    {
        setComponent(phi, i) =
            factor
            (
                component(up, i), component(down, i),
                component(largestUp, i), component(largestDown, i),
                tolerance
            );
    }
    return phi;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<bool FaceIncrements, class CellOp>
void Foam::linearReconstruction::updateCells
(
    const volVectorField& p,
    const volTensorField& P,
    CellOp cellOp
)
{
    const compactAddressing::rows& cells =
        compactAddressing::New(mesh_).cellFaces();

    // The increments of P from each cell's centre to its face centres, in
    // the order of its faces: the limiter's second pass computes them
    // anyway, and the caller needs nothing else of the stress gradients
    if (faceIncrements_.empty())
    {
        label largest = 0;
        for (label c = 0; c < cells.size(); ++c)
        {
            largest = max(largest, cells[c].size());
        }
        faceIncrements_.setSize(largest, Zero);
    }
    tensor* dPf = faceIncrements_.data();

    const tensor zero(Zero);
    const tensor unlimited(tensor::one);

    if (scheme_ == scheme::firstOrder)
    {
        forAll(P, celli)
        {
            cellOp(celli, zero, zero, zero, zero, dPf);
        }
        return;
    }

    const bool limited = (scheme_ == scheme::limitedLinear);
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    const vectorField& C = X();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& pi = p.primitiveField();
    const tensorField& Pi = P.primitiveField();

    reflectMirrorValues(pi, Pi);

    forAll(pNeighbour_, patchi)
    {
        if (pNeighbour_.set(patchi) && !mirror_[patchi])
        {
            pNeighbour_[patchi] =
                p.boundaryField()[patchi].patchNeighbourField();
            PNeighbour_[patchi] =
                P.boundaryField()[patchi].patchNeighbourField();
        }
    }

    // Increments below round-off of the field's magnitude are no
    // increments: a cell at a bound of a component that is constant along a
    // face direction would otherwise take phi = 0 from a gradient of 1e-17
    // (measured: a rigid rotation lost half its energy in a quarter turn).
    // The magnitude of the whole field, not of each component: a component
    // that is zero but for round-off (p_x of a ring falling along y) had a
    // tolerance of round-off itself, and its limiter followed the round-off
    // of each decomposition (serial and parallel parted at first contact)
    // and of each step sequence (the ring's L_z grew to 2e-7)
    scalar pTolerance = 0;
    scalar PTolerance = 0;
    if (limited)
    {
        forAll(pi, c)
        {
            pTolerance = max(pTolerance, magSqr(pi[c]));
            PTolerance = max(PTolerance, magSqr(Pi[c]));
        }
        reduce(pTolerance, maxOp<scalar>());
        reduce(PTolerance, maxOp<scalar>());
        pTolerance = roundOff_*Foam::sqrt(pTolerance);
        PTolerance = roundOff_*Foam::sqrt(PTolerance);
    }

    tensorField& gp = gradp_.primitiveFieldRef();

    for (label c = 0; c < cells.size(); ++c)
    {
        const UList<label> cellFaces(cells[c]);
        const vector& pc = pi[c];
        const tensor& Pc = Pi[c];

        // Pass 1: the gradients and the bounds of the face neighbours
        tensor gpc(Zero);
        tensor gxc(Zero);
        tensor gyc(Zero);
        tensor gzc(Zero);
        vector pMax(pc);
        vector pMin(pc);
        tensor PMax(Pc);
        tensor PMin(Pc);

        for (const label facei : cellFaces)
        {
            vector w;
            const vector* pOther;
            const tensor* POther;

            if (facei < nInternal)
            {
                // w (x) (U_other - U_c), w = Minv_c (X_other - X_c)/|..|^2
                const label other =
                    own[facei] == c ? nei[facei] : own[facei];
                w = weight(c, facei, C[other] - C[c]);
                pOther = &pi[other];
                POther = &Pi[other];
            }
            else
            {
                const label patchi = boundaryFacePatch_[facei - nInternal];
                if (!pNeighbour_.set(patchi))
                {
                    continue;
                }
                const label i = facei - mesh_.boundary()[patchi].start();
                w = coupledWeights_[patchi][i];
                pOther = &pNeighbour_[patchi][i];
                POther = &PNeighbour_[patchi][i];
            }

            const vector dp(*pOther - pc);
            const tensor dP(*POther - Pc);

            gpc += w*dp;
            gxc += w.x()*dP;
            gyc += w.y()*dP;
            gzc += w.z()*dP;

            if (limited)
            {
                pMax = max(pMax, *pOther);
                pMin = min(pMin, *pOther);
                PMax = max(PMax, *POther);
                PMin = min(PMin, *POther);
            }
        }

        if (!limited)
        {
            gp[c] = gpc;
            if (FaceIncrements)
            {
                label k = 0;
                for (const label facei : cellFaces)
                {
                    const vector r(Cf[facei] - C[c]);
                    dPf[k++] = r.x()*gxc + r.y()*gyc + r.z()*gzc;
                }
            }
            cellOp(c, gxc, gyc, gzc, unlimited, dPf);
            continue;
        }

        // Pass 2: the largest increments up and down towards the limited
        // faces.  Coupled and mirror faces are interior faces (a mirror
        // face's neighbour is the reflected cell).  Faces of a boundary
        // condition are not limited: there is no neighbour value to bound
        // them, their flux is upwinded against the condition, and clipping
        // them made every boundary cell first order (swinging cube, stress
        // order 1.0 instead of 2.2).  They bound by the cell's own
        // extrapolation instead: a field that rises monotonically to a
        // boundary would otherwise leave the boundary cell at its bound,
        // and round-off-level tangential noise would clip its whole
        // gradient (measured: a free rigid rotation lost a third of its
        // energy in a quarter turn)
        vector pUp(Zero);
        vector pDown(Zero);
        tensor PUp(Zero);
        tensor PDown(Zero);

        label k = 0;
        for (const label facei : cellFaces)
        {
            const vector r(Cf[facei] - C[c]);
            const vector dp(r & gpc);
            const tensor& dP =
                (dPf[k++] = r.x()*gxc + r.y()*gyc + r.z()*gzc);

            if
            (
                facei >= nInternal
             && !pNeighbour_.set(boundaryFacePatch_[facei - nInternal])
            )
            {
                pMax = max(pMax, pc + dp);
                pMin = min(pMin, pc + dp);
                PMax = max(PMax, Pc + dP);
                PMin = min(PMin, Pc + dP);
            }
            else
            {
                pUp = max(pUp, dp);
                pDown = min(pDown, dp);
                PUp = max(PUp, dP);
                PDown = min(PDown, dP);
            }
        }

        const vector phip
        (
            factors(pMax - pc, pMin - pc, pUp, pDown, pTolerance)
        );
        const tensor phiP
        (
            factors(PMax - Pc, PMin - Pc, PUp, PDown, PTolerance)
        );

        momentumLimiter_[c] = phip;

        // Column j of grad p carries component j of p
        gp[c] =
            cmptMultiply
            (
                gpc,
                tensor
                (
                    phip.x(), phip.y(), phip.z(),
                    phip.x(), phip.y(), phip.z(),
                    phip.x(), phip.y(), phip.z()
                )
            );
        // The limited gradient's increments: the factor of a component
        // scales its derivatives along X, Y and Z alike
        if (FaceIncrements)
        {
            for (label f = 0; f < k; ++f)
            {
                dPf[f] = cmptMultiply(dPf[f], phiP);
            }
        }
        cellOp(c, gxc, gyc, gzc, phiP, dPf);
    }

    gradp_.correctBoundaryConditions();
}


template<class StressOp>
void Foam::linearReconstruction::update
(
    const volVectorField& p,
    const volTensorField& P,
    StressOp stressOp
)
{
    updateCells<true>
    (
        p,
        P,
        [&]
        (
            const label celli,
            const tensor&,
            const tensor&,
            const tensor&,
            const tensor&,
            const tensor* dPf
        )
        {
            stressOp(celli, dPf);
        }
    );
}



// ************************************************************************* //
