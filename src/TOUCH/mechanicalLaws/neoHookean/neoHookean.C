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


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- The invariants of G = gradD = F - I and J - 1 = I1 + I2 + I3 from them,
//  without forming F (a small strain keeps its digits)
struct gradientInvariants
{
    scalar I1, I2, I3, Jm1;

    explicit gradientInvariants(const tensor& G)
    :
        I1(tr(G)),
        I2(0.5*(sqr(I1) - tr(G & G))),
        I3(det(G)),
        Jm1(I1 + I2 + I3)
    {}
};

} // End namespace Foam


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


Foam::tensor Foam::mechanicalLaws::neoHookean::P
(
    const tensor&,
    const tensor& G
) const
{
    // With F = I + G (G = gradD): J - 1 = I1 + I2 + I3, the invariants of
    // G, and cof F = I + A, A = I1 I - G^T + cof G, so that P(F) above is
    //     mu J^-2/3 (G - (s - 1) I - s A) + kappa (J - 1)(I + A),
    // s = (F && F)/(3 J), every term of which vanishes with G
    const gradientInvariants inv(G);
    const scalar I1 = inv.I1;
    const scalar Jm1 = inv.Jm1;
    const scalar J = 1 + Jm1;
    const tensor A(I1*tensor::I - G.T() + cof(G));
    const scalar sm1 = ((G && G) - I1 - 3*(Jm1 - I1))/(3*J);

    return
        mu_*isochoricFactor(J)*(G - sm1*tensor::I - (1 + sm1)*A)
      + kappa_*Jm1*(tensor::I + A);
}


Foam::scalar Foam::mechanicalLaws::neoHookean::strainEnergy
(
    const tensor& F
) const
{
    const scalar J = det(F);

    return 0.5*mu_*(isochoricFactor(J)*(F && F) - 3) + 0.5*kappa_*sqr(J - 1);
}


Foam::scalar Foam::mechanicalLaws::neoHookean::strainEnergy
(
    const tensor&,
    const tensor& G
) const
{
    // J^-2/3 (F && F) - 3 = (F && F - 3 J^2/3)/J^2/3 with, F = I + G,
    //     F && F - 3 J^2/3 = G && G - 2 (I2 + I3) + (2 (J - 1) - 3 b),
    // b = J^2/3 - 1 from expm1 and log1p: the terms of first order in G
    // cancel exactly (2 I1 = 2 (J - 1) - 2 (I2 + I3)), not in round-off
    const gradientInvariants inv(G);
    const scalar I2 = inv.I2;
    const scalar I3 = inv.I3;
    const scalar Jm1 = inv.Jm1;
    const scalar b = std::expm1((2.0/3.0)*std::log1p(Jm1));
    const scalar isochoric =
        ((G && G) - 2*(I2 + I3) + (2*Jm1 - 3*b))/(1 + b);

    return 0.5*mu_*isochoric + 0.5*kappa_*sqr(Jm1);
}


// ************************************************************************* //
