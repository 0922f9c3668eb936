/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace mechanicalLaws
{
    defineTypeNameAndDebug(linearElastic, 0);
    addToRunTimeSelectionTable(mechanicalLaw, linearElastic, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mechanicalLaws::linearElastic::linearElastic
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mechanicalLaw(mesh, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::mechanicalLaws::linearElastic::P(const tensor& F) const
{
    return mu_*(F + F.T() - 2*tensor::I) + lambda_*(tr(F) - 3)*tensor::I;
}


Foam::tensor Foam::mechanicalLaws::linearElastic::P
(
    const tensor&,
    const tensor& gradD
) const
{
    return mu_*(gradD + gradD.T()) + lambda_*tr(gradD)*tensor::I;
}


Foam::scalar Foam::mechanicalLaws::linearElastic::strainEnergy
(
    const tensor& F
) const
{
    const tensor eps(symm(F) - tensor::I);

    return mu_*(eps && eps) + 0.5*lambda_*sqr(tr(eps));
}


Foam::scalar Foam::mechanicalLaws::linearElastic::strainEnergy
(
    const tensor&,
    const tensor& gradD
) const
{
    const symmTensor eps(symm(gradD));

    return mu_*(eps && eps) + 0.5*lambda_*sqr(tr(eps));
}


// ************************************************************************* //
