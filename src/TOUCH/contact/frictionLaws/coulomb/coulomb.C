/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "coulomb.H"
#include "declaredEntry.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(coulomb, 0);
    addToRunTimeSelectionTable(frictionLaw, coulomb, dictionary);
}
}


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const string coulombWhere
    (
        string(frictionLaw::where) + ", type coulomb"
    );

    static const declaredEntry<scalar> muStaticEntry
    (
        coulombWhere, "muStatic",
        "static friction coefficient: a face sticks while"
        " |t_t| <= muStatic p_N", "-", 0.3,
        entryLimits::above(0, true), declaredEntry<scalar>::required
    );

    static const declaredEntry<scalar> muKineticEntry
    (
        coulombWhere, "muKinetic",
        "kinetic friction coefficient (<= muStatic): a sliding face gets"
        " |t_t| = muKinetic p_N", "-", 0.25,
        entryLimits::above(0, true), declaredEntry<scalar>::required
    );

    //- The kinetic coefficient, checked against the static one
    static scalar readMuKinetic(const dictionary& dict)
    {
        const scalar muKinetic = muKineticEntry.read(dict);
        const scalar muStatic = muStaticEntry.read(dict);

        if (muKinetic > muStatic)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'muKinetic' = " << muKinetic << " in "
                << dict.name() << " exceeds 'muStatic' = " << muStatic
                << ": valid 0 <= muKinetic <= muStatic (a face that slides"
                << " would hold more than one that sticks)" << nl
                << exit(FatalIOError);
        }

        return muKinetic;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionLaws::coulomb::coulomb(const dictionary& dict)
:
    frictionLaw(dict),
    muStatic_(muStaticEntry.read(dict)),
    muKinetic_(readMuKinetic(dict))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::frictionLaws::coulomb::tangentialTraction
(
    const vector& tStick,
    const scalar pN,
    const vector& slipVelocity
) const
{
    if (pN <= 0)
    {
        return Zero;
    }

    // A face at rest on the other side holds up to the static limit
    const bool stuck = (magSqr(slipVelocity) == 0);
    const scalar limit = (stuck ? muStatic_ : muKinetic_)*pN;

    const scalar magStick = mag(tStick);

    if (magStick <= limit)
    {
        return tStick;
    }

    return ((muKinetic_*pN)/magStick)*tStick;
}


// ************************************************************************* //
