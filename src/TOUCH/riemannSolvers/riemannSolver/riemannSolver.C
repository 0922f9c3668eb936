/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "riemannSolver.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(riemannSolver, 0);
    defineRunTimeSelectionTable(riemannSolver, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::riemannSolver::riemannSolver
(
    const dictionary&,
    const mechanicalLaw& law
)
:
    law_(law)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::riemannSolver::interfaceFlux
(
    const vector& vL,
    const vector& tL,
    const scalar ZnL,
    const scalar ZtL,
    const vector& vR,
    const vector& tR,
    const scalar ZnR,
    const scalar ZtR,
    const vector& n,
    vector& vC,
    vector& tC
) const
{
    // The linearised (acoustic) solution of the two materials, the normal
    // and the tangential directions each with their own impedances
    const vector dv(vR - vL);
    const vector dt(tR - tL);

    const scalar invN = 1/(ZnL + ZnR);
    const scalar invT = 1/(ZtL + ZtR);

    const vector vN((ZnL*vL + ZnR*vR + dt)*invN);
    const vector vT((ZtL*vL + ZtR*vR + dt)*invT);
    const vector tN((ZnR*tL + ZnL*tR + (ZnL*ZnR)*dv)*invN);
    const vector tT((ZtR*tL + ZtL*tR + (ZtL*ZtR)*dv)*invT);

    vC = vT + (n & (vN - vT))*n;
    tC = tT + (n & (tN - tT))*n;
}


// ************************************************************************* //
