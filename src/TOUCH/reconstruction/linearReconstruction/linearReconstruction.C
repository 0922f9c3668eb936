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

    const symmTensorField Minv(inv(M));

    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        ownerWeights_[facei] = (Minv[own[facei]] & d)/magSqr(d);
        neighbourWeights_[facei] = (Minv[nei[facei]] & d)/magSqr(d);
    }

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
    ownerWeights_(mesh.nInternalFaces(), Zero),
    neighbourWeights_(mesh.nInternalFaces(), Zero),
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

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& pi = p.primitiveField();
    const tensorField& Pi = P.primitiveField();

    tensorField& gp = gradp_.primitiveFieldRef();
    tensorField& gx = gradP_[0].primitiveFieldRef();
    tensorField& gy = gradP_[1].primitiveFieldRef();
    tensorField& gz = gradP_[2].primitiveFieldRef();

    gp = Zero;
    gx = Zero;
    gy = Zero;
    gz = Zero;

    // One pass over the faces serves both fields
    forAll(own, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        const vector dp(pi[n] - pi[o]);
        const tensor dP(Pi[n] - Pi[o]);
        const vector& wo = ownerWeights_[facei];
        const vector& wn = neighbourWeights_[facei];

        gp[o] += wo*dp;
        gx[o] += wo.x()*dP;
        gy[o] += wo.y()*dP;
        gz[o] += wo.z()*dP;

        gp[n] += wn*dp;
        gx[n] += wn.x()*dP;
        gy[n] += wn.y()*dP;
        gz[n] += wn.z()*dP;
    }

    forAll(mesh_.boundary(), patchi)
    {
        if (!mesh_.boundary()[patchi].coupled())
        {
            continue;
        }

        const vectorField pn(p.boundaryField()[patchi].patchNeighbourField());
        const tensorField Pn(P.boundaryField()[patchi].patchNeighbourField());
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        const vectorField& w = coupledWeights_[patchi];

        forAll(faceCells, i)
        {
            const label o = faceCells[i];
            const vector dp(pn[i] - pi[o]);
            const tensor dP(Pn[i] - Pi[o]);

            gp[o] += w[i]*dp;
            gx[o] += w[i].x()*dP;
            gy[o] += w[i].y()*dP;
            gz[o] += w[i].z()*dP;
        }
    }

    if (scheme_ == scheme::limitedLinear)
    {
        momentumLimiter_ =
            limiterFactors
            (
                p,
                [&](const label c, const vector& r) { return r & gp[c]; }
            );
        const vectorField& phip = momentumLimiter_;

        const tensorField phiP
        (
            limiterFactors
            (
                P,
                [&](const label c, const vector& r)
                {
                    return r.x()*gx[c] + r.y()*gy[c] + r.z()*gz[c];
                }
            )
        );

        forAll(gp, c)
        {
            // Column j of grad p carries component j of p
            const tensor phi
            (
                phip[c].x(), phip[c].y(), phip[c].z(),
                phip[c].x(), phip[c].y(), phip[c].z(),
                phip[c].x(), phip[c].y(), phip[c].z()
            );
            gp[c] = cmptMultiply(gp[c], phi);
            gx[c] = cmptMultiply(gx[c], phiP[c]);
            gy[c] = cmptMultiply(gy[c], phiP[c]);
            gz[c] = cmptMultiply(gz[c], phiP[c]);
        }
    }

    gradp_.correctBoundaryConditions();
    forAll(gradP_, d)
    {
        gradP_[d].correctBoundaryConditions();
    }
}


// ************************************************************************* //
