/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "deformationUpdate.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(deformationUpdate, 0);
    defineRunTimeSelectionTable(deformationUpdate, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::deformationUpdate::boundaryFlux
(
    const fvPatch& patch,
    solidFluxFvPatchVectorField& condition,
    const solidFluxFvPatchVectorField::interiorState& state,
    vector& torque
)
{
    vectorField& pC = pC_[patch.index()];
    vectorField& tC = tC_[patch.index()];

    condition.flux(state, pC, tC);
    condition.addTorque(state, tC, torque);

    condition == pC;
}


void Foam::deformationUpdate::addFaceMeanFRate
(
    const vectorField& pointV,
    tensorField& FRate
) const
{
    const faceList& faces = faces_.mesh().faces();
    const vectorField& Sf = faces_.mesh().faceAreas();
    const bool uniform = shares_.uniform();

    faces_.forAllFaces
    (
        [&](const label facei, const label own, const label nei)
        {
            const face& f = faces[facei];
            tensor flux(Zero);

            if (uniform)
            {
                // Equal shares S_f/n_f: the mean point velocity's flux
                vector sum(Zero);
                for (const label pointi : f)
                {
                    sum += pointV[pointi];
                }
                flux = sum*(facePointShares::inverseSize(f.size())*Sf[facei]);
            }
            else
            {
                shares_.forAllPoints
                (
                    f, facei, Sf[facei],
                    [&](const label pointi, const vector& s)
                    {
                        flux += pointV[pointi]*s;
                    }
                );
            }

            FRate[own] += flux;
            if (nei >= 0)
            {
                FRate[nei] -= flux;
            }
        }
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdate::deformationUpdate
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    faces_(faces),
    law_(law),
    riemann_(riemann),
    shares_(faces.mesh()),
    pC_(faces.mesh().boundary().size()),
    tC_(faces.mesh().boundary().size()),
    rigidSpin_(Zero),
    pointDisplacement_(nullptr),
    pointForcing_(nullptr),
    neighbourMaterial_()
{
    if (!law.uniformMaterial())
    {
        syncTools::swapBoundaryCellList
        (
            faces.mesh(), law.cellMaterial(), neighbourMaterial_
        );
    }

    forAll(faces.mesh().boundary(), patchi)
    {
        const fvPatch& patch = faces.mesh().boundary()[patchi];
        const label n = patch.coupled() ? 0 : patch.size();

        pC_.set(patchi, new vectorField(n, Zero));
        tC_.set(patchi, new vectorField(n, Zero));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformationUpdate::setNodalAveraging
(
    const nodalAveraging* average,
    const dictionary& controls
)
{
    if (!average || !average->addsPointForces())
    {
        return;
    }

    // Only the compatible update has nodal forces to add to
    if (type() != "compatible")
    {
        FatalIOErrorInFunction(controls)
            << "Entry 'nodalAveraging " << average->type() << "' in "
            << controls.name() << " with FUpdate " << type()
            << ": it adds nodal forces, which only the compatible update"
            << " has" << nl << "Valid: FUpdate compatible, or nodalAveraging"
            << " off | pressure | deformation" << nl << exit(FatalIOError);
    }

    pointForcing_ = average;
}


Foam::scalar Foam::deformationUpdate::boundaryPower() const
{
    scalar power = 0;

    forAll(pC_, patchi)
    {
        const vectorField& pC = pC_[patchi];
        const vectorField& tC = tC_[patchi];

        if (pC.size())
        {
            const scalarField& magSf = faces_.mesh().boundary()[patchi].magSf();

            forAll(pC, i)
            {
                power += (pC[i] & tC[i])*magSf[i];
            }
        }
    }

    if (law_.uniformMaterial())
    {
        return power/law_.rho();
    }

    // Each face's cell's density
    power = 0;
    forAll(pC_, patchi)
    {
        const vectorField& pC = pC_[patchi];
        const vectorField& tC = tC_[patchi];
        const fvPatch& patch = faces_.mesh().boundary()[patchi];

        forAll(pC, i)
        {
            power +=
                (pC[i] & tC[i])*patch.magSf()[i]
               /law_.rho(patch.faceCells()[i]);
        }
    }

    return power;
}


// ************************************************************************* //
