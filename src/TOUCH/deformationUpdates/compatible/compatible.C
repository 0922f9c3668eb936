/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "compatible.H"
#include "rigidWallFvPatchVectorField.H"
#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"
#include "declaredEntry.H"
#include "modelCoeffs.H"
#include "syncTools.H"
#include "Switch.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace deformationUpdates
{
    defineTypeNameAndDebug(compatible, 0);
    addToRunTimeSelectionTable(deformationUpdate, compatible, dictionary);
}
}


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- Whether a condition of lm releases its faces on the force applied
static bool releasesOnForce(const volVectorField& lm)
{
    for (const fvPatchVectorField& pf : lm.boundaryField())
    {
        if
        (
            !pf.patch().coupled()
         && isA<solidFluxFvPatchVectorField>(pf)
         && refCast<const solidFluxFvPatchVectorField>(pf).releasesOnForce()
        )
        {
            return true;
        }
    }
    return false;
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Entries  * * * * * * * * * * * * * * * * //

namespace Foam
{
    static const declaredEntry<word> jumpShareEntry
    (
        "system/fvSolution TOUCH/compatibleCoeffs", "jumpShare",
        "the momentum upwinding damps phi^2 (quadratic)"
        " or phi (linear) of the cell jump, phi the limiter's share",
        "-", word("quadratic"), entryLimits::oneOf({"quadratic", "linear"})
    );

    static const declaredEntry<scalar> pointUpwindingEntry
    (
        "system/fvSolution TOUCH/compatibleCoeffs", "pointUpwinding",
        "weight of the upwinding of the point"
        " velocities (0: off)",
        "-", 1, entryLimits::above(0, true)
    );

    static const declaredEntry<Switch> pointLimiterEntry
    (
        "system/fvSolution TOUCH/compatibleCoeffs", "pointLimiter",
        "limited extrapolation of the point velocities"
        " (default: on with reconstruction limitedLinear, else off)",
        "-", Switch(Switch::OFF)
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

bool Foam::deformationUpdates::compatible::readQuadraticShare
(
    const dictionary& coeffs
)
{
    return jumpShareEntry.read(coeffs) == "quadratic";
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deformationUpdates::compatible::compatible
(
    const dictionary& controls,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    compatible
    (
        controls,
        modelCoeffs
        (
            controls,
            typeName,
            {&jumpShareEntry, &pointUpwindingEntry, &pointLimiterEntry}
        ),
        faces,
        law,
        riemann,
        reconstruction
    )
{}


Foam::deformationUpdates::compatible::compatible
(
    const dictionary& controls,
    const dictionary& coeffs,
    solidFaces& faces,
    const mechanicalLaw& law,
    const riemannSolver& riemann,
    const linearReconstruction& reconstruction
)
:
    deformationUpdate(controls, faces, law, riemann, reconstruction),
    cellFaces_(compactAddressing::New(faces.mesh()).cellFaces()),
    pointInterpolation_
    (
        faces.mesh(),
        reconstruction,
        coeffs.found(pointLimiterEntry.name())
      ? pointLimiterEntry.read(coeffs)
      : Switch
        (
            reconstruction.schemeType()
         == linearReconstruction::scheme::limitedLinear
        )
    ),
    constraints_(faces.mesh()),
    faceFree_(faces.mesh().boundary().size()),
    faceVelocity_(faces.mesh().boundary().size()),
    faceForce_(faces.mesh().boundary().size(), Zero),
    fixingFace_(faces.mesh().boundary().size()),
    pointForce_(faces.mesh().nPoints(), Zero),
    quadraticShare_(readQuadraticShare(coeffs)),
    pointUpwinding_(pointUpwindingEntry.read(coeffs)),
    pointMobility_
    (
        law.uniformMaterial()
      ? calcPointMobility
        (
            faces.mesh(), reconstruction, pointUpwinding_, law.rho()*law.Up()
        )
      : calcPointMobilityOfMaterials(reconstruction, pointUpwinding_)
    ),
    reconstructedForce_(pointUpwinding_ > 0 ? faces.mesh().nPoints() : 0),
    faceIncrementForce_(pointUpwinding_ > 0 ? faces.mesh().nFaces() : 0),
    upwindNormal_(0),
    upwindTangential_(0),
    upwindInline_(riemann.upwindCoefficients(upwindNormal_, upwindTangential_)),
    hasContact_(contactSurfaces::any(faces.lm())),
    hasNodeContact_(false),
    nodeShare_(faces.mesh().boundary().size()),
    nodeNormal_(faces.mesh().boundary().size()),
    nodeFriction_(false),
    wallFriction_(false),
    frictionArea_(faces.mesh().boundary().size()),
    frictionMarks_(faces.mesh().boundary().size()),
    wallShare_(faces.mesh().boundary().size()),
    nodeStuck_(faces.mesh().boundary().size()),
    nodeOwn_(faces.mesh().boundary().size()),
    nodeNormalForce_(0),
    nodeMostTensile_(-GREAT),
    imbalanceWarned_(false),
    largestContactForce_(0),
    releasing_(releasesOnForce(faces.lm())),
    releaseFaceForce_(faces.mesh().boundary().size())
{
    if (hasContact_)
    {
        faces.contact().resolveAutoSides(law, faces.lm());
    }

    forAll(faces.mesh().boundary(), patchi)
    {
        const label n = pC_[patchi].size();

        faceFree_.set(patchi, new tensorField(n, tensor::I));
        faceVelocity_.set(patchi, new vectorField(n, Zero));

        const fvPatchVectorField& bf = faces.lm().boundaryField()[patchi];
        if
        (
            !bf.patch().coupled()
         && isA<solidFluxFvPatchVectorField>(bf)
         && refCast<const solidFluxFvPatchVectorField>(bf).releasesOnForce()
        )
        {
            releaseFaceForce_.set(patchi, new vectorField(n, Zero));
        }

        // Contact between bodies: its faces' points keep the contact
        // velocity along the pair's normal (with the traction alone they
        // moved with the cells: two bars at +-0.1 m/s, 50 cells a bar, met
        // at 0.77 Z v, their ends sinking into each other at 0.46 v)
        fvPatchVectorField& pf = faces.lm().boundaryFieldRef()[patchi];
        if (isA<bodyContactFvPatchVectorField>(pf))
        {
            bodyContactFvPatchVectorField& condition =
                refCast<bodyContactFvPatchVectorField>(pf);
            condition.setPointConstrained();

            if (condition.nodes())
            {
                const label nPoints = condition.patch().patch().nPoints();
                nodeShare_.set(patchi, new vectorField(nPoints, Zero));
                nodeNormal_.set(patchi, new vectorField(nPoints, Zero));
                hasNodeContact_ = true;
                if (!condition.friction().frictionless())
                {
                    frictionArea_.set(patchi, new scalarField(nPoints, Zero));
                    frictionMarks_.set(patchi, new labelField(nPoints, 1));
                    nodeStuck_.set(patchi, new boolList(nPoints, false));
                    nodeOwn_.set(patchi, new tensorField(nPoints, Zero));
                    nodeFriction_ = true;
                }
            }
        }

        // A rigid wall with friction: the friction acts at the points it
        // holds, about their reactions
        if (isA<rigidWallFvPatchVectorField>(pf))
        {
            rigidWallFvPatchVectorField& wall =
                refCast<rigidWallFvPatchVectorField>(pf);
            if (!wall.friction().frictionless())
            {
                wall.setPointFriction();
                const label nPoints = wall.patch().patch().nPoints();
                frictionArea_.set(patchi, new scalarField(nPoints, Zero));
                frictionMarks_.set(patchi, new labelField(nPoints, 1));
                wallShare_.set(patchi, new vectorField(nPoints, Zero));
                nodeStuck_.set(patchi, new boolList(nPoints, false));
                nodeOwn_.set(patchi, new tensorField(nPoints, Zero));
                wallFriction_ = true;
            }
        }
    }

    // Friction between bodies acts at the held points of side nodes: a
    // pair of surfaces with friction needs one
    if (hasContact_)
    {
        faces.contact().checkNodesFriction(faces.lm(), controls);
    }
    if (nodeFriction_)
    {
        faces.contact().setMaterialImpedances(law);
    }
    if (nodeFriction_ || wallFriction_)
    {
        calcFrictionAreas();
    }

    initLosses();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::deformationUpdates::compatible::writeOptions(Ostream& os) const
{
    os  << " (" << jumpShareEntry.name() << ' '
        << (quadraticShare_ ? "quadratic" : "linear") << ", "
        << pointUpwindingEntry.name() << ' ' << pointUpwinding_ << ", "
        << pointLimiterEntry.name() << ' '
        << (pointInterpolation_.limited() ? "on" : "off") << ')';
}


void Foam::deformationUpdates::compatible::rates
(
    const label stage,
    vectorField& lmRate,
    tensorField& FRate,
    vectorField& pointV,
    vector& torque
)
{
    // The nodal forces and the reconstructed ones are in from
    // reconstruct()
    constraints_.reset();

    addFaceRates(lmRate);
    addBoundaryFaceForces();
    if (pointForcing_)
    {
        pointForcing_->addPointForces(shares_, pointForce_);
    }

    // The nodal forces are the stresses' alone: complete before the
    // conditions, so that a wall can be released on its reaction to them
    completeNodalForces();
    setContactNodalForces();

    // The cells' velocities at the points, A v (the conditions below
    // change rates, not the cells' momenta); with friction they decide
    // which points stick, before the constraints are applied
    if (law_.uniformMaterial())
    {
        pointInterpolation_.interpolateMomentum
        (
            faces_.lm(), 1/law_.rho(), pointV
        );
    }
    else
    {
        interpolateVelocity(pointV);
    }
    if (nodeFriction_ || wallFriction_)
    {
        pointAv_ = pointV;
    }

    const bool tally = upwindLoss_.valid() && stage == 1;
    if (tally)
    {
        tallyFaceLosses();
        const vectorField before(lmRate);
        addConditionRates(stage, lmRate, torque);
        tallyCellLosses(before, lmRate);
    }
    else
    {
        addConditionRates(stage, lmRate, torque);
    }

    reportWallForces(torque);
    transferNodeReactions(torque);
    balanceContactForces(lmRate);

    // Point velocities v_a = Pi_a (A v)_a + b_a, and the upwinding of the
    // nodal forces
    constraints_.constrain(pointV);
    if (nodeFriction_ || wallFriction_)
    {
        pointVBeforeUpwinding_ = pointV;
    }

    if (pointUpwinding_ > 0)
    {
        if (tally)
        {
            const vectorField before(pointV);
            addPointUpwinding(pointV);
            tallyPointLosses(before, pointV);
        }
        else
        {
            addPointUpwinding(pointV);
        }
    }

    if (pointDisplacement_ && pointUpwinding_ > 0)
    {
        addDriftRotation(pointV);
    }

    // Points held on a partner surface (side nodes) follow its points'
    // final velocities; their friction acts at the velocities before
    holdNodesOnSurfaces(pointV);
    if (wallFriction_)
    {
        addWallFriction(torque);
    }

    // F follows the point motion alone (no upwind part: see the header)
    addFaceMeanFRate(pointV, FRate);

    addTransposeRate(lmRate);
}


Foam::scalar Foam::deformationUpdates::compatible::stableCFL
(
    const word& timeScheme
) const
{
    // Limited (the impacts): the Taylor bar on -n 6 gains energy above
    // 0.3 with either scheme (RK2 0.45: 3.4e-5 E0, RK3 0.5: 1.7e-3 E0),
    // and the bar rebound's cells invert at RK3 1.0 (-n 9, 12) and, on
    // polyhedra, 0.8 (validation/stabilityMap/FINDINGS.md 11): the
    // limiter, not the scheme's linear stability, sets the step there
    if
    (
        faces_.reconstruction().schemeType()
     == linearReconstruction::scheme::limitedLinear
    )
    {
        return 0.3;
    }

    // Twisting column, 4 x 24 x 4 and 8 x 48 x 8, nu 0.45, with the
    // quadratic jump share and the step of the cells' current heights:
    // the energy never grows up to these (at RK2 0.7 4 x 24 x 4 gains
    // 0.24 E0 in a step); RK3 holds to 1.0 also at nu 0.499, on
    // polyhedra and on tetrahedra (2 x 12 x 2: RK2 0.3, RK3 0.8;
    // validation/stabilityMap/FINDINGS.md 9, 10)
    return timeScheme == "RK3" ? 1.0 : 0.6;
}


// ************************************************************************* //
