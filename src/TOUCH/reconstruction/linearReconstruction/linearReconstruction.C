/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearReconstruction.H"
#include "fvMesh.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::linearReconstruction::scheme>
Foam::linearReconstruction::schemeNames
({
    { scheme::firstOrder, "firstOrder" },
    { scheme::linear, "linear" },
    { scheme::limitedLinear, "limitedLinear" },
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::linearReconstruction::calcWeights()
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = X_.primitiveField();
    const vectorField& Cf = mesh_.faceCentres();

    // Least-squares matrices M = sum w d d, w = 1/|d|^2
    symmTensorField M(mesh_.nCells(), Zero);

    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const symmTensor wdd(sqr(d)/magSqr(d));
        M[own[facei]] += wdd;
        M[nei[facei]] += wdd;
    }

    forAll(X_.boundaryField(), patchi)
    {
        const fvPatchVectorField& Xp = X_.boundaryField()[patchi];

        if (Xp.coupled())
        {
            const vectorField Xn(Xp.patchNeighbourField());
            const labelUList& faceCells = Xp.patch().faceCells();

            forAll(Xn, i)
            {
                const vector d(Xn[i] - C[faceCells[i]]);
                M[faceCells[i]] += sqr(d)/magSqr(d);
            }
        }
    }

    // Cells whose neighbours do not span space: add their boundary faces
    label nRegularised = 0;

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];

        if (patch.coupled())
        {
            continue;
        }

        forAll(patch, i)
        {
            const label c = patch.faceCells()[i];

            // det(M) relative to its scale: 1 for three orthogonal pairs
            if (det(M[c]) < 1e-3*pow3(tr(M[c])/3))
            {
                const vector d(Cf[patch.start() + i] - C[c]);
                M[c] += sqr(d)/magSqr(d);
                ++nRegularised;
            }
        }
    }

    reduce(nRegularised, sumOp<label>());

    if (nRegularised)
    {
        Info<< "linearReconstruction: " << nRegularised
            << " boundary faces added to rank-deficient least-squares"
            << " stencils" << endl;
    }

    Minv_ = inv(M);
    const symmTensorField& Minv = Minv_;

    forAll(X_.boundaryField(), patchi)
    {
        const fvPatchVectorField& Xp = X_.boundaryField()[patchi];

        if (Xp.coupled())
        {
            const vectorField Xn(Xp.patchNeighbourField());
            const labelUList& faceCells = Xp.patch().faceCells();
            vectorField& w = coupledWeights_[patchi];

            forAll(Xn, i)
            {
                const vector d(Xn[i] - C[faceCells[i]]);
                w[i] = (Minv[faceCells[i]] & d)/magSqr(d);
            }
        }
    }
}


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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearReconstruction::linearReconstruction
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    scheme_(schemeNames.get("reconstruction", dict)),
    limiter_
    (
        scheme_ == scheme::limitedLinear
      ? gradientLimiter::New(dict)
      : autoPtr<gradientLimiter>()
    ),
    unitRatio_(limiter_.valid() ? limiter_->unitRatio() : GREAT),
    boundaryFacePatch_(mesh.nFaces() - mesh.nInternalFaces(), -1),
    pNeighbour_(mesh.boundary().size()),
    PNeighbour_(mesh.boundary().size()),
    X_
    (
        IOobject
        (
            "referenceCellCentres",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedVector("0", dimLength, Zero),
        calculatedFvPatchVectorField::typeName
    ),
    Minv_(mesh.nCells()),
    coupledWeights_(mesh.boundary().size()),
    gradp_
    (
        IOobject
        (
            "grad(lm)",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedTensor("0", dimless, Zero),
        calculatedFvPatchTensorField::typeName
    ),
    gradP_(3)
{
    if (limiter_.valid())
    {
        momentumLimiter_.setSize(mesh.nCells());
    }

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];

        SubList<label>
        (
            boundaryFacePatch_,
            patch.size(),
            patch.start() - mesh.nInternalFaces()
        ) = patchi;

        if (patch.coupled())
        {
            pNeighbour_.set(patchi, new vectorField(patch.size()));
            PNeighbour_.set(patchi, new tensorField(patch.size()));
        }
    }

    Info<< "Reconstruction " << schemeNames[scheme_];
    if (limiter_.valid())
    {
        Info<< " with limiter " << dict.get<word>("limiter");
    }
    Info<< endl;

    X_.primitiveFieldRef() = mesh.C().primitiveField();
    forAll(X_.boundaryField(), patchi)
    {
        X_.boundaryFieldRef()[patchi] = mesh.C().boundaryField()[patchi];
    }
    X_.correctBoundaryConditions();

    forAll(mesh.boundary(), patchi)
    {
        coupledWeights_.set
        (
            patchi,
            new vectorField
            (
                mesh.boundary()[patchi].coupled()
              ? mesh.boundary()[patchi].size()
              : 0,
                Zero
            )
        );
    }

    const char* const axes[3] = {"X", "Y", "Z"};
    forAll(gradP_, d)
    {
        gradP_.set
        (
            d,
            new volTensorField
            (
                IOobject
                (
                    word("d(P)/d") + axes[d],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                mesh,
                dimensionedTensor("0", dimless, Zero),
                calculatedFvPatchTensorField::typeName
            )
        );
    }

    calcWeights();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::linearReconstruction::update
(
    const volVectorField& p,
    const volTensorField& P
)
{
    if (scheme_ == scheme::firstOrder)
    {
        return;
    }

    const bool limited = (scheme_ == scheme::limitedLinear);
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    const cellList& cells = mesh_.cells();
    const vectorField& C = X_.primitiveField();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& pi = p.primitiveField();
    const tensorField& Pi = P.primitiveField();

    forAll(pNeighbour_, patchi)
    {
        if (pNeighbour_.set(patchi))
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
    tensorField& gx = gradP_[0].primitiveFieldRef();
    tensorField& gy = gradP_[1].primitiveFieldRef();
    tensorField& gz = gradP_[2].primitiveFieldRef();

    forAll(cells, c)
    {
        const labelList& cellFaces = cells[c];
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
                w = weight(c, C[other] - C[c]);
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
            gx[c] = gxc;
            gy[c] = gyc;
            gz[c] = gzc;
            continue;
        }

        // Pass 2: the largest increments up and down towards the limited
        // faces.  Coupled faces are interior faces.  Faces of a boundary
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

        for (const label facei : cellFaces)
        {
            const vector r(Cf[facei] - C[c]);
            const vector dp(r & gpc);
            const tensor dP(r.x()*gxc + r.y()*gyc + r.z()*gzc);

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
        gx[c] = cmptMultiply(gxc, phiP);
        gy[c] = cmptMultiply(gyc, phiP);
        gz[c] = cmptMultiply(gzc, phiP);
    }

    gradp_.correctBoundaryConditions();
    forAll(gradP_, d)
    {
        gradP_[d].correctBoundaryConditions();
    }
}


// ************************************************************************* //
