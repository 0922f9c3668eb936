/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearReconstruction.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class Type, class Increment>
Foam::tmp<Foam::Field<Type>> Foam::linearReconstruction::limiterFactors
(
    const GeometricField<Type, fvPatchField, volMesh>& U,
    const Increment& increment
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = X_.primitiveField();
    const vectorField& Cf = mesh_.faceCentres();
    const Field<Type>& Ui = U.primitiveField();

    // Bounds: the cell and its face neighbours (coupled ones included)
    Field<Type> Umax(Ui);
    Field<Type> Umin(Ui);

    forAll(own, facei)
    {
        const label o = own[facei];
        const label n = nei[facei];
        Umax[o] = max(Umax[o], Ui[n]);
        Umin[o] = min(Umin[o], Ui[n]);
        Umax[n] = max(Umax[n], Ui[o]);
        Umin[n] = min(Umin[n], Ui[o]);
    }

    forAll(U.boundaryField(), patchi)
    {
        const fvPatchField<Type>& Up = U.boundaryField()[patchi];

        if (Up.coupled())
        {
            const Field<Type> Un(Up.patchNeighbourField());
            const labelUList& faceCells = Up.patch().faceCells();

            forAll(Un, i)
            {
                const label c = faceCells[i];
                Umax[c] = max(Umax[c], Un[i]);
                Umin[c] = min(Umin[c], Un[i]);
            }
        }
    }

    tmp<Field<Type>> tphi(new Field<Type>(Ui.size(), pTraits<Type>::one));
    Field<Type>& phi = tphi.ref();

    // Smallest factor over the faces of a cell, per component
    auto limitFace = [&](const label c, const label facei)
    {
        const Type dU(increment(c, Cf[facei] - C[c]));

        for (direction cmpt = 0; cmpt < pTraits<Type>::nComponents; ++cmpt)
        {
            const scalar df = component(dU, cmpt);
            scalar r = GREAT;

            if (df > VSMALL)
            {
                r = (component(Umax[c], cmpt) - component(Ui[c], cmpt))/df;
            }
            else if (df < -VSMALL)
            {
                r = (component(Umin[c], cmpt) - component(Ui[c], cmpt))/df;
            }

            setComponent(phi[c], cmpt) =
                min(component(phi[c], cmpt), limiter_->limiter(r));
        }
    };

    forAll(own, facei)
    {
        limitFace(own[facei], facei);
        limitFace(nei[facei], facei);
    }

    // Coupled faces are interior faces.  Faces of a boundary condition are
    // not limited: there is no neighbour value to bound them, their flux is
    // upwinded against the condition, and clipping them made every boundary
    // cell first order (swinging cube, stress order 1.0 instead of 2.2)
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        const label start = patch.start();

        if (!patch.coupled())
        {
            continue;
        }

        forAll(patch, i)
        {
            limitFace(patch.faceCells()[i], start + i);
        }
    }

    return tphi;
}


// ************************************************************************* //
