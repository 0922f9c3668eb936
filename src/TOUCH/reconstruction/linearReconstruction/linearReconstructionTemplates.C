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

    // A coupled face bounds by the neighbour's value.  A face of a boundary
    // condition bounds by the cell's own extrapolation to it: a field that
    // rises monotonically to a boundary would otherwise leave the boundary
    // cell at its bound, and round-off-level tangential noise would clip its
    // whole gradient (measured: a free rigid rotation lost a third of its
    // energy in a quarter turn)
    forAll(U.boundaryField(), patchi)
    {
        const fvPatchField<Type>& Up = U.boundaryField()[patchi];
        const labelUList& faceCells = Up.patch().faceCells();

        if (Up.coupled())
        {
            const Field<Type> Un(Up.patchNeighbourField());

            forAll(Un, i)
            {
                const label c = faceCells[i];
                Umax[c] = max(Umax[c], Un[i]);
                Umin[c] = min(Umin[c], Un[i]);
            }
        }
        else
        {
            const label start = Up.patch().start();

            forAll(faceCells, i)
            {
                const label c = faceCells[i];
                const Type Ub(Ui[c] + increment(c, Cf[start + i] - C[c]));
                Umax[c] = max(Umax[c], Ub);
                Umin[c] = min(Umin[c], Ub);
            }
        }
    }

    tmp<Field<Type>> tphi(new Field<Type>(Ui.size(), pTraits<Type>::one));
    Field<Type>& phi = tphi.ref();

    // Increments below round-off of the field's magnitude are no
    // increments: a cell at a bound of a component that is constant along a
    // face direction would otherwise take phi = 0 from a gradient of 1e-17
    // (measured: a rigid rotation lost half its energy in a quarter turn).
    // The magnitude of the whole field, not of each component: a component
    // that is zero but for round-off (p_x of a ring falling along y) had a
    // tolerance of round-off itself, and its limiter followed the round-off
    // of each decomposition (serial and parallel parted at first contact)
    // and of each step sequence (the ring's L_z grew to 2e-7)
    const Type tolerance(roundOff_*gMax(mag(Ui))*pTraits<Type>::one);

    // Smallest factor over the faces of a cell, per component
    auto limitFace = [&](const label c, const label facei)
    {
        const Type dU(increment(c, Cf[facei] - C[c]));

        for (direction cmpt = 0; cmpt < pTraits<Type>::nComponents; ++cmpt)
        {
            const scalar df = component(dU, cmpt);
            const scalar tol = component(tolerance, cmpt);
            scalar r = GREAT;

            if (df > tol)
            {
                r = (component(Umax[c], cmpt) - component(Ui[c], cmpt))/df;
            }
            else if (df < -tol)
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
