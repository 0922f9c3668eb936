/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "nodalAveraging.H"
#include "mechanicalLaw.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    //- off and the names of the selection table
    static wordList nodalAveragingChoices()
    {
        wordList names({"off"});
        if (nodalAveraging::meshConstructorTablePtr_)
        {
            names.append(nodalAveraging::meshConstructorTablePtr_->sortedToc());
        }
        return names;
    }

    static const declaredEntry<word> nodalAveragingEntry
    (
        "system/fvSolution TOUCH", "nodalAveraging",
        "average at the points: the volume ratio (pressure: laws with a"
        " volumetric part of J alone) or the whole F (deformation: stateless"
        " laws, tetrahedra); or the volume ratio from each cell's current"
        " volume (cellVolume: stateless laws, FUpdate compatible)",
        "-", word("off"), entryLimits::selectedFrom(&nodalAveragingChoices)
    );
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::nodalAveraging> Foam::nodalAveraging::New
(
    const fvMesh& mesh,
    const dictionary& controls,
    const mechanicalLaw& law
)
{
    const word type(nodalAveragingEntry.read(controls));

    if (type == "off")
    {
        const label nTets = nTetrahedra(mesh);

        if (nTets)
        {
            WarningInFunction
                << nTets << " of " << returnReduce(mesh.nCells(), sumOp<label>())
                << " cells are tetrahedra, which lock in bending and torsion"
                << " without 'nodalAveraging deformation;' in "
                << controls.name() << endl;
        }

        return nullptr;
    }

    auto cstrIter = meshConstructorTablePtr_->cfind(type);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(controls)
            << "Unknown nodalAveraging '" << type << "' in "
            << controls.name() << nl
            << "Valid choices: off " << meshConstructorTablePtr_->sortedToc()
            << nl << exit(FatalIOError);
    }

    autoPtr<nodalAveraging> average(cstrIter()(mesh));

    // The averages are over a point's cells, which may be of different
    // materials: one law's pointwise stress only
    if (!law.uniformMaterial())
    {
        FatalIOErrorInFunction(controls)
            << "Entry 'nodalAveraging " << type << "' in " << controls.name()
            << " with several materials ('materials' in constant/"
            << "mechanicalProperties): the averages take one law" << nl
            << "Valid: nodalAveraging off, or one material" << nl
            << exit(FatalIOError);
    }

    if (!average->suits(law))
    {
        FatalIOErrorInFunction(controls)
            << "Entry 'nodalAveraging " << type << "' in " << controls.name()
            << " needs " << average->lawRequirement() << "; model "
            << law.type() << " has not." << nl
            << "Valid: nodalAveraging off, or another model" << nl
            << exit(FatalIOError);
    }

    Info<< "Selecting nodal averaging " << type << endl;

    return average;
}


// ************************************************************************* //
