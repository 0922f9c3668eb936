/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "deformationUpdate.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::deformationUpdate> Foam::deformationUpdate::New
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
{
    const word updateType
    (
        controls.getOrDefault<word>("FUpdate", "compatible")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(updateType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            controls,
            "FUpdate",
            updateType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<deformationUpdate>
    (
        cstrIter()(controls, faces, law, riemann, reconstruction)
    );
}


// ************************************************************************* //
