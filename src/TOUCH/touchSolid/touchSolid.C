/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
#include "solidFluxFvPatchVectorField.H"
#include "emptyFvPatch.H"
#include "calculatedFvPatchFields.H"
#include "calculatedPointPatchFields.H"
#include "Switch.H"
#include "mathematicalConstants.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(touchSolid, 0);
}


const Foam::Enum<Foam::touchSolid::deformationUpdate>
Foam::touchSolid::deformationUpdateNames
({
    { deformationUpdate::plain, "plain" },
    { deformationUpdate::constrained, "constrained" },
    { deformationUpdate::compatible, "compatible" },
});


const Foam::Enum<Foam::touchSolid::rungeKutta>
Foam::touchSolid::rungeKuttaNames
({
    { rungeKutta::RK2, "RK2" },
    { rungeKutta::RK3, "RK3" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Spatial unit normal n = F^-T N/|F^-T N|, via the cofactor (J F^-T)
static inline vector spatialNormal(const tensor& F, const vector& N)
{
    const vector n(cof(F) & N);
    return n/mag(n);
}


//- Smallest eigenvalue of a symmetric tensor, by the trigonometric solution
//  of the characteristic cubic (Smith, Comm. ACM 4 (1961) 168), which stays
//  real for repeated roots where a general cubic solver reports complex ones
static inline scalar minEigenValue(const symmTensor& A)
{
    const scalar q = tr(A)/3;
    const scalar p1 = sqr(A.xy()) + sqr(A.xz()) + sqr(A.yz());
    const scalar p2 =
        sqr(A.xx() - q) + sqr(A.yy() - q) + sqr(A.zz() - q) + 2*p1;
    const scalar p = Foam::sqrt(p2/6);

    if (p <= SMALL*mag(q))
    {
        return q;
    }

    const scalar r = det((A - q*symmTensor::I)/p)/2;
    const scalar phi = Foam::acos(min(max(r, scalar(-1)), scalar(1)))/3;

    return q + 2*p*Foam::cos(phi + constant::mathematical::twoPi/3);
}


//- Combine the velocity constraints of a point's faces: the product of
//  their projectors, which for the planes of a mesh commute
struct constrainEqOp
{
    void operator()(tensor& x, const tensor& y) const
    {
        x = (x & y);
    }
};


//- Combine the prescribed velocities of a point's faces: the larger
struct prescribeEqOp
{
    void operator()(vector& x, const vector& y) const
    {
        if (magSqr(y) > magSqr(x))
        {
            x = y;
        }
    }
};


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


//- IOobject of a field of the solid at the present time
static IOobject fieldIO
(
    const fvMesh& mesh,
    const word& name,
    const IOobject::readOption read,
    const IOobject::writeOption write
)
{
    return IOobject(name, mesh.time().timeName(), mesh, read, write);
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::touchSolid::checkBoundaryConditions() const
{
    if (lm_.dimensions() != dimDensity*dimVelocity)
    {
        FatalErrorInFunction
            << "Field " << lm_.objectPath() << " has dimensions "
            << lm_.dimensions() << "; linear momentum needs "
            << dimDensity*dimVelocity << " [kg/(m^2 s)]" << nl
            << exit(FatalError);
    }

    forAll(lm_.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = lm_.boundaryField()[patchi];

        if
        (
            !pf.coupled()
         && !isA<emptyFvPatch>(pf.patch())
         && !isA<solidFluxFvPatchVectorField>(pf)
        )
        {
            FatalErrorInFunction
                << "Entry boundaryField/" << pf.patch().name() << "/type '"
                << pf.type() << "' in " << lm_.objectPath()
                << " is not a solid boundary condition." << nl
                << "Valid types: symmetricPlane skewSymmetricPlane clamped"
                << " prescribedVelocity traction" << nl
                << exit(FatalError);
        }
    }
}


Foam::scalar Foam::touchSolid::calcHmin() const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& X = reconstruction_.X().primitiveField();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& Sf = mesh_.faceAreas();

    // The distance between neighbouring centres normal to their face:
    // the cell size for hexahedra, the inscribed scale for tetrahedra
    scalar h = GREAT;

    forAll(own, facei)
    {
        const vector N(Sf[facei]/mag(Sf[facei]));
        h = min(h, mag((X[nei[facei]] - X[own[facei]]) & N));
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& faceCells = patch.faceCells();

        if (patch.coupled())
        {
            const vectorField Xn
            (
                reconstruction_.X().boundaryField()[patchi]
               .patchNeighbourField()
            );

            forAll(faceCells, i)
            {
                const label facei = patch.start() + i;
                const vector N(Sf[facei]/mag(Sf[facei]));
                h = min(h, mag((Xn[i] - X[faceCells[i]]) & N));
            }
        }
        else
        {
            forAll(faceCells, i)
            {
                const label facei = patch.start() + i;
                const vector N(Sf[facei]/mag(Sf[facei]));
                h = min(h, 2*mag((Cf[facei] - X[faceCells[i]]) & N));
            }
        }
    }

    return returnReduce(h, minOp<scalar>());
}


Foam::tmp<Foam::vectorField> Foam::touchSolid::cellPositions
(
    const vectorField& u
) const
{
    return mesh_.C().primitiveField() + u;
}


void Foam::touchSolid::computeRates(const label stage)
{
    const scalar rho = law_->rho();

    // Neighbour values across processor patches, then the stress and the
    // limited gradients (exchanged as well)
    lm_.correctBoundaryConditions();
    F_.correctBoundaryConditions();
    law_->correct(F_, P_);
    reconstruction_.update(lm_, P_);

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& X = reconstruction_.X().primitiveField();

    const vectorField& lm = lm_.primitiveField();
    const tensorField& F = F_.primitiveField();
    const tensorField& P = P_.primitiveField();
    const tensorField& gp = reconstruction_.gradp().primitiveField();
    const tensorField& gx = reconstruction_.gradP(0).primitiveField();
    const tensorField& gy = reconstruction_.gradP(1).primitiveField();
    const tensorField& gz = reconstruction_.gradP(2).primitiveField();

    lmRate_ = Zero;
    FRate_ = Zero;
    torque_ = Zero;

    if (FUpdate_ == deformationUpdate::compatible)
    {
        pointConstraint_ = tensor::I;
        pointPrescribed_ = Zero;
    }

    // Flux of one face between a cell o (left) and a neighbour state (right)
    // given by its values at the neighbour centre Xn
    auto faceFlux = [&]
    (
        const label facei,
        const label o,
        const vector& lmN,
        const tensor& PN,
        const tensor& FN,
        const tensor& gpN,
        const tensor& gxN,
        const tensor& gyN,
        const tensor& gzN,
        const vector& Xn,
        vector& tC
    )
    {
        const scalar magSf = mag(Sf[facei]);
        const vector N(Sf[facei]/magSf);
        const vector rL(Cf[facei] - X[o]);
        const vector rR(Cf[facei] - Xn);

        const vector pL(linearReconstruction::p(lm[o], gp[o], rL));
        const vector pR(linearReconstruction::p(lmN, gpN, rR));
        const vector n(spatialNormal(0.5*(F[o] + FN), N));
        vector pC;

        if (FUpdate_ == deformationUpdate::compatible)
        {
            // The central traction is the point coupling's; the upwind
            // part damps the share of the cell jump the reconstruction
            // keeps: the flux of the jump alone
            const vector jump(lmN - lm[o]);
            riemann_->flux
            (
                Zero, Zero, jumpShare(pR - pL, jump)*jump, Zero, n, pC, tC
            );
        }
        else
        {
            const vector tL
            (
                linearReconstruction::P(P[o], gx[o], gy[o], gz[o], rL) & N
            );
            const vector tR
            (
                linearReconstruction::P(PN, gxN, gyN, gzN, rR) & N
            );
            riemann_->flux(pL, tL, pR, tR, n, pC, tC);
        }

        tC *= magSf;
        faceVelocity_[facei] = pC/rho;
    };

    forAll(own, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        vector tC;

        faceFlux
        (
            facei, o,
            lm[n], P[n], F[n], gp[n], gx[n], gy[n], gz[n], X[n],
            tC
        );

        lmRate_[o] += tC;
        lmRate_[n] -= tC;
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& faceCells = patch.faceCells();

        if (patch.coupled())
        {
            const vectorField lmN
            (
                lm_.boundaryField()[patchi].patchNeighbourField()
            );
            const tensorField PN
            (
                P_.boundaryField()[patchi].patchNeighbourField()
            );
            const tensorField FN
            (
                F_.boundaryField()[patchi].patchNeighbourField()
            );
            const tensorField gpN
            (
                reconstruction_.gradp().boundaryField()[patchi]
               .patchNeighbourField()
            );
            const tensorField gxN
            (
                reconstruction_.gradP(0).boundaryField()[patchi]
               .patchNeighbourField()
            );
            const tensorField gyN
            (
                reconstruction_.gradP(1).boundaryField()[patchi]
               .patchNeighbourField()
            );
            const tensorField gzN
            (
                reconstruction_.gradP(2).boundaryField()[patchi]
               .patchNeighbourField()
            );
            const vectorField XN
            (
                reconstruction_.X().boundaryField()[patchi]
               .patchNeighbourField()
            );

            forAll(faceCells, i)
            {
                vector tC;

                faceFlux
                (
                    patch.start() + i, faceCells[i],
                    lmN[i], PN[i], FN[i], gpN[i], gxN[i], gyN[i], gzN[i],
                    XN[i],
                    tC
                );

                lmRate_[faceCells[i]] += tC;
            }

            continue;
        }

        if (patch.size() == 0)
        {
            continue;
        }

        // A solid boundary condition: the flux from the interior state
        vectorField pM(patch.size());
        vectorField tM(patch.size());
        vectorField nM(patch.size());
        vectorField xM(patch.size());
        const scalarField& magSf = patch.magSf();

        forAll(faceCells, i)
        {
            const label facei = patch.start() + i;
            const label o = faceCells[i];
            const vector N(Sf[facei]/magSf[i]);
            const vector r(Cf[facei] - X[o]);

            pM[i] = linearReconstruction::p(lm[o], gp[o], r);
            tM[i] = linearReconstruction::P(P[o], gx[o], gy[o], gz[o], r) & N;
            nM[i] = spatialNormal(F[o], N);
            xM[i] = X[o] + u_[o] + (F[o] & r);
        }

        const solidFluxFvPatchVectorField& condition =
            refCast<const solidFluxFvPatchVectorField>
            (
                lm_.boundaryField()[patchi]
            );

        if (FUpdate_ == deformationUpdate::compatible)
        {
            pointConstraints(patch, condition, pM, tM, xM, stage);
        }

        const solidFluxFvPatchVectorField::interiorState interior
        {
            pM, tM, nM, xM, rho, law_->Up(), law_->Us(), stage
        };

        vectorField pC(patch.size());
        vectorField tC(patch.size());
        condition.flux(interior, pC, tC);

        forAll(faceCells, i)
        {
            torque_ += xM[i] ^ (tC[i]*magSf[i]);
            faceVelocity_[patch.start() + i] = pC[i]/rho;
        }

        if (FUpdate_ == deformationUpdate::compatible)
        {
            // The prescribed traction of the free directions, and the
            // upwind damping of the fixed ones; their central traction is
            // the constraint's reaction
            forAll(faceCells, i)
            {
                const tensor fixed(tensor::I - faceConstraint_[i]);
                lmRate_[faceCells[i]] += (tC[i] - (fixed & tM[i]))*magSf[i];
            }
        }
        else
        {
            forAll(faceCells, i)
            {
                lmRate_[faceCells[i]] += tC[i]*magSf[i];
            }
        }

        // The contact momentum is the boundary value written
        lm_.boundaryFieldRef()[patchi] == pC;
    }

    reduce(torque_, sumOp<vector>());

    if (FUpdate_ == deformationUpdate::compatible)
    {
        compatibleRates();
    }
    else
    {
        // Point velocities: the fit of the cell velocities and of the
        // contact velocities of the boundary faces
        pointFit_->interpolate
        (
            lm_.primitiveField(),
            1/rho,
            faceVelocity_,
            pointV_.primitiveFieldRef()
        );
    }

    if (FUpdate_ == deformationUpdate::constrained)
    {
        addPointFRate();
    }
    else if (FUpdate_ == deformationUpdate::plain)
    {
        // Plain TOUCH: the F flux carries the Riemann contact velocity
        forAll(own, facei)
        {
            const tensor flux(faceVelocity_[facei]*Sf[facei]);
            FRate_[own[facei]] += flux;
            FRate_[nei[facei]] -= flux;
        }

        forAll(mesh_.boundary(), patchi)
        {
            const fvPatch& patch = mesh_.boundary()[patchi];

            forAll(patch, i)
            {
                const label facei = patch.start() + i;
                FRate_[patch.faceCells()[i]] +=
                    faceVelocity_[facei]*Sf[facei];
            }
        }
    }

    const scalarField& V = mesh_.V();
    if (debug)
    {
        // The semi-discrete energy balance: the compatible update's rate is
        // the upwind dissipation plus the work of prescribed motion and
        // tractions
        scalar kinetic = 0;
        scalar stored = 0;
        forAll(V, celli)
        {
            kinetic += (lm_[celli]/rho) & lmRate_[celli];
            stored += P_[celli] && FRate_[celli];
        }
        reduce(kinetic, sumOp<scalar>());
        reduce(stored, sumOp<scalar>());
        Info<< "touchSolid: stage " << stage << " energy rate: kinetic "
            << kinetic << ", stored " << stored << endl;
    }
    forAll(V, celli)
    {
        lmRate_[celli] /= V[celli];
        FRate_[celli] /= V[celli];
    }
}


void Foam::touchSolid::pointConstraints
(
    const fvPatch& patch,
    const solidFluxFvPatchVectorField& condition,
    vectorField& pM,
    const vectorField& tM,
    const vectorField& xM,
    const label stage
)
{
    const scalar rho = law_->rho();
    const labelUList& faceCells = patch.faceCells();
    const vectorField& lm = lm_.primitiveField();

    // The velocity constraint of each face, read off the condition's
    // contact momentum, which is affine in p-: pC = Pi p- + ..., Pi the
    // projector onto the free directions.  Probed with the reference
    // normals: the projectors of a plane are then the same at all its faces
    // and commute at its edges, so every processor combines them alike
    const scalar dp = rho*law_->Us();
    const vectorField N(patch.nf());
    vectorField pProbe(pM);
    vectorField pCBase(patch.size());
    vectorField pCProbe(patch.size());
    vectorField tCProbe(patch.size());
    const solidFluxFvPatchVectorField::interiorState probe
    {
        pProbe, tM, N, xM, rho, law_->Up(), law_->Us(), stage
    };

    condition.flux(probe, pCBase, tCProbe);

    faceConstraint_.setSize(patch.size());
    faceConstraint_ = Zero;

    for (direction d = 0; d < vector::nComponents; ++d)
    {
        vector e(Zero);
        e[d] = dp;
        pProbe = pM + e;
        condition.flux(probe, pCProbe, tCProbe);

        forAll(pCProbe, i)
        {
            const vector column((pCProbe[i] - pCBase[i])/dp);
            for (direction j = 0; j < vector::nComponents; ++j)
            {
                faceConstraint_[i](j, d) = column[j];
            }
        }
    }

    const faceList& faces = mesh_.faces();

    forAll(faceCells, i)
    {
        const tensor& Pi = faceConstraint_[i];
        const tensor fixed(tensor::I - Pi);

        const vector prescribed((fixed & pCBase[i])/rho);
        for (const label pointi : faces[patch.start() + i])
        {
            constrainEqOp()(pointConstraint_[pointi], Pi);
            prescribeEqOp()(pointPrescribed_[pointi], prescribed);
        }

        // The fixed directions are damped with the share of the cell's
        // momentum that the reconstruction keeps there, which can never
        // feed energy
        const vector cellFixed(fixed & lm[faceCells[i]]);
        pM[i] = (Pi & pM[i]) + jumpShare(fixed & pM[i], cellFixed)*cellFixed;
    }
}


void Foam::touchSolid::compatibleRates()
{
    const scalar rho = law_->rho();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const faceList& faces = mesh_.faces();
    const tensorField& P = P_.primitiveField();

    syncTools::syncPointList
    (
        mesh_, pointConstraint_, constrainEqOp(), tensor::I
    );
    syncTools::syncPointList
    (
        mesh_, pointPrescribed_, prescribeEqOp(), vector::zero
    );

    // Point velocities v_a = Pi_a (A v)_a + b_a
    vectorField& pointV = pointV_.primitiveFieldRef();
    pointInterpolation_.interpolate(lm_, 1/rho, pointV);

    forAll(pointV, pointi)
    {
        pointV[pointi] =
            (pointConstraint_[pointi] & pointV[pointi])
          + pointPrescribed_[pointi];
    }

    // F follows the point motion alone: an upwind part in the F flux
    // (the Riemann S_t [[t]] term) breaks compatibility with the points,
    // and with it the energy pairing; measured on the twisting column it
    // let the energy grow by 6e-2 E0 in a step
    addPointFRate();

    // Nodal forces f_a = sum over the faces at a of P C/n_f, for which the
    // stress power sum_e P_e : V_e dF_e/dt of the point motion is
    // sum_a f_a . v_a
    pointForce_ = Zero;

    auto spread = [&](const label facei, const vector& force)
    {
        const face& f = faces[facei];
        const vector share(force/f.size());
        for (const label pointi : f)
        {
            pointForce_[pointi] += share;
        }
    };

    forAll(own, facei)
    {
        spread(facei, (P[own[facei]] - P[nei[facei]]) & Sf[facei]);
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];

        forAll(patch, i)
        {
            const label facei = patch.start() + i;
            spread(facei, P[patch.faceCells()[i]] & Sf[facei]);
        }
    }

    syncTools::syncPointList
    (
        mesh_, pointForce_, plusEqOp<vector>(), vector::zero
    );

    // The momentum rate does the opposite work: -A^T Pi^T f
    forAll(pointForce_, pointi)
    {
        pointForce_[pointi] = -(pointConstraint_[pointi].T() & pointForce_[pointi]);
    }

    pointInterpolation_.addTranspose(pointForce_, lmRate_);
}


void Foam::touchSolid::addPointFRate()
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const faceList& faces = mesh_.faces();
    const vectorField& pointV = pointV_.primitiveField();

    // Face velocity: the mean of its points' velocities, so that F stays
    // the gradient of the point motion (curl-free)
    auto faceMean = [&](const label facei)
    {
        const face& f = faces[facei];
        vector v(Zero);
        forAll(f, fp)
        {
            v += pointV[f[fp]];
        }
        return v/f.size();
    };

    forAll(own, facei)
    {
        const tensor flux(faceMean(facei)*Sf[facei]);
        FRate_[own[facei]] += flux;
        FRate_[nei[facei]] -= flux;
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];

        forAll(patch, i)
        {
            const label facei = patch.start() + i;
            FRate_[patch.faceCells()[i]] += faceMean(facei)*Sf[facei];
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::label Foam::touchSolid::compatiblePointsSize(const fvMesh& mesh) const
{
    return FUpdate_ == deformationUpdate::compatible ? mesh.nPoints() : 0;
}


Foam::touchSolid::touchSolid(const fvMesh& mesh)
:
    mesh_(mesh),
    controls_(mesh.solutionDict().subDict("TOUCH")),
    law_(mechanicalLaw::New(mesh)),
    riemann_(riemannSolver::New(controls_, *law_)),
    reconstruction_(mesh, controls_),
    angularMomentum_(mesh),
    pointInterpolation_(mesh, reconstruction_),
    CFL_(controls_.get<scalar>("CFL")),
    preserveAngularMomentum_
    (
        controls_.get<Switch>("angularMomentumPreservation")
    ),
    FUpdate_
    (
        deformationUpdateNames.getOrDefault
        (
            "FUpdate",
            controls_,
            deformationUpdate::compatible
        )
    ),
    rungeKuttaAlpha_
    (
        rungeKuttaNames.getOrDefault
        (
            "timeScheme",
            controls_,
            rungeKutta::RK2
        ) == rungeKutta::RK2
      ? scalarList({0, 0.5})
      : scalarList({0, 0.75, 1.0/3.0})
    ),
    hMin_(calcHmin()),
    lm_
    (
        fieldIO(mesh, "lm", IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    F_
    (
        fieldIO(mesh, "F", IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        mesh,
        dimensionedTensor("I", dimless, tensor::I),
        calculatedFvPatchTensorField::typeName
    ),
    u_
    (
        fieldIO(mesh, "u", IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        mesh,
        dimensionedVector("0", dimLength, Zero),
        calculatedFvPatchVectorField::typeName
    ),
    pointU_
    (
        fieldIO(mesh, "pointU", IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        pointMesh::New(mesh),
        dimensionedVector("0", dimLength, Zero),
        calculatedPointPatchVectorField::typeName
    ),
    P_
    (
        fieldIO(mesh, "P", IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedTensor("0", dimPressure, Zero),
        calculatedFvPatchTensorField::typeName
    ),
    pointV_
    (
        fieldIO(mesh, "pointV", IOobject::NO_READ, IOobject::NO_WRITE),
        pointMesh::New(mesh),
        dimensionedVector("0", dimVelocity, Zero),
        calculatedPointPatchVectorField::typeName
    ),
    lm0_(mesh.nCells()),
    F0_(mesh.nCells()),
    u0_(mesh.nCells()),
    pointU0_(mesh.nPoints()),
    lmRate_(mesh.nCells()),
    FRate_(mesh.nCells()),
    faceVelocity_(mesh.nFaces(), Zero),
    pointConstraint_
    (
        compatiblePointsSize(mesh)
    ),
    pointPrescribed_
    (
        compatiblePointsSize(mesh)
    ),
    pointForce_
    (
        compatiblePointsSize(mesh)
    ),
    torque_(Zero),
    L0_(Zero),
    Lstage_(Zero)
{
    if (!(CFL_ > 0 && CFL_ <= 1))
    {
        FatalIOErrorInFunction(controls_)
            << "Entry 'CFL' = " << CFL_ << " in " << controls_.name()
            << " is out of range: valid values satisfy 0 < CFL <= 1" << nl
            << exit(FatalIOError);
    }

    checkBoundaryConditions();

    if (FUpdate_ != deformationUpdate::compatible)
    {
        pointFit_.reset(new pointFit(mesh_));
    }

    Info<< "TOUCH: rho " << law_->rho() << ", Up " << law_->Up()
        << ", Us " << law_->Us() << ", CFL " << CFL_
        << ", h_min " << hMin_ << nl
        << "    angular momentum preservation "
        << (preserveAngularMomentum_ ? "on" : "off")
        << ", F update " << deformationUpdateNames[FUpdate_]
        << ", " << rungeKuttaAlpha_.size() << "-stage SSP Runge-Kutta"
        << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::touchSolid::stableDeltaT() const
{
    // The fastest wave, Up, in the current configuration: reference lengths
    // shrink by the smallest principal stretch
    scalar minStretch = GREAT;

    forAll(F_, celli)
    {
        const tensor& F = F_[celli];
        minStretch = min(minStretch, minEigenValue(symm(F.T() & F)));
    }

    minStretch = Foam::sqrt(max(returnReduce(minStretch, minOp<scalar>()), 0));

    return CFL_*hMin_*minStretch/law_->Up();
}


void Foam::touchSolid::storeOldTime()
{
    lm0_ = lm_.primitiveField();
    F0_ = F_.primitiveField();
    u0_ = u_.primitiveField();
    pointU0_ = pointU_.primitiveField();

    if (preserveAngularMomentum_)
    {
        L0_ = angularMomentum_.total(cellPositions(u0_), lm0_);
        Lstage_ = L0_;
    }
}


void Foam::touchSolid::advanceStage(const label stage, const scalar dt)
{
    computeRates(stage);

    // Stage k of the SSP Runge-Kutta scheme in Shu-Osher form:
    //     U <- alpha U^n + (1 - alpha)(U + dt L(U))
    const scalar alpha = rungeKuttaAlpha_[stage - 1];
    const scalar beta = 1 - alpha;
    const scalar rho = law_->rho();

    vectorField& lm = lm_.primitiveFieldRef();
    tensorField& F = F_.primitiveFieldRef();
    vectorField& u = u_.primitiveFieldRef();
    vectorField& pointU = pointU_.primitiveFieldRef();
    const vectorField& pointV = pointV_.primitiveField();

    // u first: it advances with the stage momentum
    forAll(u, celli)
    {
        u[celli] =
            alpha*u0_[celli] + beta*(u[celli] + (dt/rho)*lm[celli]);
    }

    if (preserveAngularMomentum_)
    {
        // The stage ends at the positions just computed; its angular
        // momentum must be the same combination of the step's start and of
        // the present stage advanced by the boundary torque
        const vector Lend(alpha*L0_ + beta*(Lstage_ + dt*torque_));

        angularMomentum_.correct
        (
            cellPositions(u),
            alpha*lm0_ + beta*lm,
            beta*dt,
            Lend,
            lmRate_
        );

        Lstage_ = Lend;
    }

    forAll(lm, celli)
    {
        lm[celli] = alpha*lm0_[celli] + beta*(lm[celli] + dt*lmRate_[celli]);
        F[celli] = alpha*F0_[celli] + beta*(F[celli] + dt*FRate_[celli]);
    }
    forAll(pointU, pointi)
    {
        pointU[pointi] =
            alpha*pointU0_[pointi] + beta*(pointU[pointi] + dt*pointV[pointi]);
    }
}


bool Foam::touchSolid::valid() const
{
    bool ok = true;

    forAll(F_, celli)
    {
        const scalar J = det(F_[celli]);
        const scalar magLm = mag(lm_[celli]);

        if (!(J > 0) || !std::isfinite(J) || !std::isfinite(magLm))
        {
            ok = false;
            break;
        }
    }

    return returnReduce(ok, andOp<bool>());
}


void Foam::touchSolid::restoreOldTime()
{
    lm_.primitiveFieldRef() = lm0_;
    F_.primitiveFieldRef() = F0_;
    u_.primitiveFieldRef() = u0_;
    pointU_.primitiveFieldRef() = pointU0_;
}


Foam::vector Foam::touchSolid::totalLinearMomentum() const
{
    return gSum(mesh_.V()*lm_.primitiveField());
}


Foam::vector Foam::touchSolid::totalAngularMomentum() const
{
    return angularMomentum_.total
    (
        cellPositions(u_.primitiveField()),
        lm_.primitiveField()
    );
}


Foam::scalar Foam::touchSolid::kineticEnergy() const
{
    return gSum(mesh_.V()*magSqr(lm_.primitiveField()))/(2*law_->rho());
}


Foam::scalar Foam::touchSolid::strainEnergy() const
{
    return law_->totalStrainEnergy(F_);
}


void Foam::touchSolid::writeOutputFields() const
{
    const word& timeName = mesh_.time().timeName();
    const scalar rho = law_->rho();

    auto outputIO = [&](const word& name)
    {
        return IOobject
        (
            name,
            timeName,
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
    };

    // Stress of the final state (P_ holds the last stage's)
    volTensorField P(outputIO("P"), P_);
    forAll(P, celli)
    {
        P[celli] = law_->P(F_[celli]);
    }
    P.write();

    volVectorField v(outputIO("v"), lm_/rho);
    v.write();

    volScalarField J(outputIO("J"), det(F_));
    J.write();

    volSymmTensorField sigma(outputIO("sigma"), symm(P & F_.T())/J);
    sigma.write();

    volScalarField pressure(outputIO("pressure"), -tr(sigma)/3);
    pressure.write();
}


// ************************************************************************* //
