/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The compatible update's balance of a contact between bodies: each
    contact face's share of the nodal forces at its points (from which the
    contact velocity makes the two sides' forces equal and opposite), and
    the sides' remaining difference taken back from the faces pushed on,
    so that momentum is exchanged exactly (balanceContactForces).

\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "syncTools.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::setContactNodalForces()
{
    if (!hasContact_)
    {
        return;
    }

    const fvMesh& mesh = faces_.mesh();

    for (const label patchi : faces_.contact().patches())
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                faces_.lm().boundaryFieldRef()[patchi]
            );
        const primitivePatch& pp = condition.patch().patch();
        const labelList& meshPoints = pp.meshPoints();
        const faceList& localFaces = pp.localFaces();

        // The patch's faces at each of its points, on all ranks (every
        // rank takes part, also one whose part of the patch is empty)
        labelList nFaces(meshPoints.size(), 0);
        for (const face& f : localFaces)
        {
            for (const label pointj : f)
            {
                ++nFaces[pointj];
            }
        }
        syncTools::syncPointList
        (
            mesh, meshPoints, nFaces, plusEqOp<label>(), label(0)
        );

        vectorField& nodalForce = condition.nodalForce();
        forAll(localFaces, i)
        {
            vector sum(Zero);
            for (const label pointj : localFaces[i])
            {
                sum += pointForce_[meshPoints[pointj]]/nFaces[pointj];
            }
            nodalForce[i] = sum;
        }
    }
}


Foam::scalar Foam::deformationUpdates::compatible::contactWeight
(
    const label celli,
    const scalar magSf
) const
{
    // One material: the area alone, the same shares as the impedances'
    return law_.uniformMaterial()
      ? magSf
      : magSf*law_.rho(celli)*law_.Up(celli);
}


void Foam::deformationUpdates::compatible::warnImbalance
(
    const vector& imbalance,
    const scalar forceScale,
    const wordList& patches
)
{
    // forceScale sums both sides' magnitudes: twice the contact force
    largestContactForce_ = max(largestContactForce_, forceScale/2);
    const scalar share = mag(imbalance)/max(largestContactForce_, VSMALL);
    if (largestContactForce_ <= VSMALL || share <= imbalanceWarning)
    {
        return;
    }

    imbalanceWarned_ = true;
    WarningInFunction
        << "At time " << faces_.mesh().time().timeName()
        << " the two sides' forces of the contact between bodies "
        << patches << " differ by " << 100*share
        << " % of the largest contact force so far." << nl
        << "    With FUpdate compatible each side holds its faces in"
        << " contact whole; where the faces do not match, the two sides"
        << " hold different areas," << nl
        << "    the balancing moves the difference, and the energy can"
        << " grow (doc/userGuide.md, bodies in contact)." << nl
        << "    'side nodes;' in the bodyContact entry of the softer patch"
        << " (the finer where the two are alike) holds that side alone on"
        << " the other's surface" << nl
        << "    and exchanges the force point by point. Warned once."
        << nl << endl;
}


void Foam::deformationUpdates::compatible::balanceContactForces
(
    vectorField& lmRate
)
{
    if (!hasContact_)
    {
        return;
    }

    vector imbalance(Zero);
    scalar weightSum = 0;
    scalar forceScale = 0;
    DynamicList<word> patches;

    for (const label patchi : faces_.contact().patches())
    {
        const bodyContactFvPatchVectorField& condition =
            refCast<const bodyContactFvPatchVectorField>
            (
                faces_.lm().boundaryField()[patchi]
            );
        const scalarField& magSf = condition.patch().magSf();
        const labelUList& faceCells = condition.patch().faceCells();

        imbalance += condition.stageForce();
        if (!imbalanceWarned_)
        {
            forceScale +=
                mag(returnReduce(condition.stageForce(), sumOp<vector>()));
            patches.append(condition.patch().name());
        }
        forAll(condition.touching(), i)
        {
            if (condition.touching()[i])
            {
                weightSum += contactWeight(faceCells[i], magSf[i]);
            }
        }
    }

    reduce(imbalance, sumOp<vector>());
    reduce(weightSum, sumOp<scalar>());

    if (!imbalanceWarned_)
    {
        warnImbalance(imbalance, forceScale, patches);
    }

    if (weightSum <= 0)
    {
        return;
    }

    for (const label patchi : faces_.contact().patches())
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                faces_.lm().boundaryFieldRef()[patchi]
            );
        const scalarField& magSf = condition.patch().magSf();
        const labelUList& faceCells = condition.patch().faceCells();
        vector taken(Zero);

        forAll(faceCells, i)
        {
            if (condition.touching()[i])
            {
                const vector correction
                (
                    -(contactWeight(faceCells[i], magSf[i])/weightSum)
                   *imbalance
                );
                lmRate[faceCells[i]] += correction;
                taken += correction;
            }
        }
        condition.correctStageForce(condition.stageForce() + taken);
    }
}


// ************************************************************************* //
