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
    sums of the classes that moved to it round as before, and the slots
    of the faces' points in their cells' point rows name those points.
    It is built before the mesh's lists, which must not be needed for it.
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


//- Whether the slot of every face point in its cell's point row names
//  that point, face by face in the order of the cell's faces
static bool slotsNamePoints
(
    const compactAddressing& addressing,
    const faceList& faces
)
{
    const compactAddressing::slotRows& slots =
        addressing.cellFacePointSlots();
    if (slots.empty())
    {
        return false;
    }

    const compactAddressing::rows& cellFaces = addressing.cellFaces();
    const compactAddressing::rows& cellPoints = addressing.cellPoints();

    for (label c = 0; c < cellFaces.size(); ++c)
    {
        const uint8_t* slot = slots.row(c);
        const UList<label> points(cellPoints[c]);
        for (const label facei : cellFaces[c])
        {
            for (const label pointi : faces[facei])
            {
                const label s = *slot++;
                if (s >= points.size() || points[s] != pointi)
                {
                    return false;
                }
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
        "face point slots name the cell points",
        slotsNamePoints(addressing, mesh.faces())
    );
    report.check
    (
        "one instance a mesh",
        &compactAddressing::New(mesh) == &addressing
    );

    return report.result("Test-compactAddressing");
}


// ************************************************************************* //
