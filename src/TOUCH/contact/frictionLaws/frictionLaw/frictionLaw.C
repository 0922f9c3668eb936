/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "frictionLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(frictionLaw, 0);
    defineRunTimeSelectionTable(frictionLaw, dictionary);
}

const char* const Foam::frictionLaw::where =
    "0/U (or 0/lm) boundaryField, contact condition friction";


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionLaw::frictionLaw(const dictionary& dict)
:
    dict_(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionLaw::write(Ostream& os) const
{
    if (dict_.size())
    {
        dict_.writeEntry("friction", os);
    }
}


// ************************************************************************* //
