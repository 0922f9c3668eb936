/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.
\*---------------------------------------------------------------------------*/

#include "linearReconstruction.H"
#include "fvMesh.H"
#include "calculatedFvPatchFields.H"
#include "declaredEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::linearReconstruction::scheme>
Foam::linearReconstruction::schemeNames
({
    { scheme::firstOrder, "firstOrder" },
    { scheme::linear, "linear" },
    { scheme::limitedLinear, "limitedLinear" },
});


namespace Foam
{
    static const declaredEntry<word> reconstructionEntry
    (
        "system/fvSolution TOUCH", "reconstruction",
        "the face values of p and P: cell values (firstOrder), least-squares"
        " linear, or linear with a gradient limiter (limitedLinear: monotone"
        " fronts)",
        "-", word("limitedLinear"),
        entryLimits::oneOf({"firstOrder", "linear", "limitedLinear"}),
        declaredEntry<word>::required
    );
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::linearReconstruction::calcWeights()
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = X();
    const vectorField& Cf = mesh_.faceCentres();

    // Least-squares matrices M = sum w d d, w = 1/|d|^2
    symmTensorField M(mesh_.nCells(), Zero);

    forAll(own, facei)
    {
        const vector d(C[nei[facei]] - C[own[facei]]);
        const symmTensor wdd(sqr(d)/magSqr(d));
        M[own[facei]] += wdd;
        M[nei[facei]] += wdd;

        // As weight(): 1/|d|^2, the same from either side
        inverseDistanceSqr_[facei] = 1/magSqr(d);
    }

    forAll(mesh_.boundaryMesh(), patchi)
    {
        const polyPatch& patch = mesh_.boundaryMesh()[patchi];

        if (patch.coupled() || mirror_[patchi])
        {
            const vectorField& Xn = neighbourCentres_[patchi];
            const labelUList& faceCells = patch.faceCells();

            forAll(Xn, i)
            {
                const vector d(Xn[i] - C[faceCells[i]]);
                M[faceCells[i]] += sqr(d)/magSqr(d);
            }
        }
    }

    // Cells whose neighbours do not span space: add their boundary faces.
    // The faces of the polyPatches: an empty patch (2D) has no fvPatch
    // faces, but its faces bound the cells as a symmetric plane's do
    label nRegularised = 0;

    forAll(mesh_.boundaryMesh(), patchi)
    {
        const polyPatch& patch = mesh_.boundaryMesh()[patchi];

        if (patch.coupled() || mirror_[patchi])
        {
            continue;
        }

        forAll(patch, i)
        {
            const label c = patch.faceCells()[i];

            // det(M) relative to its scale: 1 for three orthogonal pairs
            if (det(M[c]) < 1e-3*pow3(tr(M[c])/3))
            {
                const vector d(Cf[patch.start() + i] - C[c]);
                M[c] += sqr(d)/magSqr(d);
                ++nRegularised;
            }
        }
    }

    reduce(nRegularised, sumOp<label>());

    if (nRegularised)
    {
        Info<< "linearReconstruction: " << nRegularised
            << " boundary faces added to rank-deficient least-squares"
            << " stencils" << endl;
    }

    Minv_ = inv(M);
    const symmTensorField& Minv = Minv_;

    forAll(mesh_.boundaryMesh(), patchi)
    {
        const polyPatch& patch = mesh_.boundaryMesh()[patchi];

        if (patch.coupled() || mirror_[patchi])
        {
            const vectorField& Xn = neighbourCentres_[patchi];
            const labelUList& faceCells = patch.faceCells();
            vectorField& w = coupledWeights_[patchi];

            forAll(Xn, i)
            {
                const vector d(Xn[i] - C[faceCells[i]]);
                // As weight(): the same round-off as an interior face's
                w[i] = (Minv[faceCells[i]] & d)*(1/magSqr(d));
            }
        }
    }
}


void Foam::linearReconstruction::reflectMirrorValues
(
    const vectorField& p,
    const tensorField& P
)
{
    forAll(mirrorNormals_, patchi)
    {
        if (!mirror_[patchi])
        {
            continue;
        }

        const vectorField& N = mirrorNormals_[patchi];
        const scalar sign = mirrorSign_[patchi];
        const labelUList& faceCells =
            mesh_.boundaryMesh()[patchi].faceCells();
        vectorField& pR = pNeighbour_[patchi];
        tensorField& PR = PNeighbour_[patchi];

        forAll(N, i)
        {
            const tensor R(tensor::I - 2*sqr(N[i]));
            const label c = faceCells[i];

            pR[i] = sign*(R & p[c]);
            PR[i] = sign*(R & P[c] & R);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::linearReconstruction::linearReconstruction
(
    const fvMesh& mesh,
    const dictionary& dict,
    const scalarList& mirrorSigns
)
:
    mesh_(mesh),
    scheme_(schemeNames[reconstructionEntry.read(dict)]),
    limiter_
    (
        scheme_ == scheme::limitedLinear
      ? gradientLimiter::New(dict)
      : autoPtr<gradientLimiter>()
    ),
    cellBody_(),
    nBodies_(0),
    boundaryFacePatch_(mesh.nFaces() - mesh.nInternalFaces(), -1),
    pNeighbour_(mesh.boundary().size()),
    PNeighbour_(mesh.boundary().size()),
    neighbourCentres_(mesh.boundary().size()),
    Minv_(mesh.nCells()),
    inverseDistanceSqr_(mesh.nInternalFaces()),
    coupledWeights_(mesh.boundary().size()),
    mirror_(mesh.boundary().size(), false),
    mirrorSign_(mesh.boundary().size(), scalar(1)),
    mirrorNormals_(mesh.boundary().size()),
    gradp_
    (
        IOobject
        (
            "grad(lm)",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedTensor("0", dimless, Zero),
        calculatedFvPatchTensorField::typeName
    ),
    gradP_()
{
    if (limiter_.valid())
    {
        momentumLimiter_.setSize(mesh.nCells());

        const solidBodies bodies(mesh);
        cellBody_ = bodies.cellBody();
        nBodies_ = bodies.size();
    }

    forAll(mirrorSigns, patchi)
    {
        if (mirrorSigns[patchi] != 0)
        {
            mirror_[patchi] = true;
            mirrorSign_[patchi] = mirrorSigns[patchi];
        }
    }

    // The polyPatches' sizes and faces throughout: an empty patch (2D) has
    // no fvPatch faces, yet its faces are the cells' faces, and as a mirror
    // (symmetricPlanes mirror) they are a symmetric plane's
    const vectorField& Sf = mesh.faceAreas();
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& patch = mesh.boundaryMesh()[patchi];

        SubList<label>
        (
            boundaryFacePatch_,
            patch.size(),
            patch.start() - mesh.nInternalFaces()
        ) = patchi;

        if (patch.coupled() || mirror_[patchi])
        {
            pNeighbour_.set(patchi, new vectorField(patch.size()));
            PNeighbour_.set(patchi, new tensorField(patch.size()));
        }

        // The unit normals as fvPatch::nf() forms them, S_f/|S_f|
        mirrorNormals_.set(patchi, new vectorField());
        if (mirror_[patchi])
        {
            const vectorField::subField S(patch.patchSlice(Sf));
            mirrorNormals_[patchi] = S/mag(S);
        }
    }

    Info<< "Reconstruction " << description().c_str() << endl;

    {
        // The neighbour centres across the coupled patches, through a field
        // of the centres with the coupled patch types for the exchange
        volVectorField X
        (
            IOobject
            (
                "referenceCellCentres",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensionedVector("0", dimLength, Zero),
            calculatedFvPatchVectorField::typeName
        );
        X.primitiveFieldRef() = mesh.C().primitiveField();
        forAll(X.boundaryField(), patchi)
        {
            X.boundaryFieldRef()[patchi] = mesh.C().boundaryField()[patchi];
        }
        X.correctBoundaryConditions();

        // Both empty but on the coupled and the mirror patches; a mirror
        // face's neighbour is the cell's reflection in the face's plane
        forAll(mesh.boundary(), patchi)
        {
            const polyPatch& patch = mesh.boundaryMesh()[patchi];
            const bool coupled = patch.coupled();

            neighbourCentres_.set
            (
                patchi,
                new vectorField
                (
                    coupled
                  ? X.boundaryField()[patchi].patchNeighbourField()
                  : tmp<vectorField>(new vectorField())
                )
            );

            if (mirror_[patchi])
            {
                const vectorField Xc(X(), patch.faceCells());
                const vectorField& N = mirrorNormals_[patchi];
                neighbourCentres_[patchi] =
                    Xc + 2*((patch.faceCentres() - Xc) & N)*N;
            }

            coupledWeights_.set
            (
                patchi,
                new vectorField
                (
                    coupled || mirror_[patchi] ? patch.size() : 0,
                    Zero
                )
            );
        }
    }

    calcWeights();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::linearReconstruction::description() const
{
    string text(schemeNames[scheme_]);
    if (limiter_.valid())
    {
        text += " (limiter " + limiter_->type() + ')';
    }
    return text;
}


void Foam::linearReconstruction::update
(
    const volVectorField& p,
    const volTensorField& P
)
{
    if (gradP_.empty())
    {
        // Sized on first use: an update that takes the stress gradients
        // cell by cell (compatible) never stores them
        gradP_.setSize(3);
        const char* const axes[3] = {"X", "Y", "Z"};
        forAll(gradP_, d)
        {
            gradP_.set
            (
                d,
                new volTensorField
                (
                    IOobject
                    (
                        word("d(P)/d") + axes[d],
                        mesh_.time().timeName(),
                        mesh_,
                        IOobject::NO_READ,
                        IOobject::NO_WRITE,
                        false
                    ),
                    mesh_,
                    dimensionedTensor("0", dimless, Zero),
                    calculatedFvPatchTensorField::typeName
                )
            );
        }
    }

    if (scheme_ == scheme::firstOrder)
    {
        return;
    }

    tensorField& gx = gradP_[0].primitiveFieldRef();
    tensorField& gy = gradP_[1].primitiveFieldRef();
    tensorField& gz = gradP_[2].primitiveFieldRef();

    updateCells<false>
    (
        p,
        P,
        [&]
        (
            const label celli,
            const tensor& gxc,
            const tensor& gyc,
            const tensor& gzc,
            const tensor& phiP,
            const tensor*
        )
        {
            gx[celli] = cmptMultiply(gxc, phiP);
            gy[celli] = cmptMultiply(gyc, phiP);
            gz[celli] = cmptMultiply(gzc, phiP);
        }
    );

    forAll(gradP_, d)
    {
        gradP_[d].correctBoundaryConditions();
    }
}


// ************************************************************************* //
