/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearPointInterpolation.H"
#include "syncTools.H"
#include "compactAddressing.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearPointInterpolation::linearPointInterpolation
(
    const fvMesh& mesh,
    const linearReconstruction& reconstruction,
    const bool limited
)
:
    mesh_(mesh),
    reconstruction_(reconstruction),
    inverseNPointCells_(mesh.nPoints(), Zero),
    cellWork_(),
    boundaryFaceWork_(mesh.nBoundaryFaces()),
    limited_(limited)
{
    if
    (
        limited_
     && reconstruction_.schemeType()
     != linearReconstruction::scheme::limitedLinear
    )
    {
        FatalErrorInFunction
            << "A limited point interpolation takes its limiter from the"
            << " reconstruction, which must be limitedLinear" << nl
            << exit(FatalError);
    }

    const labelList sizes(compactAddressing::New(mesh_).pointCells().sizes());
    scalarField& n = inverseNPointCells_;
    forAll(sizes, pointi)
    {
        n[pointi] = sizes[pointi];
    }

    syncTools::syncPointList(mesh_, n, plusEqOp<scalar>(), scalar(0));

    // Every point has a cell
    n = 1/n;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::linearPointInterpolation::interpolate
(
    const volVectorField& U,
    const scalar scale,
    vectorField& pointValues
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Ui = U.primitiveField();
    // Unlimited least-squares gradients: a fixed linear map, so that the
    // transpose below is exact
    tensorField& grad = cellWork_;
    grad.setSize(mesh_.nCells());
    grad = Zero;

    forAll(own, facei)
    {
        const vector dU(Ui[nei[facei]] - Ui[own[facei]]);
        grad[own[facei]] += reconstruction_.ownerWeight(facei)*dU;
        grad[nei[facei]] += reconstruction_.neighbourWeight(facei)*dU;
    }

    forAll(mesh_.boundary(), patchi)
    {
        // The polyPatch's cells: an empty patch's fvPatch has none, and as
        // a mirror it reflects them
        const labelUList& faceCells =
            mesh_.boundaryMesh()[patchi].faceCells();
        const vectorField& w = reconstruction_.coupledWeights(patchi);

        if (reconstruction_.mirror(patchi))
        {
            // The reflected cell: U' - U = (s R - I) U
            forAll(faceCells, i)
            {
                grad[faceCells[i]] +=
                    w[i]
                   *reconstruction_.mirrorJump(patchi, i, Ui[faceCells[i]]);
            }
            continue;
        }

        if (!mesh_.boundary()[patchi].coupled())
        {
            continue;
        }

        const vectorField Un(U.boundaryField()[patchi].patchNeighbourField());

        forAll(faceCells, i)
        {
            grad[faceCells[i]] += w[i]*(Un[i] - Ui[faceCells[i]]);
        }
    }

    if (limited_)
    {
        // The reconstruction's limiter of each component of p, on the
        // column of the gradient that carries it
        const vectorField& phi = reconstruction_.momentumLimiter();
        forAll(grad, celli)
        {
            const vector& f = phi[celli];
            grad[celli] = cmptMultiply
            (
                grad[celli],
                tensor(f.x(), f.y(), f.z(), f.x(), f.y(), f.z(), f.x(), f.y(), f.z())
            );
        }
    }

    extrapolate(Ui, grad, scale, pointValues);
}


void Foam::linearPointInterpolation::interpolateMomentum
(
    const volVectorField& p,
    const scalar scale,
    vectorField& pointValues
) const
{
    const linearReconstruction::scheme scheme = reconstruction_.schemeType();
    const bool limitedAlike =
        limited_ == (scheme == linearReconstruction::scheme::limitedLinear);

    if (scheme == linearReconstruction::scheme::firstOrder || !limitedAlike)
    {
        interpolate(p, scale, pointValues);
        return;
    }

    extrapolate
    (
        p.primitiveField(),
        reconstruction_.gradp().primitiveField(),
        scale,
        pointValues
    );
}


void Foam::linearPointInterpolation::extrapolate
(
    const vectorField& Ui,
    const tensorField& grad,
    const scalar scale,
    vectorField& pointValues
) const
{
    const pointField& points = mesh_.points();
    const vectorField& X = reconstruction_.X();
    const compactAddressing::rows& pointCells =
        compactAddressing::New(mesh_).pointCells();

    for (label pointi = 0; pointi < pointCells.size(); ++pointi)
    {
        vector sum(Zero);
        for (const label celli : pointCells[pointi])
        {
            sum += Ui[celli] + ((points[pointi] - X[celli]) & grad[celli]);
        }
        pointValues[pointi] = sum;
    }

    syncTools::syncPointList
    (
        mesh_, pointValues, plusEqOp<vector>(), vector::zero
    );

    forAll(pointValues, pointi)
    {
        pointValues[pointi] *= scale*inverseNPointCells_[pointi];
    }
}


void Foam::linearPointInterpolation::addTranspose
(
    const vectorField& pointValues,
    vectorField& cellValues
) const
{
    const pointField& points = mesh_.points();
    const vectorField& X = reconstruction_.X();
    const compactAddressing& addressing = compactAddressing::New(mesh_);
    const compactAddressing::rows& cellPoints = addressing.cellPoints();
    const compactAddressing::rows& cells = addressing.cellFaces();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    const scalarField& inverseN = inverseNPointCells_;

    // Processor faces: this side's share leaves the cell here, and the
    // neighbour's share arrives from the other rank
    boundaryFaceWork_ = Zero;

    for (label celli = 0; celli < cellPoints.size(); ++celli)
    {
        // The mean and the extrapolation: the cell collects its points'
        // shares f_a/n_a, and the dual H_e = sum_a f_a/n_a (x) (X_a - X_e)
        // of its gradient
        vector sum(Zero);
        tensor H(Zero);
        for (const label pointi : cellPoints[celli])
        {
            // The point's share f_a/n_a
            const vector share(inverseN[pointi]*pointValues[pointi]);
            sum += share;
            H += share*(points[pointi] - X[celli]);
        }
        cellValues[celli] += sum;

        // Row d of the dual is component d's
        if (limited_)
        {
            const vector& phi = reconstruction_.momentumLimiter()[celli];
            H = tensor(phi.x()*H.x(), phi.y()*H.y(), phi.z()*H.z());
        }

        // The gradient of the cell gains w (x) (U_other - U_e) at each of
        // its faces, so the transpose moves H_e w from the cell to the
        // other one
        for (const label facei : cells[celli])
        {
            if (facei < nInternal)
            {
                const label other =
                    own[facei] == celli ? nei[facei] : own[facei];
                const vector q
                (
                    H
                  & reconstruction_.weight(celli, facei, X[other] - X[celli])
                );
                cellValues[other] += q;
                cellValues[celli] -= q;
                continue;
            }

            const label patchi = patches.patchID()[facei - nInternal];
            if (reconstruction_.mirror(patchi))
            {
                // The gradient gained w (x) (s R - I) U_e from the
                // reflected cell, R = I - 2 N N: its transpose, symmetric
                // as R, stays in the cell
                const label i = facei - mesh_.boundary()[patchi].start();
                const vector q(H & reconstruction_.coupledWeights(patchi)[i]);
                cellValues[celli] += reconstruction_.mirrorJump(patchi, i, q);
            }
            else if (mesh_.boundary()[patchi].coupled())
            {
                const label i = facei - mesh_.boundary()[patchi].start();
                const vector q(H & reconstruction_.coupledWeights(patchi)[i]);
                cellValues[celli] -= q;
                boundaryFaceWork_[facei - nInternal] = q;
            }
        }
    }

    syncTools::swapBoundaryFaceList(mesh_, boundaryFaceWork_);

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];

        if (patch.coupled())
        {
            forAll(patch, i)
            {
                cellValues[patch.faceCells()[i]] +=
                    boundaryFaceWork_[patch.start() + i - nInternal];
            }
        }
    }
}


// ************************************************************************* //
