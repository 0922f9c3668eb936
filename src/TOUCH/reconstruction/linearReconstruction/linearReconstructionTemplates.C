/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearReconstruction.H"
#include "compactAddressing.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

inline Foam::packedMomentumStress Foam::linearReconstruction::increment
(
    const vector& r,
    const packedMomentumStress& gX,
    const packedMomentumStress& gY,
    const packedMomentumStress& gZ
)
{
    return packedMomentumStress
    (
        r.x()*gX.a + r.y()*gY.a + r.z()*gZ.a,
        r.x()*gX.b + r.y()*gY.b + r.z()*gZ.b,
        r.x()*gX.c + r.y()*gY.c + r.z()*gZ.c
    );
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
    // and of each step sequence (the ring's L_z grew to 2e-7).  For p the
    // largest range of a component, not the largest |p|: a uniform drift
    // changes no increment, and so no limiter factor (Galilean invariance,
    // test slidingWallInvariance).  The range within a body, the largest
    // of the bodies': two bars meeting at +-v are not a field of range 2 v,
    // and each must be the bar on a rigid wall (test barCollision; with the
    // range over the mesh the two parted by 2e-8 of max |p| on 100 cells a
    // metre).  Not each body's own: a body at rest that is hit then had a
    // tolerance near the round-off of the exchange, and serial and
    // parallel parted at a sticking decision (test contactParallel)
    scalar pTolerance = 0;
    scalar PTolerance = 0;
    if (limited)
    {
        List<vector> pMax(nBodies_, vector::uniform(-GREAT));
        List<vector> pMin(nBodies_, vector::uniform(GREAT));
        forAll(pi, c)
        {
            const label b = cellBody_[c];
            pMax[b] = max(pMax[b], pi[c]);
            pMin[b] = min(pMin[b], pi[c]);
            PTolerance = max(PTolerance, magSqr(Pi[c]));
        }
        Pstream::listCombineGather(pMax, maxEqOp<vector>());
        Pstream::listCombineScatter(pMax);
        Pstream::listCombineGather(pMin, minEqOp<vector>());
        Pstream::listCombineScatter(pMin);
        reduce(PTolerance, maxOp<scalar>());

        forAll(pMax, b)
        {
            pTolerance = max(pTolerance, cmptMax(pMax[b] - pMin[b]));
        }
        pTolerance *= roundOff_;
        PTolerance = roundOff_*Foam::sqrt(PTolerance);
    }
    const packedMomentumStress tolerance
    (
        vector(pTolerance, pTolerance, pTolerance),
        tensor(PTolerance*tensor::one)
    );

    tensorField& gp = gradp_.primitiveFieldRef();

    typedef packedMomentumStress packed;

    for (label c = 0; c < cells.size(); ++c)
    {
        const UList<label> cellFaces(cells[c]);
        const packed centre(pi[c], Pi[c]);

        // Pass 1: the derivatives of every component along X, Y and Z and
        // the bounds of the face neighbours
        packed gX(0.0);
        packed gY(0.0);
        packed gZ(0.0);
        packed largest(centre);
        packed smallest(centre);

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
                const label i = facei - mesh_.boundaryMesh()[patchi].start();
                w = coupledWeights_[patchi][i];
                pOther = &pNeighbour_[patchi][i];
                POther = &PNeighbour_[patchi][i];
            }

            const packed other(*pOther, *POther);
            const packed jump(other - centre);

            gX.addScaled(w.x(), jump);
            gY.addScaled(w.y(), jump);
            gZ.addScaled(w.z(), jump);

            if (limited)
            {
                largest.raise(other);
                smallest.lower(other);
            }
        }

        // Row i of grad p is d p/d X_i
        const tensor gpc
        (
            gX.a[0], gX.a[1], gX.a[2],
            gY.a[0], gY.a[1], gY.a[2],
            gZ.a[0], gZ.a[1], gZ.a[2]
        );

        if (!limited)
        {
            gp[c] = gpc;
            if (FaceIncrements)
            {
                label k = 0;
                for (const label facei : cellFaces)
                {
                    const vector r(Cf[facei] - C[c]);
                    increment(r, gX, gY, gZ).stress(dPf[k++]);
                }
            }
            cellOp(c, gX.stress(), gY.stress(), gZ.stress(), unlimited, dPf);
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
        packed largestUp(0.0);
        packed largestDown(0.0);

        label k = 0;
        for (const label facei : cellFaces)
        {
            const vector r(Cf[facei] - C[c]);
            const packed inc(increment(r, gX, gY, gZ));
            inc.stress(dPf[k++]);

            if
            (
                facei >= nInternal
             && !pNeighbour_.set(boundaryFacePatch_[facei - nInternal])
            )
            {
                const packed faceValue(centre + inc);
                largest.raise(faceValue);
                smallest.lower(faceValue);
            }
            else
            {
                largestUp.raise(inc);
                largestDown.lower(inc);
            }
        }

        // The factors of the 3 + 9 components, one limiter call a cell
        scalar phi[packed::nComponents];
        packed::ratios
        (
            largest - centre,
            smallest - centre,
            largestUp,
            largestDown,
            tolerance
        ).components(phi);
        limiter_->factors(phi, packed::nComponents);

        const vector phip(phi[0], phi[1], phi[2]);
        const tensor phiP
        (
            phi[3], phi[4], phi[5],
            phi[6], phi[7], phi[8],
            phi[9], phi[10], phi[11]
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
        cellOp(c, gX.stress(), gY.stress(), gZ.stress(), phiP, dPf);
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
