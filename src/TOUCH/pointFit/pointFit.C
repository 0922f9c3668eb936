/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "pointFit.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::pointFit::calcWeights()
{
    const pointField& points = mesh_.points();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Cf = mesh_.faceCentres();
    const faceList& faces = mesh_.faces();
    const labelListList& pointCells = mesh_.pointCells();

    // The empty patches' faces too: a 2D mesh's points have the centres of
    // their cells in one plane, and the fit across it needs the faces'
    // values (the caller gives them as a symmetric plane's)
    DynamicList<label> boundaryFaces;
    for (const polyPatch& patch : mesh_.boundaryMesh())
    {
        if (!patch.coupled())
        {
            forAll(patch, i)
            {
                boundaryFaces.append(patch.start() + i);
            }
        }
    }
    boundaryFaces_.transfer(boundaryFaces);

    // The least-squares matrix of each point, [1 d; d d d]
    scalarField s0(mesh_.nPoints(), Zero);
    vectorField s1(mesh_.nPoints(), Zero);
    symmTensorField s2(mesh_.nPoints(), Zero);

    auto add = [&](const label pointi, const vector& centre)
    {
        const vector d(centre - points[pointi]);
        s0[pointi] += 1;
        s1[pointi] += d;
        s2[pointi] += sqr(d);
    };

    forAll(pointCells, pointi)
    {
        for (const label celli : pointCells[pointi])
        {
            add(pointi, C[celli]);
        }
    }
    for (const label facei : boundaryFaces_)
    {
        for (const label pointi : faces[facei])
        {
            add(pointi, Cf[facei]);
        }
    }

    syncTools::syncPointList(mesh_, s0, plusEqOp<scalar>(), scalar(0));
    syncTools::syncPointList(mesh_, s1, plusEqOp<vector>(), vector::zero);
    syncTools::syncPointList
    (
        mesh_, s2, plusEqOp<symmTensor>(), symmTensor::zero
    );

    // First row of the inverse, by the Schur complement of s2
    forAll(points, pointi)
    {
        const symmTensor& S = s2[pointi];
        const scalar scale = tr(S)/3;

        if (det(S) > 1e-9*pow3(scale))
        {
            const vector Sinvs1(inv(S) & s1[pointi]);
            const scalar schur = s0[pointi] - (s1[pointi] & Sinvs1);

            if (schur > 1e-6*s0[pointi])
            {
                m0_[pointi] = 1/schur;
                m_[pointi] = -m0_[pointi]*Sinvs1;
                continue;
            }
        }

        // Centres that do not determine a linear fit (a point of a
        // one-cell-thick layer): their mean
        m0_[pointi] = 1/max(s0[pointi], scalar(1));
        m_[pointi] = Zero;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pointFit::pointFit(const fvMesh& mesh)
:
    mesh_(mesh),
    m0_(mesh.nPoints(), Zero),
    m_(mesh.nPoints(), Zero),
    sumV_(mesh.nPoints()),
    sumDV_(mesh.nPoints())
{
    calcWeights();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pointFit::interpolate
(
    const vectorField& cellValues,
    const scalar cellScale,
    const vectorField& faceValues,
    vectorField& pointValues
) const
{
    const pointField& points = mesh_.points();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Cf = mesh_.faceCentres();
    const faceList& faces = mesh_.faces();
    const labelListList& pointCells = mesh_.pointCells();

    sumV_ = Zero;
    sumDV_ = Zero;

    forAll(pointCells, pointi)
    {
        for (const label celli : pointCells[pointi])
        {
            const vector v(cellScale*cellValues[celli]);
            sumV_[pointi] += v;
            sumDV_[pointi] += (C[celli] - points[pointi])*v;
        }
    }
    for (const label facei : boundaryFaces_)
    {
        const vector& v = faceValues[facei];
        for (const label pointi : faces[facei])
        {
            sumV_[pointi] += v;
            sumDV_[pointi] += (Cf[facei] - points[pointi])*v;
        }
    }

    syncTools::syncPointList(mesh_, sumV_, plusEqOp<vector>(), vector::zero);
    syncTools::syncPointList
    (
        mesh_, sumDV_, plusEqOp<tensor>(), tensor::zero
    );

    forAll(pointValues, pointi)
    {
        pointValues[pointi] =
            m0_[pointi]*sumV_[pointi] + (m_[pointi] & sumDV_[pointi]);
    }
}


// ************************************************************************* //
