/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's face loop: the central nodal forces of every
    face (addFaceForces, addBoundaryFaceForces) and the momentum upwinding
    of the interior and processor faces, phi^2 (or phi) of each cell jump
    through the Riemann solver's upwind traction, of one material
    (addFaceRates) or of several (addFaceRatesOfMaterials).

\*---------------------------------------------------------------------------*/

#include "compatible.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

inline Foam::vector Foam::deformationUpdates::compatible::upwindForce
(
    const vector& cellJump,
    const vector& reconstructedJump,
    const tensor& FSum,
    const vector& Sf,
    const scalar magSf
) const
{
    // The central traction is the point coupling's; the upwind part damps
    // the share of the cell jump the reconstruction keeps: the flux of the
    // jump alone
    if (upwindInline_)
    {
        // With m = cof(F_L + F_R) S_f, the spatial normal's projector
        // n n = m m/|m|^2: no square root. The share phi = a/c, a the
        // reconstructed jump along the cell jump clipped to [0, c], c =
        // |cell jump|^2 (jumpShare), and 1/|m|^2 come from one division:
        // the face loop waited on two, one after the other
        const scalar c = magSqr(cellJump);
        const scalar a =
            min(max(reconstructedJump & cellJump, scalar(0)), c);
        const vector m(cof(FSum) & Sf);
        const scalar mSqr = magSqr(m);
        const scalar denominator = c*c*mSqr;

        if (denominator < VSMALL)
        {
            // No jump (the share is 0), or one too small to divide by
            // (a non-finite one goes on, to be caught with the cell)
            return Zero;
        }

        // share/|m|^2: phi^2/|m|^2 = a^2/(c^2 |m|^2), phi/|m|^2 = a c/(..)
        const scalar inverse = 1/denominator;
        const scalar shareByMSqr = (quadraticShare_ ? a*a : a*c)*inverse;
        const scalar cN = upwindNormal_;
        const scalar cT = upwindTangential_;

        return
            (magSf*shareByMSqr)
           *(cT*mSqr*cellJump + ((cN - cT)*(m & cellJump))*m);
    }

    return riemannUpwindForce(cellJump, reconstructedJump, FSum, Sf, magSf);
}


Foam::vector Foam::deformationUpdates::compatible::riemannUpwindForce
(
    const vector& cellJump,
    const vector& reconstructedJump,
    const tensor& FSum,
    const vector& Sf,
    const scalar magSf
) const
{
    const vector dp(upwindShare(reconstructedJump, cellJump)*cellJump);

    return
        magSf
       *riemann_.upwindTraction(dp, solidFaces::spatialNormal(FSum, Sf));
}


inline void Foam::deformationUpdates::compatible::addFaceForces
(
    const label facei,
    const Foam::face& f,
    const vector& S,
    const tensor& PJump,
    const bool reconstructed
)
{
    // The central nodal forces of both sides, (P_L - P_R) & s_a at each
    // point a of the face, and, at faces that are not a condition's, the
    // reconstructed traction forces in equal shares
    const vector central(PJump & S);
    const scalar invSize = facePointShares::inverseSize(f.size());

    if (shares_.uniform())
    {
        const vector share(central*invSize);
        for (const label pointi : f)
        {
            pointForce_[pointi] += share;
        }
    }
    else
    {
        shares_.forAllPoints
        (
            f, facei, S,
            [&](const label pointi, const vector& s)
            {
                pointForce_[pointi] += PJump & s;
            }
        );
    }

    if (reconstructed)
    {
        const vector share((central + faceIncrementForce_[facei])*invSize);
        for (const label pointi : f)
        {
            reconstructedForce_[pointi] += share;
        }
    }
}


void Foam::deformationUpdates::compatible::addBoundaryFaceForces()
{
    // The interior faces' are added by the face loop (addFaceRates)
    const fvMesh& mesh = faces_.mesh();
    const faceList& faces = mesh.faces();
    const vectorField& Sf = mesh.faceAreas();
    const tensorField& P = faces_.P().primitiveField();
    const bool upwindPoints = pointUpwinding_ > 0;

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        const labelUList& faceCells = patch.faceCells();

        // Each side of a processor face adds its own part
        const bool reconstructed = upwindPoints && patch.coupled();
        forAll(faceCells, i)
        {
            const label facei = patch.start() + i;
            addFaceForces
            (
                facei, faces[facei], Sf[facei], P[faceCells[i]],
                reconstructed
            );
        }
    }
}


void Foam::deformationUpdates::compatible::addFaceRates
(
    vectorField& lmRate
)
{
    if (!law_.uniformMaterial())
    {
        addFaceRatesOfMaterials(lmRate);
        return;
    }

    // With preservation, the cell jumps less the jump of the body's rigid
    // spin (zero otherwise), which no reconstruction keeps and which the
    // upwinding must not damp
    const bool spinning = magSqr(rigidSpin_) > 0;

    // The interior faces straight from the arrays: the per-face views of
    // solidFaces cost a fifth of this loop's instructions
    const fvMesh& mesh = faces_.mesh();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const vectorField& X = faces_.reconstructionCentres();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& Sf = mesh.faceAreas();
    const scalarField& magSf = mesh.magSf().primitiveField();
    const vectorField& p = faces_.lm().primitiveField();
    const tensorField& F = faces_.F().primitiveField();
    const tensorField& gradp =
        faces_.reconstruction().gradp().primitiveField();
    const vectorField& u = faces_.u().primitiveField();
    const tensorField& P = faces_.P().primitiveField();
    const faceList& faces = mesh.faces();
    const bool upwindPoints = pointUpwinding_ > 0;

    forAll(own, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];

        addFaceForces
        (
            facei, faces[facei], Sf[facei], P[o] - P[n], upwindPoints
        );

        vector jump(p[n] - p[o]);
        if (spinning)
        {
            jump -= rigidSpin_ ^ ((X[n] + u[n]) - (X[o] + u[o]));
        }

        const vector tC
        (
            upwindForce
            (
                jump,
                linearReconstruction::p(p[n], gradp[n], Cf[facei] - X[n])
              - linearReconstruction::p(p[o], gradp[o], Cf[facei] - X[o]),
                F[o] + F[n],
                Sf[facei],
                magSf[facei]
            )
        );

        lmRate[o] += tC;
        lmRate[n] -= tC;
    }

    faces_.forAllCoupledPatchFaces
    (
        [&](const solidFaces::coupledFace& face)
        {
            vector jump(face.right.lm - face.left.lm);
            if (spinning)
            {
                jump -= rigidSpin_ ^ (face.right.x() - face.left.x());
            }

            lmRate[face.owner] +=
                upwindForce
                (
                    jump,
                    face.pR() - face.pL(),
                    face.left.F + face.right.F,
                    face.Sf,
                    face.magSf
                );
        }
    );
}


Foam::vector Foam::deformationUpdates::compatible::materialUpwindForce
(
    const label mL,
    const label mR,
    const vector& cellJump,
    const vector& reconstructedJump,
    const tensor& FSum,
    const vector& Sf,
    const scalar magSf
) const
{
    // The share of the velocity jump the reconstruction keeps, damped with
    // Z_L Z_R/(Z_L + Z_R) per direction: rho Up/2 of the momentum jump's
    // Up/2 when the two sides are one material
    const vector dv(upwindShare(reconstructedJump, cellJump)*cellJump);

    const scalar rhoL = law_.materialRho(mL);
    const scalar rhoR = law_.materialRho(mR);

    return
        magSf
       *riemann_.interfaceUpwindTraction
        (
            dv,
            rhoL*law_.materialUp(mL), rhoL*law_.materialUs(mL),
            rhoR*law_.materialUp(mR), rhoR*law_.materialUs(mR),
            solidFaces::spatialNormal(FSum, Sf)
        );
}


void Foam::deformationUpdates::compatible::addFaceRatesOfMaterials
(
    vectorField& lmRate
)
{
    const fvMesh& mesh = faces_.mesh();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const vectorField& X = faces_.reconstructionCentres();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& Sf = mesh.faceAreas();
    const scalarField& magSf = mesh.magSf().primitiveField();
    const vectorField& p = faces_.lm().primitiveField();
    const tensorField& F = faces_.F().primitiveField();
    const tensorField& gradp =
        faces_.reconstruction().gradp().primitiveField();
    const tensorField& P = faces_.P().primitiveField();
    const faceList& faces = mesh.faces();
    const bool upwindPoints = pointUpwinding_ > 0;

    forAll(own, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];

        addFaceForces
        (
            facei, faces[facei], Sf[facei], P[o] - P[n], upwindPoints
        );

        const label mL = law_.material(o);
        const label mR = law_.material(n);
        const scalar invRhoL = 1/law_.materialRho(mL);
        const scalar invRhoR = 1/law_.materialRho(mR);

        const vector tC
        (
            materialUpwindForce
            (
                mL,
                mR,
                invRhoR*p[n] - invRhoL*p[o],
                invRhoR
               *linearReconstruction::p(p[n], gradp[n], Cf[facei] - X[n])
              - invRhoL
               *linearReconstruction::p(p[o], gradp[o], Cf[facei] - X[o]),
                F[o] + F[n],
                Sf[facei],
                magSf[facei]
            )
        );

        lmRate[o] += tC;
        lmRate[n] -= tC;
    }

    faces_.forAllCoupledPatchFaces
    (
        [&](const solidFaces::coupledFace& face)
        {
            const label mL = law_.material(face.owner);
            const label mR = rightMaterial(face.facei, face.neighbour);
            const scalar invRhoL = 1/law_.materialRho(mL);
            const scalar invRhoR = 1/law_.materialRho(mR);

            lmRate[face.owner] +=
                materialUpwindForce
                (
                    mL,
                    mR,
                    invRhoR*face.right.lm - invRhoL*face.left.lm,
                    invRhoR*face.pR() - invRhoL*face.pL(),
                    face.left.F + face.right.F,
                    face.Sf,
                    face.magSf
                );
        }
    );
}

// ************************************************************************* //
