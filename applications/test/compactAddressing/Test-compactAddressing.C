/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Application
    Test-compactAddressing

Description
    Checks compactAddressing on the case's mesh (any cell shape): its cell
    faces, cell points and point cells hold the entries of the mesh's own
    cells(), cellPoints() and pointCells(), in ascending order, so that the
    sums of the classes that moved to it round as before.  It is built
    before the mesh's lists, which must not be needed for it.
    Exits non-zero on any wrong answer.

Usage
    Test-compactAddressing -case <case with a mesh>

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "compactAddressing.H"
#include "testReport.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Whether every row equals the mesh's list, sorted ascending
template<class Lists>
static bool sameRows(const compactAddressing::rows& rows, const Lists& lists)
{
    if (rows.size() != lists.size())
    {
        return false;
    }

    forAll(lists, i)
    {
        labelList expected(lists[i]);
        Foam::sort(expected);
        const UList<label> row(rows[i]);

        if (row.size() != expected.size())
        {
            return false;
        }
        forAll(row, j)
        {
            if (row[j] != expected[j])
            {
                return false;
            }
        }
    }

    return true;
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    testReport report;

    const compactAddressing& addressing = compactAddressing::New(mesh);

    report.check
    (
        "built without the mesh's cells, cellPoints, pointCells",
        !mesh.hasCells() && !mesh.hasCellPoints() && !mesh.hasPointCells()
    );
    report.check
    (
        "cell faces = mesh.cells()",
        sameRows(addressing.cellFaces(), mesh.cells())
    );
    report.check
    (
        "cell points = mesh.cellPoints()",
        sameRows(addressing.cellPoints(), mesh.cellPoints())
    );
    report.check
    (
        "point cells = mesh.pointCells()",
        sameRows(addressing.pointCells(), mesh.pointCells())
    );
    report.check
    (
        "one instance a mesh",
        &compactAddressing::New(mesh) == &addressing
    );

    return report.result("Test-compactAddressing");
}


// ************************************************************************* //
