/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The overlap of two contact faces seen along the pair's normal: both
    faces are split into triangles about their centres, projected on the
    plane normal to n, and every triangle of one is clipped by every
    triangle of the other (Sutherland and Hodgman, CACM 17 (1974) 32-42);
    the overlap is the sum of the clipped areas.  It is the pair's share of
    both faces (the mortar idea of non-matching interfaces: the same area
    on both sides, so that the forces are equal and opposite and a face
    covered by several partners is loaded by each in proportion), scaled
    from the projection to the faces' current areas.

\*---------------------------------------------------------------------------*/

#include "contactSurfaces.H"
#include "vector2D.H"
#include "FixedList.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
    //- A triangle in the plane, counter-clockwise
    typedef FixedList<vector2D, 3> planeTriangle;

    //- Twice the signed area of the triangle (a, b, c)
    static scalar twiceSignedArea
    (
        const vector2D& a,
        const vector2D& b,
        const vector2D& c
    )
    {
        return (b.x() - a.x())*(c.y() - a.y()) - (b.y() - a.y())*(c.x() - a.x());
    }

    //- The area of the intersection of two counter-clockwise triangles
    //  and its first moment (area times centroid): the first clipped by
    //  the half-planes left of the second's edges (a triangle clipped by
    //  three half-planes has at most six corners)
    static scalar intersectionArea
    (
        const planeTriangle& a,
        const planeTriangle& b,
        vector2D& moment
    )
    {
        FixedList<vector2D, 8> polygon;
        FixedList<vector2D, 8> clipped;
        label n = 3;
        for (label k = 0; k < 3; ++k)
        {
            polygon[k] = a[k];
        }

        for (label e = 0; e < 3 && n > 0; ++e)
        {
            const vector2D& p = b[e];
            const vector2D& q = b[(e + 1) % 3];

            label m = 0;
            for (label k = 0; k < n; ++k)
            {
                const vector2D& cur = polygon[k];
                const vector2D& prev = polygon[(k + n - 1) % n];
                const scalar dCur = twiceSignedArea(p, q, cur);
                const scalar dPrev = twiceSignedArea(p, q, prev);

                if ((dCur >= 0) != (dPrev >= 0))
                {
                    const scalar s = dPrev/(dPrev - dCur);
                    clipped[m++] = prev + s*(cur - prev);
                }
                if (dCur >= 0)
                {
                    clipped[m++] = cur;
                }
            }

            n = m;
            for (label k = 0; k < n; ++k)
            {
                polygon[k] = clipped[k];
            }
        }

        scalar twice = 0;
        moment = vector2D::zero;
        for (label k = 1; k + 1 < n; ++k)
        {
            const scalar t =
                twiceSignedArea(polygon[0], polygon[k], polygon[k + 1]);
            twice += t;
            moment += (t/6)*(polygon[0] + polygon[k] + polygon[k + 1]);
        }
        return 0.5*twice;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::contactSurfaces::overlapArea
(
    const label gi,
    const label gj,
    const vector& n,
    scalar& gap
) const
{
    // Faces whose projected discs (about the centres, through the farthest
    // point) lie apart do not overlap: most of a face's candidates, tested
    // without building their triangles
    auto projectedRadius = [&](const label g)
    {
        scalar r2 = 0;
        for (label o = pointStart_[g]; o < pointStart_[g + 1]; ++o)
        {
            const vector& d = pointOffsets_[o];
            r2 = max(r2, magSqr(d) - sqr(d & n));
        }
        return Foam::sqrt(max(r2, scalar(0)));
    };
    {
        const vector d(x_[gj] - x_[gi]);
        const scalar apart = Foam::sqrt(max(magSqr(d) - sqr(d & n), 0.0));
        if (apart >= projectedRadius(gi) + projectedRadius(gj))
        {
            return 0;
        }
    }

    // A basis of the plane normal to n, about face gi's centre (offsets
    // of the size of the faces: no round-off from the positions' size)
    vector e1(n ^ vector(1, 0, 0));
    if (magSqr(e1) < 0.5)
    {
        e1 = n ^ vector(0, 1, 0);
    }
    e1 /= mag(e1);
    const vector e2(n ^ e1);
    const point& origin = x_[gi];

    // The faces' triangles about their centres, counter-clockwise in the
    // plane, and the faces' projected areas
    auto triangles = [&](const label g, scalar& projected)
    {
        const label first = pointStart_[g];
        const label nPoints = pointStart_[g + 1] - first;
        const vector2D centre
        (
            (x_[g] - origin) & e1,
            (x_[g] - origin) & e2
        );

        List<planeTriangle> tris(nPoints);
        projected = 0;
        for (label k = 0; k < nPoints; ++k)
        {
            const vector a(x_[g] + pointOffsets_[first + k] - origin);
            const vector b
            (
                x_[g] + pointOffsets_[first + (k + 1) % nPoints] - origin
            );
            planeTriangle& t = tris[k];
            t[0] = centre;
            t[1] = vector2D(a & e1, a & e2);
            t[2] = vector2D(b & e1, b & e2);
            const scalar twice = twiceSignedArea(t[0], t[1], t[2]);
            if (twice < 0)
            {
                Swap(t[1], t[2]);
            }
            projected += 0.5*mag(twice);
        }
        return tris;
    };

    scalar projectedI = 0;
    scalar projectedJ = 0;
    const List<planeTriangle> trisI(triangles(gi, projectedI));
    const List<planeTriangle> trisJ(triangles(gj, projectedJ));

    // A face seen edge-on along n has no share
    if
    (
        projectedI <= SMALL*a_[gi]
     || projectedJ <= SMALL*a_[gj]
    )
    {
        return 0;
    }

    scalar overlap = 0;
    vector2D moment(vector2D::zero);
    // Each triangle's bounding box: pairs of boxes apart are not clipped
    auto box = [](const planeTriangle& t, vector2D& lo, vector2D& hi)
    {
        lo = hi = t[0];
        for (label k = 1; k < 3; ++k)
        {
            lo = vector2D(min(lo.x(), t[k].x()), min(lo.y(), t[k].y()));
            hi = vector2D(max(hi.x(), t[k].x()), max(hi.y(), t[k].y()));
        }
    };
    List<vector2D> loJ(trisJ.size());
    List<vector2D> hiJ(trisJ.size());
    forAll(trisJ, k)
    {
        box(trisJ[k], loJ[k], hiJ[k]);
    }

    for (const planeTriangle& ti : trisI)
    {
        vector2D loI;
        vector2D hiI;
        box(ti, loI, hiI);
        forAll(trisJ, k)
        {
            if
            (
                loI.x() >= hiJ[k].x() || loJ[k].x() >= hiI.x()
             || loI.y() >= hiJ[k].y() || loJ[k].y() >= hiI.y()
            )
            {
                continue;
            }
            const planeTriangle& tj = trisJ[k];
            vector2D m;
            overlap += intersectionArea(ti, tj, m);
            moment += m;
        }
    }
    if (overlap <= 0)
    {
        return 0;
    }

    // The gap at the overlap's centroid: from face gi's plane to face
    // gj's along n (the centres' gap for matching faces; for faces that
    // do not match, the planes' distance where they meet)
    const vector2D c(moment/overlap);
    const point p(origin + c.x()*e1 + c.y()*e2);
    gap =
        ((x_[gj] - p) & n_[gj])/(n & n_[gj])
      - ((x_[gi] - p) & n_[gi])/(n & n_[gi]);

    // From the projection to the current areas (the faces' areas by
    // Nanson, as their tractions are per current area): the two faces'
    // mean factor, the same on both sides
    return overlap*0.5*(a_[gi]/projectedI + a_[gj]/projectedJ);
}


// ************************************************************************* //
