/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::contactSurfaces::writeReport
(
    const volVectorField& lm,
    const scalar time,
    label nActive,
    scalar normalForce,
    scalar area,
    scalar penetration
)
{
    reduce(nActive, sumOp<label>());
    reduce(normalForce, sumOp<scalar>());
    reduce(area, sumOp<scalar>());
    reduce(penetration, maxOp<scalar>());
    reduce(mostTensile_, maxOp<scalar>());

    scalar power = 0;
    if (friction_)
    {
        reduce(frictionRatio_, maxOp<scalar>());
        reduce(pairFrictionRatio_, maxOp<scalar>());
        reduce(pairFrictionPower_, maxOp<scalar>());
        forAll(patches_, s)
        {
            power +=
                refCast<const bodyContactFvPatchVectorField>
                (
                    lm.boundaryField()[patches_[s]]
                ).stageFrictionPower();
        }
        reduce(power, sumOp<scalar>());
    }

    if (file_.valid())
    {
        file_()
            << time << ' ' << nActive << ' ' << normalForce << ' '
            << area << ' ' << penetration << ' '
            << (mostTensile_ > -GREAT ? mostTensile_ : 0);
        if (friction_)
        {
            file_()
                << ' ' << frictionRatio_ << ' '
                << (pairFrictionPower_ > -GREAT ? pairFrictionPower_ : 0)
                << ' ' << power << ' ' << pairFrictionRatio_;
        }
        file_() << endl;
    }
    mostTensile_ = -GREAT;
    frictionRatio_ = 0;
    pairFrictionRatio_ = 0;
    pairFrictionPower_ = -GREAT;
}


// ************************************************************************* //
