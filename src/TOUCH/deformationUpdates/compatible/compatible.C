/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "declaredEntry.H"
#include "modelCoeffs.H"
#include "syncTools.H"
#include "Switch.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace deformationUpdates
{
    defineTypeNameAndDebug(compatible, 0);
    addToRunTimeSelectionTable(deformationUpdate, compatible, dictionary);
}
}


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- The share in [0, 1] of a cell jump that the reconstructed jump keeps
//  along it: upwinding phi (cell jump) damps like the reconstructed jump in
//  smooth regions (phi = O(h)) yet can never feed energy, which the
//  reconstructed jump itself does where it opposes the cell jump (least-
//  squares gradients on tetrahedra)
static inline scalar jumpShare(const vector& reconstructed, const vector& cell)
{
    const scalar cellSqr = magSqr(cell);

    if (cellSqr < VSMALL)
    {
        return 0;
    }

    return min(max((reconstructed & cell)/cellSqr, scalar(0)), scalar(1));
}

//- Add a face's force to its points, an equal share each
static inline void spreadToPoints
(
    const face& f,
    const vector& force,
    vectorField& pointValues
)
{
    const vector share(force/f.size());
    for (const label pointi : f)
    {
        pointValues[pointi] += share;
    }
}

//- Whether a condition of lm releases its faces on the force applied
static bool releasesOnForce(const volVectorField& lm)
{
    for (const fvPatchVectorField& pf : lm.boundaryField())
    {
        if
        (
            !pf.patch().coupled()
         && isA<solidFluxFvPatchVectorField>(pf)
         && refCast<const solidFluxFvPatchVectorField>(pf).releasesOnForce()
        )
        {
            return true;
        }
    }
    return false;
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> jumpShareEntry
    (
        "system/fvSolution TOUCH/compatibleCoeffs", "jumpShare",
        "the momentum upwinding damps phi^2 (quadratic)"
        " or phi (linear) of the cell jump, phi the limiter's share",
        "-", word("quadratic"), entryLimits::oneOf({"quadratic", "linear"})
    );

    static const declaredEntry<scalar> pointUpwindingEntry
    (
        "system/fvSolution TOUCH/compatibleCoeffs", "pointUpwinding",
        "weight of the upwinding of the point"
        " velocities (0: off)",
        "-", 1, entryLimits::above(0, true)
    );

    static const declaredEntry<Switch> pointLimiterEntry
    (
        "system/fvSolution TOUCH/compatibleCoeffs", "pointLimiter",
        "limited extrapolation of the point velocities"
        " (default: on with reconstruction limitedLinear, else off)",
        "-", Switch(Switch::OFF)
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

inline Foam::scalar Foam::deformationUpdates::compatible::upwindShare
(
    const vector& reconstructed,
    const vector& cell
) const
{
    const scalar phi = jumpShare(reconstructed, cell);

    return quadraticShare_ ? phi*phi : phi;
}


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


void Foam::deformationUpdates::compatible::addBoundaryRate
(
    const label stage,
    vectorField& lmRate,
    vector& torque,
    const bool decide
)
{
    const vectorField& lm = faces_.lm().primitiveField();

    faces_.forAllSolidPatches
    (
        law_,
        stage,
        [&]
        (
            const fvPatch& patch,
            solidFluxFvPatchVectorField& condition,
            const solidFluxFvPatchVectorField::interiorState& state,
            const solidFluxFvPatchVectorField::interiorState& reference
        )
        {
            const label patchi = patch.index();
            const labelUList& faceCells = patch.faceCells();
            const tensorField& free = faceFree_[patchi];

            // Declared with the reference normals: the constraints of a
            // plane are then the same at all its faces, so every processor
            // combines them alike
            condition.constraint
            (
                reference, faceFree_[patchi], faceVelocity_[patchi]
            );
            constraints_.add(patch, free, faceVelocity_[patchi]);

            // The fixed directions are damped towards the prescribed
            // momentum with the share of the cell's departure from it that
            // the reconstruction keeps there, which can never feed energy
            // (towards zero instead, a moving wall's bounce was off by
            // 1.2e-3 in momentum)
            vectorField& pM = faces_.interiorMomentum(patchi);
            forAll(faceCells, i)
            {
                const tensor fixed(tensor::I - free[i]);
                const vector pStar(state.rho[i]*faceVelocity_[patchi][i]);
                const vector departure((fixed & lm[faceCells[i]]) - pStar);
                pM[i] =
                    (free[i] & pM[i]) + pStar
                  + upwindShare((fixed & pM[i]) - pStar, departure)*departure;
            }

            // A condition that fixes directions is taken with the normals
            // its constraint was declared with: with the spatial normal of
            // the boundary cell (cof F N, off the plane's normal by O(h)
            // where the cell shears) the flux's normal traction did not
            // match the fixed part of the interior traction taken out
            // below, and the rest did work: a free-flying quarter bar
            // between symmetry planes gained 4e-7 E0 in a step
            bool fixesDirections = false;
            forAll(free, i)
            {
                if (magSqr(tensor::I - free[i]) > SMALL)
                {
                    fixesDirections = true;
                    break;
                }
            }

            boundaryFlux
            (
                patch, condition, fixesDirections ? reference : state, torque
            );

            // The prescribed traction of the free directions, and the
            // upwind damping of the fixed ones; their central traction is
            // the constraint's reaction
            const vectorField& tC = tC_[patchi];
            const scalarField& magSf = patch.magSf();
            vector faceForce(Zero);
            forAll(faceCells, i)
            {
                const tensor fixed(tensor::I - free[i]);
                const vector force((tC[i] - (fixed & state.t[i]))*magSf[i]);
                lmRate[faceCells[i]] += force;
                faceForce += force;
            }
            faceForce_[patchi] = faceForce;

            // Per face, for a condition released on the force applied
            if (releaseFaceForce_.set(patchi))
            {
                vectorField& force = releaseFaceForce_[patchi];
                forAll(faceCells, i)
                {
                    const tensor fixed(tensor::I - free[i]);
                    force[i] = (tC[i] - (fixed & state.t[i]))*magSf[i];
                }
            }

            // The torque of a wall is that of the force it applies: the
            // faces' part above and the constraint's reaction at the
            // points (reportWallForces), not the flux's central traction
            // at the faces, whose total differs from the reaction by up
            // to half of it on a curved body.  The difference turned with
            // the lever arm of the body's drift along the wall: a ring
            // sliding on it at 0.85 of its falling speed spun up to 0.17
            // |p| R_outer and left the wall 4 % early
            // (validation/ringImpact/FINDINGS.md)
            if (pointDisplacement_ && condition.reportsForce())
            {
                forAll(faceCells, i)
                {
                    const tensor fixed(tensor::I - free[i]);
                    torque -= state.x[i] ^ ((fixed & state.t[i])*magSf[i]);
                }
            }

            // The reconstructed traction against the condition's
            if (pointUpwinding_ > 0)
            {
                const faceList& faces = faces_.mesh().faces();
                forAll(faceCells, i)
                {
                    spreadToPoints
                    (
                        faces[patch.start() + i],
                        magSf[i]*(state.t[i] - tC[i]),
                        reconstructedForce_
                    );
                }
            }
        },
        decide
    );
}


void Foam::deformationUpdates::compatible::addTransposeRate
(
    vectorField& lmRate
)
{
    // The momentum rate does the opposite work of the central point
    // motion: -A^T Pi^T f
    constraints_.constrainTranspose(pointForce_);
    pointForce_ = -pointForce_;

    pointInterpolation_.addTranspose(pointForce_, lmRate);
}


bool Foam::deformationUpdates::compatible::readQuadraticShare
(
    const dictionary& coeffs
)
{
    return jumpShareEntry.read(coeffs) == "quadratic";
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdates::compatible::compatible
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    compatible
    (
        controls,
        modelCoeffs
        (
            controls,
            typeName,
            {&jumpShareEntry, &pointUpwindingEntry, &pointLimiterEntry}
        ),
        faces,
        law,
        riemann,
        reconstruction
    )
{}


Foam::deformationUpdates::compatible::compatible
(
    const dictionary& controls,
    const dictionary& coeffs,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    deformationUpdate(controls, faces, law, riemann, reconstruction),
    cellFaces_(compactAddressing::New(faces.mesh()).cellFaces()),
    pointInterpolation_
    (
        faces.mesh(),
        reconstruction,
        coeffs.found(pointLimiterEntry.name())
      ? pointLimiterEntry.read(coeffs)
      : Switch
        (
            reconstruction.schemeType()
         == linearReconstruction::scheme::limitedLinear
        )
    ),
    constraints_(faces.mesh()),
    faceFree_(faces.mesh().boundary().size()),
    faceVelocity_(faces.mesh().boundary().size()),
    faceForce_(faces.mesh().boundary().size(), Zero),
    fixingFace_(faces.mesh().boundary().size()),
    pointForce_(faces.mesh().nPoints(), Zero),
    quadraticShare_(readQuadraticShare(coeffs)),
    pointUpwinding_(pointUpwindingEntry.read(coeffs)),
    pointMobility_
    (
        law.uniformMaterial()
      ? calcPointMobility
        (
            faces.mesh(), reconstruction, pointUpwinding_, law.rho()*law.Up()
        )
      : calcPointMobilityOfMaterials(reconstruction, pointUpwinding_)
    ),
    reconstructedForce_(pointUpwinding_ > 0 ? faces.mesh().nPoints() : 0),
    faceIncrementForce_(pointUpwinding_ > 0 ? faces.mesh().nFaces() : 0),
    upwindNormal_(0),
    upwindTangential_(0),
    upwindInline_(riemann.upwindCoefficients(upwindNormal_, upwindTangential_)),
    hasContact_(contactSurfaces::any(faces.lm())),
    releasing_(releasesOnForce(faces.lm())),
    releaseFaceForce_(faces.mesh().boundary().size())
{
    forAll(faces.mesh().boundary(), patchi)
    {
        const label n = pC_[patchi].size();

        faceFree_.set(patchi, new tensorField(n, tensor::I));
        faceVelocity_.set(patchi, new vectorField(n, Zero));

        const fvPatchVectorField& bf = faces.lm().boundaryField()[patchi];
        if
        (
            !bf.patch().coupled()
         && isA<solidFluxFvPatchVectorField>(bf)
         && refCast<const solidFluxFvPatchVectorField>(bf).releasesOnForce()
        )
        {
            releaseFaceForce_.set(patchi, new vectorField(n, Zero));
        }

        // Contact between bodies: its faces' points keep the contact
        // velocity along the pair's normal (with the traction alone they
        // moved with the cells: two bars at +-0.1 m/s, 50 cells a bar, met
        // at 0.77 Z v, their ends sinking into each other at 0.46 v)
        fvPatchVectorField& pf = faces.lm().boundaryFieldRef()[patchi];
        if (isA<bodyContactFvPatchVectorField>(pf))
        {
            refCast<bodyContactFvPatchVectorField>(pf).setPointConstrained();
        }
    }

    initLosses();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::writeOptions(Ostream& os) const
{
    os  << " (" << jumpShareEntry.name() << ' '
        << (quadraticShare_ ? "quadratic" : "linear") << ", "
        << pointUpwindingEntry.name() << ' ' << pointUpwinding_ << ", "
        << pointLimiterEntry.name() << ' '
        << (pointInterpolation_.limited() ? "on" : "off") << ')';
}


void Foam::deformationUpdates::compatible::rates
(
    const label stage,
    vectorField& lmRate,
    tensorField& FRate,
    vectorField& pointV,
    vector& torque
)
{
    // The nodal forces and the reconstructed ones are in from
    // reconstruct()
    constraints_.reset();

    addFaceRates(lmRate);
    addBoundaryFaceForces();
    if (pointForcing_)
    {
        pointForcing_->addPointForces(shares_, pointForce_);
    }

    // The nodal forces are the stresses' alone: complete before the
    // conditions, so that a wall can be released on its reaction to them
    completeNodalForces();

    const bool tally = upwindLoss_.valid() && stage == 1;
    if (tally)
    {
        tallyFaceLosses();
        const vectorField before(lmRate);
        addConditionRates(stage, lmRate, torque);
        tallyCellLosses(before, lmRate);
    }
    else
    {
        addConditionRates(stage, lmRate, torque);
    }

    reportWallForces(torque);
    balanceContactForces(lmRate);

    // Point velocities v_a = Pi_a (A v)_a + b_a, and the upwinding of the
    // nodal forces
    if (law_.uniformMaterial())
    {
        pointInterpolation_.interpolateMomentum
        (
            faces_.lm(), 1/law_.rho(), pointV
        );
    }
    else
    {
        interpolateVelocity(pointV);
    }
    constraints_.constrain(pointV);

    if (pointUpwinding_ > 0)
    {
        if (tally)
        {
            const vectorField before(pointV);
            addPointUpwinding(pointV);
            tallyPointLosses(before, pointV);
        }
        else
        {
            addPointUpwinding(pointV);
        }
    }

    if (pointDisplacement_ && pointUpwinding_ > 0)
    {
        addDriftRotation(pointV);
    }

    // F follows the point motion alone (no upwind part: see the header)
    addFaceMeanFRate(pointV, FRate);

    addTransposeRate(lmRate);
}


Foam::scalar Foam::deformationUpdates::compatible::stableCFL
(
    const word& timeScheme
) const
{
    // Limited (the impacts): the Taylor bar on -n 6 gains energy above
    // 0.3 with either scheme (RK2 0.45: 3.4e-5 E0, RK3 0.5: 1.7e-3 E0),
    // and the bar rebound's cells invert at RK3 1.0 (-n 9, 12) and, on
    // polyhedra, 0.8 (validation/stabilityMap/FINDINGS.md 11): the
    // limiter, not the scheme's linear stability, sets the step there
    if
    (
        faces_.reconstruction().schemeType()
     == linearReconstruction::scheme::limitedLinear
    )
    {
        return 0.3;
    }

    // Twisting column, 4 x 24 x 4 and 8 x 48 x 8, nu 0.45, with the
    // quadratic jump share and the step of the cells' current heights:
    // the energy never grows up to these (at RK2 0.7 4 x 24 x 4 gains
    // 0.24 E0 in a step); RK3 holds to 1.0 also at nu 0.499, on
    // polyhedra and on tetrahedra (2 x 12 x 2: RK2 0.3, RK3 0.8;
    // validation/stabilityMap/FINDINGS.md 9, 10)
    return timeScheme == "RK3" ? 1.0 : 0.6;
}


// ************************************************************************* //
