#include "autorig/RigSurface.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>

#include "autorig/WrapInput.h"
#include "base/DisjointSets.h"
#include "base/Error.h"
#include "mesh/MeshAdjacency.h"
#include "mesh/MeshChecks.h"

namespace rigmesh {

namespace {

// Bytes per input vertex and face the rig holds at once at most: the
// welding table, the wrap's soup and its clustered copy (measured order
// of magnitude, with room to spare).
constexpr double kBytesPerVertex = 160.0;
constexpr double kBytesPerFace = 240.0;

void checkInput(const TriMesh& mesh, const RigSurfaceOptions& options) {
    for (const Vec3& v : mesh.vertices)
        if (!v.allFinite())
            throw Error(MessageId::AutoRigNotFinite);
    for (const auto& face : mesh.faces)
        for (int corner : face)
            if (corner < 0 || corner >= mesh.vertexCount())
                throw Error(MessageId::AutoRigFaceOutOfRange, corner, mesh.vertexCount());
    const double bytes = kBytesPerVertex * mesh.vertexCount() + kBytesPerFace * mesh.faceCount();
    if (bytes > options.memoryBudgetBytes)
        throw Error(MessageId::AutoRigOverMemoryBudget, mesh.faceCount(),
                    static_cast<long long>(options.memoryBudgetBytes / (1024.0 * 1024.0)));
}

// The connected piece of `mesh` with the largest area, and how many there are.
TriMesh largestPiece(const TriMesh& mesh, int& pieces) {
    DisjointSets sets(mesh.vertices.size());
    for (const auto& f : mesh.faces) {
        sets.unite(f[0], f[1]);
        sets.unite(f[0], f[2]);
    }
    std::vector<double> area(mesh.vertices.size(), 0.0);
    for (const auto& f : mesh.faces)
        area[sets.find(f[0])] += (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                                     .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]])
                                     .norm();
    pieces = 0;
    int best = -1;
    for (int v = 0; v < mesh.vertexCount(); ++v)
        if (sets.find(v) == v && area[v] > 0.0) {
            ++pieces;
            if (best < 0 || area[v] > area[best])
                best = v;
        }
    if (pieces <= 1)
        return mesh;
    TriMesh piece;
    std::vector<int> index(mesh.vertices.size(), -1);
    for (const auto& f : mesh.faces) {
        if (sets.find(f[0]) != best)
            continue;
        std::array<int, 3> face{};
        for (int i = 0; i < 3; ++i) {
            if (index[f[i]] < 0) {
                index[f[i]] = piece.vertexCount();
                piece.vertices.push_back(mesh.vertices[f[i]]);
            }
            face[i] = index[f[i]];
        }
        piece.faces.push_back(face);
    }
    return piece;
}

// `mesh`'s mean edge length over the diagonal of its vertices' bounding box
// (0 for a mesh without faces or extent).
double edgeFraction(const TriMesh& mesh) {
    const double diagonal = mesh.vertices.empty() ? 0.0 : boundingBox(mesh).diagonal().norm();
    return mesh.faceCount() > 0 && diagonal > 0.0 ? meanEdgeLength(mesh) / diagonal : 0.0;
}

RigSurface fromRepair(RepairedMesh repaired, const WrapInput& input) {
    RigSurface surface;
    surface.kind = repaired.repairs.empty() ? RigSurface::Kind::Input : RigSurface::Kind::Repaired;
    surface.mesh = std::move(repaired.mesh);
    surface.mainPiece = surface.mesh;
    surface.notes = std::move(repaired.repairs);
    surface.surfaceVertexOf.assign(input.weldedTo.size(), -1);
    // A welded vertex's copies take its surface vertex.
    std::vector<int> ofWelded(input.weldedTo.size(), -1);
    for (int s = 0; s < surface.mesh.vertexCount(); ++s) {
        const int source = repaired.sourceVertex[s];
        if (source >= 0 && ofWelded[input.weldedTo[source]] < 0)
            ofWelded[input.weldedTo[source]] = s;
    }
    for (std::size_t v = 0; v < input.weldedTo.size(); ++v)
        surface.surfaceVertexOf[v] = ofWelded[input.weldedTo[v]];
    return surface;
}

}  // namespace

RigSurface rigSurfaceFor(const TriMesh& input, const RigSurfaceOptions& options,
                         const RigProgress& progress) {
    checkInput(input, options);
    WrapInput wrapInput = wrapInputFor(input);
    if (wrapInput.soup.faces.empty())
        throw Error(MessageId::AutoRigTooFewFaces, input.faceCount());

    Message unfit;
    const double edges = edgeFraction(input);
    const bool coarse = edges > options.coarsestEdgeFraction;
    if (input.vertexCount() <= options.directVertexLimit && !coarse) {
        if (input.faceCount() >= 4 && fitForRigging(input)) {
            RepairedMesh same;
            same.mesh = input;
            same.sourceVertex.resize(input.vertices.size());
            std::iota(same.sourceVertex.begin(), same.sourceVertex.end(), 0);
            RigSurface surface = fromRepair(std::move(same), wrapInput);
            surface.pieceOf = std::move(wrapInput.pieceOf);
            surface.pieces = wrapInput.pieces;
            return surface;
        }
        RepairAttempt attempt = repairForRigging(input, options.repair);
        if (attempt.repaired) {
            RigSurface surface = fromRepair(std::move(*attempt.repaired), wrapInput);
            surface.kind = RigSurface::Kind::Repaired;
            surface.pieceOf = std::move(wrapInput.pieceOf);
            surface.pieces = wrapInput.pieces;
            return surface;
        }
        unfit = attempt.reason;
    }
    reportRigProgress(progress, 0.0);

    RigSurface surface;
    surface.kind = RigSurface::Kind::Proxy;
    if (wrapInput.pieces > 1)
        surface.notes.push_back(
            {MessageId::AutoRigSeveralPieces, {messageArgument(wrapInput.pieces)}});
    if (wrapInput.borderLoops > 0)
        surface.notes.push_back({MessageId::AutoRigOpenBorder,
                                 {messageArgument(wrapInput.borderLoops),
                                  messageArgument(wrapInput.largestBorderEdges)}});
    if (unfit.id == MessageId::AutoRigSelfIntersecting || unfit.id == MessageId::AutoRigNotManifold)
        surface.notes.push_back(unfit);
    if (input.vertexCount() > options.directVertexLimit)
        surface.notes.push_back(
            {MessageId::AutoRigLargeMesh, {messageArgument(input.vertexCount())}});
    else if (coarse)
        surface.notes.push_back({MessageId::AutoRigCoarseMesh, {shortNumber(100.0 * edges)}});

    ProxyWrapResult wrap = wrapIntoProxy(wrapInput.soup, options.wrap, progress);
    surface.alpha = wrap.alpha;
    surface.offset = wrap.offset;
    surface.mesh = std::move(wrap.mesh);
    int proxyPieces = 1;
    surface.mainPiece = largestPiece(surface.mesh, proxyPieces);
    surface.notes.push_back({MessageId::AutoRigProxyWrapped,
                             {messageArgument(surface.mesh.vertexCount()),
                              messageArgument(std::max(1, wrapInput.pieces))}});
    if (proxyPieces > 1)
        surface.notes.push_back({MessageId::AutoRigProxyApart, {messageArgument(proxyPieces - 1)}});
    surface.surfaceVertexOf.assign(input.vertices.size(), -1);
    surface.pieceOf = std::move(wrapInput.pieceOf);
    surface.pieces = wrapInput.pieces;
    return surface;
}

}  // namespace rigmesh
