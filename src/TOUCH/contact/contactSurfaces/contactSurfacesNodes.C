/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    Side nodes of contactSurfaces: the partner surface under a held point,
    its weights over the partner face's points, and the point slots through
    which the update reads the partner's velocities and gives it the
    reactions (compatible::transferNodeReactions, holdNodesOnSurfaces).

\*---------------------------------------------------------------------------*/

#include "contactSurfaces.H"
#include "bodyContactFvPatchVectorField.H"

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace Foam
{
    //- Opposed faces: the cosine of the angle of their normals below this
    //  (as the pairing's)
    static const scalar nodesOpposedCos = -0.5;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::contactSurfaces::anyNodes() const
{
    forAll(nodes_, s)
    {
        if (nodes_[s])
        {
            return true;
        }
    }
    return false;
}


bool Foam::contactSurfaces::nodesContact(const label s) const
{
    if (nodes_[s])
    {
        return true;
    }
    forAll(nodes_, t)
    {
        if (nodes_[t] && allowed_[s][t])
        {
            return true;
        }
    }
    return false;
}


void Foam::contactSurfaces::subtractSlotPowers
(
    const vectorField& slotForce,
    const vectorField& slotVelocity,
    scalarField& patchPower
) const
{
    label o = pointStart_[globalFaces_.localStart()];
    forAll(patches_, s)
    {
        const label nSlots =
            pointStart_[globalFaces_.localStart() + start_[s + 1]]
          - pointStart_[globalFaces_.localStart() + start_[s]];
        for (label m = 0; m < nSlots; ++m)
        {
            patchPower[s] -= slotForce[o] & slotVelocity[o];
            ++o;
        }
    }
}


Foam::label Foam::contactSurfaces::localFace
(
    const label patchi,
    const label i
) const
{
    const label s = patches_.find(patchi);
    if (s < 0)
    {
        FatalErrorInFunction
            << "Patch " << mesh_.boundary()[patchi].name()
            << " is not a bodyContact patch" << exit(FatalError);
    }
    return start_[s] + i;
}


void Foam::contactSurfaces::surfaceWeights
(
    const label k,
    const point& x,
    const vector& e,
    DynamicList<label>& slots,
    DynamicList<scalar>& weights
) const
{
    const label gk = globalFaces_.localStart() + k;
    const label s = slot_[gk];

    // The best triangle so far: its face, its edge and the barycentric
    // weights of the point where the line x + t e meets its plane.  Best:
    // the largest smallest weight (inside when >= 0), ties to the smaller
    // face index, so that every rank that holds the point chooses alike
    label bestFace = -1;
    label bestEdge = -1;
    scalar bestScore = -GREAT;
    vector bestLambda(Zero);

    const auto consider = [&](const label g)
    {
        if
        (
            !faceActive_[g]
         || !allowed_[s][slot_[g]]
         || !nodePair(gk, g)
         || (n_[gk] & n_[g]) > nodesOpposedCos
        )
        {
            return;
        }

        const label first = pointStart_[g];
        const label nPoints = pointStart_[g + 1] - first;
        point centre(Zero);
        for (label m = 0; m < nPoints; ++m)
        {
            centre += pointOffsets_[first + m];
        }
        centre = x_[g] + centre/nPoints;
        const scalar size = Foam::sqrt(a_[g]);

        for (label m = 0; m < nPoints; ++m)
        {
            const point b(x_[g] + pointOffsets_[first + m]);
            const point d(x_[g] + pointOffsets_[first + (m + 1) % nPoints]);
            const vector N((b - centre) ^ (d - centre));
            const scalar magSqrN = magSqr(N);
            const scalar across = e & N;
            if (magSqrN <= VSMALL || mag(across) <= 1e-6*Foam::sqrt(magSqrN))
            {
                continue;
            }

            // Along e from x to the triangle's plane: not a face of the far
            // side of a body
            const scalar t = ((centre - x) & N)/across;
            if (t < -0.5*size || t > 0.5*size)
            {
                continue;
            }
            const vector r(x + t*e - centre);
            const scalar lb = ((r ^ (d - centre)) & N)/magSqrN;
            const scalar ld = (((b - centre) ^ r) & N)/magSqrN;
            const vector lambda(1 - lb - ld, lb, ld);
            const scalar score = cmptMin(lambda);

            if
            (
                score > bestScore
             || (score == bestScore && g < bestFace)
            )
            {
                bestFace = g;
                bestEdge = m;
                bestScore = score;
                bestLambda = lambda;
            }
        }
    };

    for (const label g : candidates_[k])
    {
        consider(g);
    }

    // A face in contact has its partners among its candidates; should the
    // search have missed one, every face is tried before giving up
    if (bestFace < 0)
    {
        forAll(x_, g)
        {
            consider(g);
        }
    }
    if (bestFace < 0)
    {
        FatalErrorInFunction
            << "No partner surface under the point " << x << " of patch "
            << mesh_.boundary()[patches_[s]].name() << " (side nodes), which"
            << " its face's contact holds" << exit(FatalError);
    }

    // Clipped to the triangle, then spread over the face's points: the
    // centre's weight equally
    vector lambda(max(bestLambda, vector::zero));
    lambda /= cmptSum(lambda);

    const label first = pointStart_[bestFace];
    const label nPoints = pointStart_[bestFace + 1] - first;
    for (label m = 0; m < nPoints; ++m)
    {
        scalar w = lambda.x()/nPoints;
        if (m == bestEdge)
        {
            w += lambda.y();
        }
        if (m == (bestEdge + 1) % nPoints)
        {
            w += lambda.z();
        }
        slots.append(first + m);
        weights.append(w);
    }
}


Foam::tmp<Foam::vectorField> Foam::contactSurfaces::gatherSlots
(
    const vectorField& pointValues
) const
{
    const faceList& faces = mesh_.faces();
    vectorField local
    (
        pointStart_[globalFaces_.localStart() + globalFaces_.localSize()]
      - pointStart_[globalFaces_.localStart()]
    );

    label o = 0;
    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        forAll(patch, i)
        {
            for (const label pointi : faces[patch.start() + i])
            {
                local[o++] = pointValues[pointi];
            }
        }
    }

    return gather(local);
}


void Foam::contactSurfaces::addSlotForces
(
    const vectorField& slotForce,
    vectorField& pointForce,
    List<vector>& patchForce,
    vector& torque
) const
{
    const faceList& faces = mesh_.faces();
    label o = pointStart_[globalFaces_.localStart()];

    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        forAll(patch, i)
        {
            const label g = globalFaces_.localStart() + start_[s] + i;
            for (const label pointi : faces[patch.start() + i])
            {
                const vector& f = slotForce[o];
                pointForce[pointi] += f;
                patchForce[s] -= f;
                torque -= (x_[g] + pointOffsets_[o]) ^ f;
                ++o;
            }
        }
    }
}


Foam::scalar Foam::contactSurfaces::pairShearImpedance
(
    const label k,
    const label slot
) const
{
    const label gk = globalFaces_.localStart() + k;
    const label g = findLower(pointStart_, slot + 1);
    return materialZs_[gk]*materialZs_[g]/(materialZs_[gk] + materialZs_[g]);
}



void Foam::contactSurfaces::reportNodeFriction
(
    const scalar ratio,
    const scalar power
)
{
    pairFrictionRatio_ = max(pairFrictionRatio_, ratio);
    pairFrictionPower_ = max(pairFrictionPower_, power);
}


void Foam::contactSurfaces::resolveAutoSides
(
    const mechanicalLaw& law,
    volVectorField& lm
)
{
    // Each patch's mean P-wave impedance and mean face area, on all ranks
    const label n = patches_.size();
    scalarList Z(n, Zero);
    scalarList area(n, Zero);
    scalarList faces(n, Zero);
    bool anyAuto = false;
    forAll(patches_, s)
    {
        const fvPatch& patch = mesh_.boundary()[patches_[s]];
        for (const label celli : patch.faceCells())
        {
            Z[s] += law.rho(celli)*law.Up(celli);
        }
        area[s] = sum(patch.magSf());
        faces[s] = patch.size();
        anyAuto =
            anyAuto
         || refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[s]]
            ).autoSide();
    }
    if (!anyAuto)
    {
        return;
    }
    Pstream::listCombineGather(Z, plusEqOp<scalar>());
    Pstream::listCombineGather(area, plusEqOp<scalar>());
    Pstream::listCombineGather(faces, plusEqOp<scalar>());
    Pstream::listCombineScatter(Z);
    Pstream::listCombineScatter(area);
    Pstream::listCombineScatter(faces);
    forAll(Z, s)
    {
        Z[s] /= max(faces[s], scalar(1));
        area[s] /= max(faces[s], scalar(1));
    }

    // Whether s, not t, should hold its points: the softer, else the
    // finer, else the first in the boundary (ratios within 5 % alike)
    auto holdsAgainst = [&](const label s, const label t)
    {
        const scalar rZ = Z[s]/max(Z[t], VSMALL);
        if (mag(rZ - 1) > 0.05)
        {
            return rZ < 1;
        }
        const scalar rA = area[s]/max(area[t], VSMALL);
        if (mag(rA - 1) > 0.05)
        {
            return rA < 1;
        }
        return s < t;
    };

    const boolList given(nodes_);
    forAll(patches_, s)
    {
        bodyContactFvPatchVectorField& condition =
            refCast<bodyContactFvPatchVectorField>
            (
                lm.boundaryFieldRef()[patches_[s]]
            );
        if (!condition.autoSide())
        {
            continue;
        }
        label against = -1;
        forAll(patches_, t)
        {
            if
            (
                t != s && (allowed_[s][t] || allowed_[t][s]) && !given[t]
             && holdsAgainst(s, t)
            )
            {
                against = t;
                break;
            }
        }
        if (against >= 0)
        {
            nodes_[s] = true;
            condition.setNodes();
        }
        Info<< "bodyContact " << mesh_.boundary()[patches_[s]].name()
            << ": side auto -> " << (against >= 0 ? "nodes" : "both");
        if (against >= 0)
        {
            const int precision = Info().precision(4);
            Info<< " (against " << mesh_.boundary()[patches_[against]].name()
                << ": rho c_p " << Z[s] << " and " << Z[against]
                << ", mean face area " << area[s] << " and " << area[against]
                << ")";
            Info().precision(precision);
        }
        Info<< endl;
    }
}


void Foam::contactSurfaces::checkNodesFriction
(
    const volVectorField& lm,
    const dictionary& controls
) const
{
    forAll(patches_, s)
    {
        const bodyContactFvPatchVectorField& condition =
            refCast<const bodyContactFvPatchVectorField>
            (
                lm.boundaryField()[patches_[s]]
            );
        if (condition.friction().frictionless() || nodes_[s])
        {
            continue;
        }
        // A patch's contact with itself is left to its faces (a surface
        // cannot hold its own points): only pairs of two patches
        forAll(patches_, t)
        {
            if (t != s && allowed_[s][t] && !nodes_[t])
            {
                FatalIOErrorInFunction(controls)
                    << "Patches " << mesh_.boundary()[patches_[s]].name()
                    << " and " << mesh_.boundary()[patches_[t]].name()
                    << " (bodyContact) may touch with friction, and FUpdate"
                    << " is compatible (" << controls.name() << "): its"
                    << " normal contact force is the reaction of the points"
                    << " the contact holds, which friction needs at points"
                    << " held on one side" << nl
                    << "Valid: 'side nodes;' on one of the two patches (the"
                    << " softer, or the finer where they are alike), 'side"
                    << " auto;' on both, or FUpdate plain" << nl
                    << exit(FatalIOError);
            }
        }
    }
}


// ************************************************************************* //
