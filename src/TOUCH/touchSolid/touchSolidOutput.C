/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    What touchSolid reports: the totals the monitor asks for every step
    (linear and angular momentum, kinetic and stored energy), the start-up
    summary of the log and the output fields written with each time.

\*---------------------------------------------------------------------------*/

#include "touchSolid.H"
#include "calculatedFvPatchFields.H"

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
            u_.primitiveField(),
            lm_.primitiveField()
        )
      - (origin ^ totalLinearMomentum());
}


Foam::scalar Foam::touchSolid::kineticEnergy() const
{
    const scalarField& V = mesh_.V();
    const vectorField& lm = lm_.primitiveField();

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

    return law_->totalStrainEnergy(F_);
}


void Foam::touchSolid::writeSummary(Ostream& os) const
{
    os  << "    mechanical law  ";
    law_->writeConstants(os);

    os  << nl
        << "    elastic moduli  mu " << law_->mu() << ", lambda "
        << law_->lambda() << ", kappa " << law_->kappa() << nl
        << "    wave speeds     Up " << law_->Up() << ", Us " << law_->Us()
        << nl
        << "    h_min           " << timeStep_.hMin() << nl
        << "    scheme          Riemann solver " << riemann_->type()
        << ", reconstruction " << reconstruction_.description().c_str()
        << ", CFL " << timeStep_.CFL() << nl
        << "                    " << rungeKutta_.name() << " ("
        << rungeKutta_.nStages() << "-stage SSP Runge-Kutta), F update "
        << update_->type() << ", angular momentum preservation "
        << (preserveAngularMomentum_ ? "on" : "off")
        << ", nodal averaging "
        << (nodalAveraging_ ? nodalAveraging_->type() : word("off"))
        << ", symmetric planes " << (mirrorPlanes_ ? "mirror" : "oneSided")
        << nl;
}


void Foam::touchSolid::writeOutputFields()
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

    // One output field at a time, the stress in P_ itself (the next stage
    // recomputes it): holding P, v, J, sigma and pressure together set the
    // run's peak memory, 106 bytes a cell above the time loop's (1.05 M
    // cells, measured)

    // Stress of the final state through the law's own path (P_ held the
    // last stage's)
    law_->stress(F_.primitiveField(), P_.primitiveFieldRef());
    if (nodalAveraging_)
    {
        nodalAveraging_->correct
        (
            *law_, F_.primitiveField(), P_.primitiveFieldRef()
        );
    }
    P_.instance() = timeName;
    P_.write();

    {
        volVectorField v(outputIO("v"), lm_/rho);
        v.write();
    }

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

    volScalarField pressure(outputIO("pressure"), -tr(sigma)/3);
    pressure.write();
}


// ************************************************************************* //
