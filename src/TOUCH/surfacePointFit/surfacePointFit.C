/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "surfacePointFit.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::surfacePointFit::calcWeights()
{
    const pointField& X = mesh_.points();
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const faceList& faces = mesh_.faces();

    // Mesh-point-sized sums, synchronised over the ranks: a point shared by
    // processors may have the patches' faces on one rank only and must get
    // the same value on every rank

    // The points' normals: the sum of their faces' area vectors
    vectorField normal(mesh_.nPoints(), Zero);
    for (const label facei : faces_)
    {
        for (const label pointi : faces[facei])
        {
            normal[pointi] += Sf[facei];
        }
    }
    syncTools::syncPointList(mesh_, normal, plusEqOp<vector>(), vector::zero);

    DynamicList<label> points;
    forAll(normal, pointi)
    {
        if (magSqr(normal[pointi]) > 0)
        {
            points.append(pointi);
        }
    }
    points_.transfer(points);
    normal /= mag(normal) + VSMALL;

    // The least-squares sums with the offsets in the tangent planes
    scalarField s0(mesh_.nPoints(), Zero);
    vectorField s1(mesh_.nPoints(), Zero);
    symmTensorField s2(mesh_.nPoints(), Zero);
    for (const label facei : faces_)
    {
        for (const label pointi : faces[facei])
        {
            const vector d(Cf[facei] - X[pointi]);
            const vector dt(d - (normal[pointi] & d)*normal[pointi]);
            s0[pointi] += 1;
            s1[pointi] += dt;
            s2[pointi] += sqr(dt);
        }
    }
    syncTools::syncPointList(mesh_, s0, plusEqOp<scalar>(), scalar(0));
    syncTools::syncPointList(mesh_, s1, plusEqOp<vector>(), vector::zero);
    syncTools::syncPointList
    (
        mesh_, s2, plusEqOp<symmTensor>(), symmTensor::zero
    );

    m0_.setSize(points_.size());
    m_.setSize(points_.size());
    forAll(points_, k)
    {
        const label pointi = points_[k];

        // The pseudo-inverse of s2 within the tangent plane: s2 has no part
        // along the normal, so inv(s2 + tr nn) - nn/tr where the faces span
        // the plane, s2/tr^2 where they lie in a row
        const symmTensor& S = s2[pointi];
        const scalar trace = tr(S);
        m0_[k] = 1/max(s0[pointi], scalar(1));
        m_[k] = Zero;
        if (trace <= VSMALL)
        {
            continue;
        }

        const symmTensor nn(sqr(normal[pointi]));
        const symmTensor full(S + trace*nn);
        const symmTensor Sinv
        (
            det(full)/trace > 1e-6*sqr(trace)
          ? inv(full) - nn/trace
          : S/sqr(trace)
        );

        const vector Sinvs1(Sinv & s1[pointi]);
        const scalar schur = s0[pointi] - (s1[pointi] & Sinvs1);
        if (schur > 1e-6*s0[pointi])
        {
            m0_[k] = 1/schur;
            m_[k] = -m0_[k]*Sinvs1;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfacePointFit::surfacePointFit
(
    const fvMesh& mesh,
    const labelUList& patches
)
:
    mesh_(mesh)
{
    DynamicList<label> faces;
    for (const label patchi : patches)
    {
        const polyPatch& patch = mesh_.boundaryMesh()[patchi];
        forAll(patch, i)
        {
            faces.append(patch.start() + i);
        }
    }
    faces_.transfer(faces);

    if (returnReduce(faces_.size(), sumOp<label>()) == 0)
    {
        return;
    }
    calcWeights();

    // The scratch sums only where there is a contact surface: a mesh
    // without one pays nothing
    if (active())
    {
        sumV_.setSize(mesh_.nPoints());
        sumDV_.setSize(mesh_.nPoints());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::surfacePointFit::active() const
{
    return returnReduce(points_.size(), sumOp<label>()) > 0;
}


void Foam::surfacePointFit::interpolate
(
    const vectorField& faceValues,
    vectorField& pointValues
) const
{
    const pointField& X = mesh_.points();
    const vectorField& Cf = mesh_.faceCentres();
    const faceList& faces = mesh_.faces();

    vectorField& sumV = sumV_;
    tensorField& sumDV = sumDV_;
    sumV = Zero;
    sumDV = Zero;
    for (const label facei : faces_)
    {
        const vector& v = faceValues[facei];
        for (const label pointi : faces[facei])
        {
            sumV[pointi] += v;
            sumDV[pointi] += (Cf[facei] - X[pointi])*v;
        }
    }
    syncTools::syncPointList(mesh_, sumV, plusEqOp<vector>(), vector::zero);
    syncTools::syncPointList(mesh_, sumDV, plusEqOp<tensor>(), tensor::zero);

    forAll(points_, k)
    {
        const label pointi = points_[k];
        pointValues[pointi] = m0_[k]*sumV[pointi] + (m_[k] & sumDV[pointi]);
    }
}


// ************************************************************************* //
