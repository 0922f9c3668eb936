/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "solidFaces.H"
#include "mechanicalLaw.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Op>
void Foam::solidFaces::forAllCoupled(Op op) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const scalarField& magSf = mesh_.magSf().primitiveField();

    forAll(own, facei)
    {
        const cellValues left(cell(own[facei]));
        const cellValues right(cell(nei[facei]));

        op
        (
            coupledFace
            {
                facei, own[facei], nei[facei], left, right,
                Sf[facei], magSf[facei],
                Cf[facei] - left.X, Cf[facei] - right.X
            }
        );
    }

    forAllCoupledPatchFaces(op);
}


template<class Op>
void Foam::solidFaces::forAllCoupledPatchFaces(Op op) const
{
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const surfaceScalarField& magSfs = mesh_.magSf();

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        if (!patch.coupled())
        {
            continue;
        }

        const labelUList& faceCells = patch.faceCells();
        forAll(faceCells, i)
        {
            const label facei = patch.start() + i;
            const cellValues left(cell(faceCells[i]));
            const cellValues right(neighbour(patchi, i));

            op
            (
                coupledFace
                {
                    facei, faceCells[i], -1, left, right,
                    Sf[facei], magSfs.boundaryField()[patchi][i],
                    Cf[facei] - left.X, Cf[facei] - right.X
                }
            );
        }
    }
}


template<class Op>
void Foam::solidFaces::forAllSolidPatches
(
    const mechanicalLaw& law,
    const label stage,
    Op op,
    const bool decide
)
{
    if (!materialFilled_)
    {
        fillMaterial(law);
    }

    // The contact needs every contact patch's state before any flux
    if (decide && contact_.valid())
    {
        updateContact(stage);
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];

        // An empty part of a patch whose condition decides contact takes
        // part in the decision (below); other empty patches ('empty' of
        // a 2D case, a condition without a decision) are left out
        if
        (
            patch.coupled()
         || (
                patch.size() == 0
             && !(
                    decide
                 && isA<solidFluxFvPatchVectorField>
                    (
                        lm_.boundaryField()[patchi]
                    )
                )
            )
        )
        {
            continue;
        }

        fillInteriorState(patchi);

        const solidFluxFvPatchVectorField::interiorState state
        {
            pM_[patchi], tM_[patchi], nM_[patchi], xM_[patchi],
            xPointsM_[patchi], rhoM_[patchi], UpM_[patchi], UsM_[patchi], stage,
            stageTime_
        };
        const solidFluxFvPatchVectorField::interiorState reference
        {
            pM_[patchi], tM_[patchi], NM_[patchi], xM_[patchi],
            xPointsM_[patchi], rhoM_[patchi], UpM_[patchi], UsM_[patchi], stage,
            stageTime_
        };

        solidFluxFvPatchVectorField& condition =
            refCast<solidFluxFvPatchVectorField>(lm_.boundaryFieldRef()[patchi]);

        // A rank whose part of the patch is empty decides too: the decision
        // may exchange across the ranks (a rigid wall's held points), and
        // every rank must join that exchange
        if (decide)
        {
            condition.updateActiveSet(state);
        }

        if (patch.size())
        {
            op(patch, condition, state, reference);
        }
    }
}


template<class Op>
void Foam::solidFaces::forAllFaces(Op op) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();

    forAll(own, facei)
    {
        op(facei, own[facei], nei[facei]);
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const labelUList& faceCells = patch.faceCells();

        forAll(patch, i)
        {
            op(patch.start() + i, faceCells[i], -1);
        }
    }
}


// ************************************************************************* //
