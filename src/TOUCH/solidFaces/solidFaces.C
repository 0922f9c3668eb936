/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "solidFaces.H"
#include "mechanicalLaw.H"
#include "contactSurfaces.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- One buffer per patch: sized for the patches that pass the test, empty
//  for the others
template<class Type, class Test>
static void sizeBuffers
(
    const fvMesh& mesh,
    PtrList<Field<Type>>& buffers,
    const Test& test
)
{
    buffers.setSize(mesh.boundary().size());

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        buffers.set
        (
            patchi,
            new Field<Type>(test(patch) ? patch.size() : 0, Zero)
        );
    }
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::solidFaces::fillInteriorState(const label patchi)
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    const labelUList& faceCells = patch.faceCells();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& N = NM_[patchi];
    vectorField& pM = pM_[patchi];
    vectorField& tM = tM_[patchi];
    vectorField& nM = nM_[patchi];
    vectorField& xM = xM_[patchi];
    vectorField& xPointsM = xPointsM_[patchi];
    const faceList& faces = mesh_.faces();
    const pointField& X = mesh_.points();
    const vectorField& pointU = pointU_.primitiveField();
    const bool stored = reconstruction_.storesStressGradients();
    const bool pointPositions =
        refCast<const solidFluxFvPatchVectorField>
        (
            lm_.boundaryField()[patchi]
        ).usesPointPositions();

    forAll(faceCells, i)
    {
        const label o = faceCells[i];
        const cellValues owner(cell(o));
        const vector r(Cf[patch.start() + i] - owner.X);

        pM[i] = owner.p(r);
        if (stored)
        {
            tM[i] = owner.t(r, N[i]);
        }
        nM[i] = spatialNormal(owner.F, N[i]);
        xM[i] = owner.X + u_[o] + (owner.F & r);

        if (!pointPositions)
        {
            continue;
        }

        // The mean of the face's points where they are now: the surface
        // that is drawn and measured.  A contact decided by X + u + F r
        // instead let a wall face touch while its points, which drift from
        // the cells' motion (the point upwinding), hovered up to 80 um
        // above the wall, and held them there (Taylor bar)
        const face& f = faces[patch.start() + i];
        vector sum(Zero);
        for (const label pointi : f)
        {
            sum += X[pointi] + pointU[pointi];
        }
        xPointsM[i] = sum/f.size();
    }
}


void Foam::solidFaces::fillMaterial(const mechanicalLaw& law)
{
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        scalarField& rho = rhoM_[patchi];
        scalarField& Up = UpM_[patchi];
        scalarField& Us = UsM_[patchi];

        forAll(rho, i)
        {
            rho[i] = law.rho(faceCells[i]);
            Up[i] = law.Up(faceCells[i]);
            Us[i] = law.Us(faceCells[i]);
        }
    }

    materialFilled_ = true;
}


void Foam::solidFaces::updateContact(const label stage)
{
    const labelList& patches = contact_->patches();
    PtrList<solidFluxFvPatchVectorField::interiorState> states(patches.size());

    forAll(patches, s)
    {
        const label patchi = patches[s];
        fillInteriorState(patchi);

        states.set
        (
            s,
            new solidFluxFvPatchVectorField::interiorState
            {
                pM_[patchi], tM_[patchi], nM_[patchi], xM_[patchi],
                xPointsM_[patchi], rhoM_[patchi], UpM_[patchi], UsM_[patchi],
                stage, stageTime_
            }
        );
    }

    contact_->update(states, F_, lm_, stage, stageTime_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidFaces::solidFaces
(
    const fvMesh& mesh,
    const linearReconstruction& reconstruction,
    volVectorField& lm,
    const volTensorField& F,
    const volTensorField& P,
    const volVectorField& u,
    const pointVectorField& pointU
)
:
    mesh_(mesh),
    reconstruction_(reconstruction),
    lm_(lm),
    F_(F),
    P_(P),
    u_(u),
    pointU_(pointU),
    stageTime_(mesh.time().value()),
    materialFilled_(false)
{
    auto coupled = [](const fvPatch& patch) { return patch.coupled(); };
    auto solid = [](const fvPatch& patch) { return !patch.coupled(); };

    sizeBuffers(mesh, lmN_, coupled);
    sizeBuffers(mesh, FN_, coupled);
    sizeBuffers(mesh, PN_, coupled);
    sizeBuffers(mesh, gradLmN_, coupled);
    sizeBuffers(mesh, XN_, coupled);
    sizeBuffers(mesh, uN_, coupled);

    sizeBuffers(mesh, pM_, solid);
    sizeBuffers(mesh, tM_, solid);
    sizeBuffers(mesh, nM_, solid);
    sizeBuffers(mesh, NM_, solid);
    sizeBuffers(mesh, xM_, solid);
    sizeBuffers(mesh, xPointsM_, solid);
    sizeBuffers(mesh, rhoM_, solid);
    sizeBuffers(mesh, UpM_, solid);
    sizeBuffers(mesh, UsM_, solid);

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];

        if (patch.coupled())
        {
            XN_[patchi] = reconstruction_.neighbourCentres(patchi);
        }
        else if (patch.size())
        {
            NM_[patchi] = patch.nf();
        }
    }

    // Nothing for a mesh without contact surfaces
    if (contactSurfaces::any(lm))
    {
        contact_.reset(new contactSurfaces(mesh, lm));
    }
}


Foam::solidFaces::~solidFaces()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidFaces::update()
{
    forAll(mesh_.boundary(), patchi)
    {
        if (!mesh_.boundary()[patchi].coupled())
        {
            continue;
        }

        lmN_[patchi] = lm_.boundaryField()[patchi].patchNeighbourField();
        uN_[patchi] = u_.boundaryField()[patchi].patchNeighbourField();
        FN_[patchi] = F_.boundaryField()[patchi].patchNeighbourField();
        PN_[patchi] = P_.boundaryField()[patchi].patchNeighbourField();
        gradLmN_[patchi] =
            reconstruction_.gradp().boundaryField()[patchi]
           .patchNeighbourField();

        if (reconstruction_.storesStressGradients())
        {
            if (gradPxN_.empty())
            {
                // Sized on first use, as the stored gradients are
                auto coupled = [](const fvPatch& p) { return p.coupled(); };
                sizeBuffers(mesh_, gradPxN_, coupled);
                sizeBuffers(mesh_, gradPyN_, coupled);
                sizeBuffers(mesh_, gradPzN_, coupled);
            }

            gradPxN_[patchi] =
                reconstruction_.gradP(0).boundaryField()[patchi]
               .patchNeighbourField();
            gradPyN_[patchi] =
                reconstruction_.gradP(1).boundaryField()[patchi]
               .patchNeighbourField();
            gradPzN_[patchi] =
                reconstruction_.gradP(2).boundaryField()[patchi]
               .patchNeighbourField();
        }
    }
}


const Foam::contactSurfaces& Foam::solidFaces::contact() const
{
    return contact_();
}


Foam::contactSurfaces& Foam::solidFaces::contact()
{
    return contact_();
}


// ************************************************************************* //
