/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "neoHookean.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(neoHookean, 0);
    addToRunTimeSelectionTable(mechanicalLaw, neoHookean, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaws::neoHookean::neoHookean
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mechanicalLaw(mesh, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::mechanicalLaws::neoHookean::P(const tensor& F) const
{
    // H = cof F = J F^-T avoids a division by J in the volumetric part
    const tensor H(cof(F));
    const scalar J = det(F);
    const scalar FF = F && F;

    return
        mu_*isochoricFactor(J)*(F - (FF/(3*J))*H)
      + kappa_*(J - 1)*H;
}


Foam::scalar Foam::mechanicalLaws::neoHookean::strainEnergy
(
    const tensor& F
) const
{
    const scalar J = det(F);

    return 0.5*mu_*(isochoricFactor(J)*(F && F) - 3) + 0.5*kappa_*sqr(J - 1);
}


// ************************************************************************* //
