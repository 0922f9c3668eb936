/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearPointInterpolation.H"
#include "syncTools.H"
#include "compactAddressing.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * //

const Foam::Enum<Foam::linearPointInterpolation::limiting>
Foam::linearPointInterpolation::limitingNames
({
    { limiting::none, "off" },
    { limiting::cell, "cell" },
    { limiting::point, "point" }
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearPointInterpolation::linearPointInterpolation
(
    const fvMesh& mesh,
    const linearReconstruction& reconstruction,
    const limiting limit
)
:
    mesh_(mesh),
    reconstruction_(reconstruction),
    inverseNPointCells_(mesh.nPoints(), Zero),
    cellWork_(),
    boundaryFaceWork_(mesh.nBoundaryFaces()),
    limiting_(limit),
    pointFactors_(),
    pointMax_(),
    pointMin_()
{
    if
    (
        limiting_ == limiting::cell
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
    vectorField& pointValues,
    const bool setFactors
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

    if (limiting_ == limiting::point)
    {
        if (setFactors || pointFactors_.empty())
        {
            setPointFactors(Ui, grad);
        }
        extrapolatePointLimited(Ui, grad, scale, pointValues);
        return;
    }

    if (limiting_ == limiting::cell)
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
        (limiting_ == limiting::cell)
     == (scheme == linearReconstruction::scheme::limitedLinear);

    if
    (
        scheme == linearReconstruction::scheme::firstOrder
     || !limitedAlike
     || limiting_ == limiting::point
    )
    {
        interpolate(p, scale, pointValues, true);
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


void Foam::linearPointInterpolation::setPointFactors
(
    const vectorField& Ui,
    const tensorField& grad
) const
{
    const pointField& points = mesh_.points();
    const vectorField& X = reconstruction_.X();
    const compactAddressing::rows& cellPoints =
        compactAddressing::New(mesh_).cellPoints();

    // The bounds at each point: its cells, their reflections across a
    // mirror it lies on, and the cells of the other ranks
    pointMax_.setSize(mesh_.nPoints());
    pointMin_.setSize(mesh_.nPoints());
    pointMax_ = vector::uniform(-GREAT);
    pointMin_ = vector::uniform(GREAT);

    scalar largest = 0;
    for (label celli = 0; celli < cellPoints.size(); ++celli)
    {
        const vector& U = Ui[celli];
        largest = max(largest, cmptMax(cmptMag(U)));
        for (const label pointi : cellPoints[celli])
        {
            pointMax_[pointi] = max(pointMax_[pointi], U);
            pointMin_[pointi] = min(pointMin_[pointi], U);
        }
    }

    forAll(mesh_.boundary(), patchi)
    {
        if (!reconstruction_.mirror(patchi))
        {
            continue;
        }
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        const labelUList& faceCells = pp.faceCells();
        forAll(pp, i)
        {
            const vector& U = Ui[faceCells[i]];
            const vector reflected(U + reconstruction_.mirrorJump(patchi, i, U));
            for (const label pointi : pp[i])
            {
                pointMax_[pointi] = max(pointMax_[pointi], reflected);
                pointMin_[pointi] = min(pointMin_[pointi], reflected);
            }
        }
    }

    syncTools::syncPointList
    (
        mesh_, pointMax_, maxEqOp<vector>(), vector::uniform(-GREAT)
    );
    syncTools::syncPointList
    (
        mesh_, pointMin_, minEqOp<vector>(), vector::uniform(GREAT)
    );

    // Overshoots below round-off of the field's largest value are left:
    // clipping noise would make the map depend on it
    reduce(largest, maxOp<scalar>());
    const scalar tolerance = 1e-12*largest;

    pointFactors_.setSize(compactAddressing::New(mesh_).cellPoints().nEntries());

    for (label celli = 0; celli < cellPoints.size(); ++celli)
    {
        const vector& U = Ui[celli];
        label entry = cellPoints.start(celli);
        for (const label pointi : cellPoints[celli])
        {
            const vector delta((points[pointi] - X[celli]) & grad[celli]);
            vector& factor = pointFactors_[entry++];
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                const scalar up = pointMax_[pointi][d] - U[d];
                const scalar down = pointMin_[pointi][d] - U[d];
                if (delta[d] > up + tolerance)
                {
                    factor[d] = max(up, scalar(0))/delta[d];
                }
                else if (delta[d] < down - tolerance)
                {
                    factor[d] = min(down, scalar(0))/delta[d];
                }
                else
                {
                    factor[d] = 1;
                }
            }
        }
    }
}


void Foam::linearPointInterpolation::extrapolatePointLimited
(
    const vectorField& Ui,
    const tensorField& grad,
    const scalar scale,
    vectorField& pointValues
) const
{
    const pointField& points = mesh_.points();
    const vectorField& X = reconstruction_.X();
    const compactAddressing::rows& cellPoints =
        compactAddressing::New(mesh_).cellPoints();

    pointValues = Zero;
    for (label celli = 0; celli < cellPoints.size(); ++celli)
    {
        label entry = cellPoints.start(celli);
        for (const label pointi : cellPoints[celli])
        {
            pointValues[pointi] +=
                Ui[celli]
              + cmptMultiply
                (
                    pointFactors_[entry++],
                    (points[pointi] - X[celli]) & grad[celli]
                );
        }
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
        const bool pointLimited = limiting_ == limiting::point;
        label entry = cellPoints.start(celli);
        for (const label pointi : cellPoints[celli])
        {
            // The point's share f_a/n_a
            const vector share(inverseN[pointi]*pointValues[pointi]);
            sum += share;
            H +=
                (
                    pointLimited
                  ? vector(cmptMultiply(share, pointFactors_[entry++]))
                  : share
                )
               *(points[pointi] - X[celli]);
        }
        cellValues[celli] += sum;

        // Row d of the dual is component d's
        if (limiting_ == limiting::cell)
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
