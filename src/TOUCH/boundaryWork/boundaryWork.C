/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "boundaryWork.H"
#include "bodyContactFvPatchVectorField.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
    //- The bodyContact patches of lm whose friction law is not frictionless
    static labelList frictionContactPatches(const fvMesh& mesh)
    {
        DynamicList<label> patches;
        if (mesh.foundObject<volVectorField>("lm"))
        {
            const volVectorField& lm = mesh.lookupObject<volVectorField>("lm");
            forAll(lm.boundaryField(), patchi)
            {
                const fvPatchVectorField& pf = lm.boundaryField()[patchi];
                if
                (
                    isA<bodyContactFvPatchVectorField>(pf)
                 && !refCast<const bodyContactFvPatchVectorField>(pf)
                    .friction().frictionless()
                )
                {
                    patches.append(patchi);
                }
            }
        }
        return labelList(std::move(patches));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::boundaryWork::boundaryWork
(
    const fvMesh& mesh,
    const labelList& cellBody,
    const label nBodies
)
:
    mesh_(mesh),
    cellBody_(cellBody),
    patchWork_(mesh.boundary().size(), Zero),
    bodyWork_(nBodies, Zero),
    patchWork0_(patchWork_),
    bodyWork0_(bodyWork_),
    frictionPatches_(frictionContactPatches(mesh)),
    frictionWork_(0),
    frictionWork0_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::boundaryWork::storeOldTime()
{
    patchWork0_ = patchWork_;
    bodyWork0_ = bodyWork_;
    frictionWork0_ = frictionWork_;
}


void Foam::boundaryWork::addStage
(
    const scalar alpha,
    const scalar dt,
    const deformationUpdate& update,
    const mechanicalLaw& law
)
{
    const PtrList<vectorField>& pC = update.contactMomentum();
    const PtrList<vectorField>& tC = update.contactTraction();
    const scalar beta = 1 - alpha;

    // W <- alpha W^n + beta (W + dt P): the part of the present work first,
    // then the stage's power added face by face
    patchWork_ = alpha*patchWork0_ + beta*patchWork_;
    bodyWork_ = alpha*bodyWork0_ + beta*bodyWork_;

    const scalar weight = beta*dt;
    const volVectorField& lm = mesh_.lookupObject<volVectorField>("lm");
    forAll(pC, patchi)
    {
        const vectorField& p = pC[patchi];
        if (p.empty())
        {
            continue;
        }
        const vectorField& t = tC[patchi];
        const fvPatch& patch = mesh_.boundary()[patchi];
        const scalarField& magSf = patch.magSf();
        const labelUList& faceCells = patch.faceCells();

        // A force at points the faces' fluxes do not see: its power as
        // the update had it, the patch's body's
        const fvPatchVectorField& pf = lm.boundaryField()[patchi];
        if
        (
            isA<solidFluxFvPatchVectorField>(pf)
         && refCast<const solidFluxFvPatchVectorField>(pf).reportsPower()
        )
        {
            const scalar work =
                weight
               *refCast<const solidFluxFvPatchVectorField>(pf).stagePower();
            patchWork_[patchi] += work;
            bodyWork_[cellBody_[faceCells[0]]] += work;
            continue;
        }

        scalar patchWork = 0;
        forAll(p, i)
        {
            const label celli = faceCells[i];
            const scalar work =
                weight*(p[i] & t[i])*magSf[i]/law.rho(celli);
            patchWork += work;
            bodyWork_[cellBody_[celli]] += work;
        }

        // and the forces the update applied at its points
        const scalarField* pointPower =
            isA<solidFluxFvPatchVectorField>(pf)
          ? refCast<const solidFluxFvPatchVectorField>(pf).stagePointPower()
          : nullptr;
        if (pointPower)
        {
            forAll(*pointPower, i)
            {
                const scalar work = weight*(*pointPower)[i];
                patchWork += work;
                bodyWork_[cellBody_[faceCells[i]]] += work;
            }
        }
        patchWork_[patchi] += patchWork;
    }

    if (frictionPatches_.size())
    {
        frictionWork_ = alpha*frictionWork0_ + beta*frictionWork_;
        for (const label patchi : frictionPatches_)
        {
            frictionWork_ +=
                weight
               *refCast<const solidFluxFvPatchVectorField>
                (
                    lm.boundaryField()[patchi]
                ).stageFrictionPower();
        }
    }
}


void Foam::boundaryWork::restoreOldTime()
{
    patchWork_ = patchWork0_;
    bodyWork_ = bodyWork0_;
    frictionWork_ = frictionWork0_;
}


// ************************************************************************* //
