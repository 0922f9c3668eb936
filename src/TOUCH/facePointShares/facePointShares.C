/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "facePointShares.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::facePointShares::facePointShares(const fvMesh& mesh)
:
    offsets_(mesh.nFaces() + 1, 0),
    shares_()
{
    const faceList& faces = mesh.faces();
    const pointField& points = mesh.points();
    const vectorField& Sf = mesh.faceAreas();

    forAll(faces, facei)
    {
        offsets_[facei + 1] = offsets_[facei] + faces[facei].size();
    }

    vectorField shares(offsets_.last(), Zero);
    bool uniform = true;

    forAll(faces, facei)
    {
        const face& f = faces[facei];
        const label n = f.size();
        point c(Zero);
        forAll(f, fp)
        {
            c += points[f[fp]];
        }
        c /= n;
        const label start = offsets_[facei];

        // Area vector of triangle i: (p_i, p_i+1, c)
        for (label i = 0; i < n; ++i)
        {
            const point& a = points[f[i]];
            const point& b = points[f[(i + 1) % n]];
            const vector t(0.5*((b - a) ^ (c - a)));

            shares[start + i] += t/3;
            shares[start + (i + 1) % n] += t/3;
        }

        const scalar tol = 1e-12*mag(Sf[facei]);
        for (label i = 0; i < n; ++i)
        {
            shares[start + i] += Sf[facei]/(3*n);

            if (mag(shares[start + i] - Sf[facei]/n) > tol)
            {
                uniform = false;
            }
        }
    }

    if (!returnReduce(uniform, andOp<bool>()))
    {
        shares_.transfer(shares);
    }
    else
    {
        offsets_.clear();
    }
}


// ************************************************************************* //
