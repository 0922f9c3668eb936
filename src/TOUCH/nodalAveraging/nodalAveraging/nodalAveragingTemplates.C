/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "nodalAveraging.H"
#include "syncTools.H"

// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::nodalAveraging::averageToPoints
(
    const Field<Type>& cellValues,
    Field<Type>& pointValues
) const
{
    const scalarField& V = mesh_.V();
    const labelListList& cellPoints = mesh_.cellPoints();

    pointValues = Zero;

    forAll(cellPoints, celli)
    {
        const Type share((V[celli]/cellPoints[celli].size())*cellValues[celli]);

        for (const label pointi : cellPoints[celli])
        {
            pointValues[pointi] += share;
        }
    }

    syncTools::syncPointList
    (
        mesh_, pointValues, plusEqOp<Type>(), pTraits<Type>::zero
    );

    pointValues /= pointVolume_;
}


template<class Type>
Type Foam::nodalAveraging::cellMean
(
    const label celli,
    const Field<Type>& pointValues
) const
{
    const labelList& points = mesh_.cellPoints()[celli];

    Type sum(Zero);
    for (const label pointi : points)
    {
        sum += pointValues[pointi];
    }

    return sum/scalar(points.size());
}


// ************************************************************************* //
