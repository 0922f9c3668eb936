/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    What touchSolid reports: the totals the monitor asks for every step
    (linear and angular momentum, kinetic and stored energy), the start-up
    summary of the log and the output fields written with each time.

    The output fields have the names OpenFOAM's solvers give them (U the
    velocity; solidDisplacementFoam's D and sigmaEq; solids4foam's pointD),
    so that a user finds them in ParaView where expected: U, P, J, sigma,
    sigmaEq, pressure and, with a rigid wall, contact.  The state (lm, F,
    gradD, D, pointD) writes itself.

\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
#include "calculatedFvPatchFields.H"
#include "rigidWallFvPatchVectorField.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- The values of a field's cells on its boundary patches (not on coupled
//  ones, which hold the neighbours').  The solver reads the patches of
//  processor faces only, so the others kept their initial values (F = I,
//  P = 0, D = 0): foamToVTK's patches showed zero stress and ParaView
//  interpolated the cells' values to the boundary points against them
template<class Type>
static void cellValuesOnPatches
(
    GeometricField<Type, fvPatchField, volMesh>& field
)
{
    for (fvPatchField<Type>& pf : field.boundaryFieldRef())
    {
        if (!pf.coupled())
        {
            pf = pf.patchInternalField();
        }
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::touchSolid::totalLinearMomentum() const
{
    // The totals are summed in place: the monitor asks for them every step
    const scalarField& V = mesh_.V();
    const vectorField& lm = lm_.primitiveField();

    vector sum(Zero);
    forAll(lm, celli)
    {
        sum += V[celli]*lm[celli];
    }

    return returnReduce(sum, sumOp<vector>());
}


Foam::vector Foam::touchSolid::totalAngularMomentum(const point& origin) const
{
    return
        angularMomentum_.total
        (
            mesh_.C().primitiveField(),
            D_.primitiveField(),
            lm_.primitiveField()
        )
      - (origin ^ totalLinearMomentum());
}


Foam::scalar Foam::touchSolid::kineticEnergy() const
{
    const scalarField& V = mesh_.V();
    const vectorField& lm = lm_.primitiveField();

    if (!law_->uniformMaterial())
    {
        scalar sum = 0;
        forAll(lm, celli)
        {
            sum += V[celli]*magSqr(lm[celli])/law_->rho(celli);
        }
        return returnReduce(sum, sumOp<scalar>())/2;
    }

    scalar sum = 0;
    forAll(lm, celli)
    {
        sum += V[celli]*magSqr(lm[celli]);
    }

    return returnReduce(sum, sumOp<scalar>())/(2*law_->rho());
}


Foam::scalar Foam::touchSolid::strainEnergy() const
{
    if (nodalAveraging_)
    {
        return nodalAveraging_->totalStrainEnergy(*law_, F_);
    }

    return law_->totalStrainEnergy(F_, gradD_);
}


Foam::scalar Foam::touchSolid::potentialEnergy() const
{
    return
        gravity_
      ? gravity_->potentialEnergy(cellPositions(D_.primitiveField()))
      : 0;
}


void Foam::touchSolid::accountBoundaryWork
(
    const labelList& cellBody,
    const label nBodies
)
{
    if (!boundaryWork_)
    {
        boundaryWork_.reset(new boundaryWork(mesh_, cellBody, nBodies));
    }
}


void Foam::touchSolid::writeSummary(Ostream& os) const
{
    os  << "    mechanical law  ";
    law_->writeConstants(os);

    os  << nl;
    if (law_->uniformMaterial())
    {
        os  << "    elastic moduli  mu " << law_->mu() << ", lambda "
            << law_->lambda() << ", kappa " << law_->kappa() << nl
            << "    wave speeds     Up " << law_->Up() << ", Us "
            << law_->Us() << nl;
    }
    os  << "    h_min           " << timeStep_.hMin() << nl
        << "    scheme          Riemann solver " << riemann_->type()
        << ", reconstruction " << reconstruction_.description().c_str()
        << ", CFL " << timeStep_.CFL() << nl
        << "                    " << rungeKutta_.name() << " ("
        << rungeKutta_.nStages() << "-stage SSP Runge-Kutta), F update "
        << update_->type();
    update_->writeOptions(os);
    os  << ", angular momentum preservation "
        << (preserveAngularMomentum_ ? "on" : "off")
        << ", nodal averaging "
        << (nodalAveraging_ ? nodalAveraging_->type() : word("off"))
        << ", symmetric planes " << (mirrorPlanes_ ? "mirror" : "oneSided")
        << nl;
    if (gravity_)
    {
        gravity_->writeSummary(os);
    }
}


void Foam::touchSolid::prepareWrite()
{
    // F, gradD and D write themselves with the state; J, sigma, sigmaEq
    // and pressure take their patches from F's
    cellValuesOnPatches(F_);
    // Its processor values too: the stages exchange F's only
    gradD_.correctBoundaryConditions();
    cellValuesOnPatches(gradD_);
    cellValuesOnPatches(D_);
}


void Foam::touchSolid::writeOutputFields()
{
    const word& timeName = mesh_.time().timeName();

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

    // One output field at a time, the stress in P_ itself (the next stage
    // recomputes it): holding P, U, J, sigma and pressure together set the
    // run's peak memory, 106 bytes a cell above the time loop's (1.05 M
    // cells, measured)

    // Stress of the final state through the law's own path (P_ held the
    // last stage's)
    law_->stress
    (
        F_.primitiveField(), gradD_.primitiveField(), P_.primitiveFieldRef()
    );
    if (nodalAveraging_)
    {
        nodalAveraging_->correct
        (
            *law_, F_.primitiveField(), P_.primitiveFieldRef()
        );
    }
    // J, sigma, sigmaEq and pressure take their patches from F's (set by
    // prepareWrite) and P's
    cellValuesOnPatches(P_);
    P_.instance() = timeName;
    P_.write();

    {
        volScalarField J(outputIO("J"), det(F_));
        J.write();
    }

    // Cauchy stress cell by cell and face by face (the field expression
    // held three tensor temporaries)
    auto cauchy = [](const tensor& P, const tensor& F)
    {
        return symmTensor(symm(P & F.T())/det(F));
    };

    volSymmTensorField sigma
    (
        outputIO("sigma"),
        mesh_,
        dimensionedSymmTensor(P_.dimensions(), Zero),
        calculatedFvPatchField<symmTensor>::typeName
    );
    forAll(sigma, celli)
    {
        sigma[celli] = cauchy(P_[celli], F_[celli]);
    }
    forAll(sigma.boundaryField(), patchi)
    {
        fvPatchSymmTensorField& sp = sigma.boundaryFieldRef()[patchi];
        const fvPatchTensorField& Pp = P_.boundaryField()[patchi];
        const fvPatchTensorField& Fp = F_.boundaryField()[patchi];
        forAll(sp, i)
        {
            sp[i] = cauchy(Pp[i], Fp[i]);
        }
    }
    sigma.write();

    {
        volScalarField pressure(outputIO("pressure"), -tr(sigma)/3);
        pressure.write();
    }

    {
        volScalarField sigmaEq
        (
            outputIO("sigmaEq"),
            sqrt((3.0/2.0)*magSqr(dev(sigma)))
        );
        sigmaEq.write();
    }

    writeContact(outputIO("contact"));

    // U last: a folder with a complete U was written to the end
    {
        // lm/rho of the lm written with it, cell by cell and on the patches
        // (with the dimensions of a velocity: a restart from a folder
        // whose lm is missing reads this U, and checks them)
        volVectorField U(outputIO("U"), lm_/law_->materialRho(0));
        if (!law_->uniformMaterial())
        {
            // Each cell's own density, and the patch cell's on a patch
            U.primitiveFieldRef() = lm_.primitiveField()/law_->cellRho();
            forAll(U.boundaryField(), patchi)
            {
                const labelUList& faceCells =
                    mesh_.boundary()[patchi].faceCells();
                fvPatchVectorField& Up = U.boundaryFieldRef()[patchi];
                forAll(Up, i)
                {
                    Up[i] =
                        lm_.boundaryField()[patchi][i]
                       /law_->rho(faceCells[i]);
                }
            }
        }
        U.dimensions().reset(dimVelocity);
        U.write();
    }
}


void Foam::touchSolid::writeContact(const IOobject& io) const
{
    // The rigid walls' active sets are entries of lm's patches, which
    // ParaView does not show: as a field, 1 on a face in contact (the
    // decision of the last stage of the last step) and 0 else, and in the
    // cells 1 where one of its faces is in contact, so that the internal
    // mesh shows it too
    const volVectorField::Boundary& lmBf = lm_.boundaryField();

    bool anyWall = false;
    forAll(lmBf, patchi)
    {
        anyWall = anyWall || isA<rigidWallFvPatchVectorField>(lmBf[patchi]);
    }

    // The patches are every rank's, so every rank decides alike
    if (!anyWall)
    {
        return;
    }

    volScalarField contact
    (
        io,
        mesh_,
        dimensionedScalar("0", dimless, Zero),
        calculatedFvPatchField<scalar>::typeName
    );

    forAll(lmBf, patchi)
    {
        if (isA<rigidWallFvPatchVectorField>(lmBf[patchi]))
        {
            const boolList& inContact =
                refCast<const rigidWallFvPatchVectorField>(lmBf[patchi])
               .contact();
            const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
            fvPatchScalarField& pc = contact.boundaryFieldRef()[patchi];

            forAll(inContact, facei)
            {
                if (inContact[facei])
                {
                    pc[facei] = 1;
                    contact[faceCells[facei]] = 1;
                }
            }
        }
    }

    contact.write();
}


// ************************************************************************* //
