#include "cut/CutPart.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "autorig/JointsInside.h"
#include "base/Error.h"
#include "base/ParallelFor.h"
#include "base/Stopwatch.h"
#include "cut/SurfaceSplitCgal.h"
#include "geometry/ConstrainedTriangulation.h"
#include "mesh/CgalClosedSurface.h"
#include "mesh/ExactWinding.h"
#include "mesh/Fairing.h"
#include "mesh/MeshAdjacency.h"
#include "mesh/MeshVolume.h"
#include "part/BoneAnnotations.h"
#include "part/BoneConnection.h"
#include "part/BoneWeights.h"
#include "rig/ShortBones.h"
#include "surface/PatchLattice.h"

namespace rigmesh {

namespace {

// Fills one hole with a planar patch (paper 3.1: GridMesh-like; here our
// lattice + CDT, as the sketch patches of 2.2). The loop runs the way the
// patch must (SurfaceSplit.h); returns the new vertices.
std::vector<int> fillHole(TriMesh& mesh, const std::vector<int>& loop, const CutSurface& surface,
                          double edgeLength) {
    std::vector<Vec2> boundary;
    for (int i : loop)
        boundary.push_back(surface.toPatch(mesh.vertices[i]));
    double area = 0.0;
    for (std::size_t i = 0; i < boundary.size(); ++i) {
        const Vec2& a = boundary[i];
        const Vec2& b = boundary[(i + 1) % boundary.size()];
        area += a.x() * b.y() - a.y() * b.x();
    }
    // Counter-clockwise in the patch's frame (mirrored if need be), so the
    // triangles run as the hole's border does.
    const double flip = area < 0.0 ? -1.0 : 1.0;
    for (Vec2& p : boundary)
        p.y() *= flip;
    const std::vector<Vec2> interior = latticeInside(boundary, edgeLength);
    const PatchTriangulation patch =
        triangulatePatch(boundary, interior, std::vector<bool>(boundary.size(), false));
    std::vector<int> index(patch.points.size());
    std::vector<int> added;
    for (std::size_t i = 0; i < patch.points.size(); ++i) {
        if (i < loop.size() && (patch.points[i] - boundary[i]).norm() == 0.0) {
            index[i] = loop[i];
            continue;
        }
        index[i] = mesh.vertexCount();
        added.push_back(index[i]);
        const Vec2& p = patch.points[i];
        mesh.vertices.push_back(surface.fromPatch(Vec2(p.x(), flip * p.y())));
    }
    for (const auto& t : patch.triangles)
        mesh.faces.push_back({index[t[0]], index[t[1]], index[t[2]]});
    return added;
}

// Which piece each joint of the part lies in: the piece whose closed
// (patched) surface winds around it most (the generalized winding number).
// A swept cut ends where the stroke was drawn, so which side of the cut
// surface's extension a joint is on says nothing about its piece: the torso
// beside an arm cut off is on both sides of the arm cut's extension. A
// joint that neither piece or both pieces wind around (a tip joint just
// outside the surface; a joint on the cut's patch, which both patched
// pieces may claim) goes by its side of the cut; `pieces` are sorted by
// side.
std::map<JointId, int> jointPieces(const Skeleton& skeleton, const std::array<TriMesh, 2>& meshes,
                                   const CutSurface& surface) {
    // Each piece's winding numbers on its own thread. A patched piece whose
    // directed edges cancel winds an integer number of times around a joint
    // off it, which a ray's crossings give exactly (mesh/ExactWinding.h); the
    // sum of solid angles (an atan2 per face per joint, a quarter of a cut
    // by perf) approximates that integer to far better than the 0.5 the
    // decision below needs, so both decide alike. It remains for a joint the
    // ray cannot decide (on a face, or the ray along an edge) and for a
    // piece that does not bound. All joints' rays go through the faces
    // once (each face meets the rays within its box only).
    const std::vector<Joint>& joints = skeleton.joints();
    std::array<std::vector<double>, 2> winding;
    std::vector<Vec3> positions;
    for (const Joint& joint : joints)
        positions.push_back(joint.position);
    parallelFor(2, 2, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const std::vector<std::optional<int>> exact =
                directedEdgesCancel(meshes[k]) ? exactWindingNumbers(meshes[k], positions)
                                               : std::vector<std::optional<int>>(positions.size());
            for (std::size_t j = 0; j < positions.size(); ++j)
                winding[k].push_back(exact[j] ? double(*exact[j])
                                              : windingNumber(meshes[k], positions[j]));
        }
    });
    std::map<JointId, int> pieceOf;
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const Joint& joint = joints[j];
        const double w0 = winding[0][j];
        const double w1 = winding[1][j];
        if ((w0 >= 0.5) == (w1 >= 0.5))
            pieceOf[joint.id] = surface.side(joint.position) < 0.0 ? 0 : 1;
        else
            pieceOf[joint.id] = w0 >= w1 ? 0 : 1;
    }
    return pieceOf;
}

// The skeleton with every bone whose joints lie in different pieces split
// where it crosses the cut surface, and each joint's piece (-1: both, a new
// joint at a crossing or a joint on the cut). `tailHalf` maps a split bone
// to its new half on its tail's side. A crossing within `minimum` of one of
// the bone's joints snaps to that joint (rig/ShortBones.h): the bone is not
// split, the joint belongs to both pieces, and `snapped` keeps, per side of
// the cut surface at the joint (a piece's MeshPiece::side), the shortest
// bone a split would have left there: a tip joint may lie outside both
// patched pieces, so its piece cannot tell.
struct SplitSkeleton {
    Skeleton skeleton;
    std::map<BoneId, BoneId> tailHalf;
    std::map<int, double> snapped;  // side (-1, 1) -> shortest bone not made
};

SplitSkeleton splitCrossingBones(const Skeleton& skeleton, const CutSurface& surface,
                                 std::map<JointId, int>& pieceOf, double minimum) {
    SplitSkeleton out{skeleton, {}, {}};
    auto snap = [&](JointId joint, double length) {
        const int side = surface.side(skeleton.joint(joint).position) < 0.0 ? -1 : 1;
        auto [at, inserted] = out.snapped.emplace(side, length);
        if (!inserted)
            at->second = std::min(at->second, length);
        pieceOf[joint] = -1;
    };
    for (const Bone& bone : skeleton.bones()) {
        if (pieceOf[bone.head] == pieceOf[bone.tail] || pieceOf[bone.head] < 0 ||
            pieceOf[bone.tail] < 0)
            continue;
        const Vec3 head = skeleton.joint(bone.head).position;
        const Vec3 tail = skeleton.joint(bone.tail).position;
        const double a = surface.side(head);
        const double b = surface.side(tail);
        // Where the bone meets the cut; a bone whose ends read on one side
        // (it passes the cut's end) is split at its middle.
        const Vec3 at = (a < 0.0) != (b < 0.0) ? surface.crossing(head, tail) : 0.5 * (head + tail);
        const double toHead = (at - head).norm();
        const double toTail = (at - tail).norm();
        if (std::min(toHead, toTail) < minimum) {
            if (toHead <= toTail)
                snap(bone.head, toHead);
            else
                snap(bone.tail, toTail);
        } else {
            const JointId middle = out.skeleton.splitBone(bone.id, at);
            pieceOf[middle] = -1;
            for (BoneId id : out.skeleton.bonesAt(middle))
                if (id != bone.id)
                    out.tailHalf[bone.id] = id;
        }
    }
    return out;
}

// The joints of piece `k` and those shared by both pieces.
Skeleton skeletonOfPiece(const Skeleton& split, const std::map<JointId, int>& pieceOf, int k) {
    Skeleton piece = split;
    for (const Joint& joint : split.joints()) {
        const int owner = pieceOf.at(joint.id);
        if (owner >= 0 && owner != k)
            piece.removeJoint(joint.id);
    }
    return piece;
}

// A piece's skeleton can fall apart where the cut took the joint that held
// its limbs together (a star cut near its centre: the arms on one side meet
// only at the centre joint on the other). Each stray component is joined by
// a bone from its joint nearest to the main component, so each piece keeps
// one tree (paper 3.1); joints closer than `minimum` become one instead
// (rig/ShortBones.h).
void joinComponents(Skeleton& skeleton, double minimum) {
    while (true) {
        std::map<JointId, int> component;
        int count = 0;
        for (const Joint& joint : skeleton.joints()) {
            if (component.contains(joint.id))
                continue;
            std::vector<JointId> stack{joint.id};
            component[joint.id] = count;
            while (!stack.empty()) {
                const JointId j = stack.back();
                stack.pop_back();
                for (BoneId b : skeleton.bonesAt(j)) {
                    const Bone& bone = skeleton.bone(b);
                    const JointId other = bone.head == j ? bone.tail : bone.head;
                    if (component.emplace(other, count).second)
                        stack.push_back(other);
                }
            }
            ++count;
        }
        if (count <= 1)
            return;
        // The closest pair between component 0 and any other.
        JointId from = kNoJoint, to = kNoJoint;
        double best = 0.0;
        for (const Joint& a : skeleton.joints())
            for (const Joint& b : skeleton.joints())
                if (component[a.id] == 0 && component[b.id] != 0) {
                    const double d = (a.position - b.position).norm();
                    if (from == kNoJoint || d < best) {
                        from = a.id;
                        to = b.id;
                        best = d;
                    }
                }
        if (best < minimum || best == 0.0)
            skeleton.mergeJoints(from, to);
        else
            skeleton.addBone(from, to);
    }
}

}  // namespace

CutResult cutPart(const Part& part, const CutRequest& request) {
    const auto start = std::chrono::steady_clock::now();
    if (part.skeleton.boneCount() == 0)
        throw Error(MessageId::CutNeedsRiggedPart);
    // Each piece's skeleton is rebuilt as one connected tree.
    requireConnectedSkeleton(part);
    // The request's own checks first: they cost nothing, the part's build a
    // surface.
    if (request.stroke.empty() && (!(request.normal.norm() > 0.0) || !request.normal.allFinite() ||
                                   !request.point.allFinite()))
        throw Error(MessageId::CutNeedsPlane);
    for (const Vec3& p : request.stroke)
        if (!p.allFinite())
            throw Error(MessageId::CutStrokeNotFinite);
    // The split and the patches rely on a closed, oriented surface. The
    // split's surface built directly says the surface is closed, oriented and
    // manifold at every edge and vertex (mesh/CgalClosedSurface.h), which is
    // what validateSolid's topology check finds (mesh/MeshChecks:
    // analyseTopology, 8% of cutPart's samples on the benchmark thread of
    // bench_merge's curved camel cut): then the rest of validateSolid is left
    // (validate(); the bones are checked above). Otherwise validateSolid
    // names the problem, if any.
    std::optional<cgal::SurfaceMesh> closed = cgal::closedSurfaceMesh(part.mesh);
    if (const std::vector<Message> problems =
            closed && part.mesh.faceCount() > 0 ? part.validate() : part.validateSolid();
        !problems.empty())
        throw Error(MessageId::CutPartNotSolid, problems.front());
    const CutSurface surface = request.stroke.empty()
                                   ? CutSurface::plane(request.point, request.normal)
                                   : CutSurface::swept(request.stroke, request.sweep);
    std::vector<MeshPiece> pieces = closed ? splitBySurface(part.mesh, std::move(*closed), surface)
                                           : splitBySurface(part.mesh, surface);
    if (pieces.size() < 2)
        throw Error(MessageId::CutMissesPart);
    if (pieces.size() > 2)
        throw Error(MessageId::CutCrossesTwice, pieces.size());
    std::sort(pieces.begin(), pieces.end(),
              [](const MeshPiece& a, const MeshPiece& b) { return a.side < b.side; });
    if (pieces[0].side == pieces[1].side)
        throw Error(MessageId::CutPiecesOnOneSide);

    // The part's mean edge, measured once: the patches' edge length unless
    // the request gives one, and the shortest bone a piece may keep.
    const double meanEdge = meanEdgeLength(part.mesh);
    const double edge = request.edgeLength > 0.0 ? request.edgeLength : meanEdge;
    const WeightsById& weights = part.weights.perVertex;

    CutResult result;
    // The holes become patches; a smooth cut fairs their interior. The two
    // pieces are independent: one thread each (the first error is rethrown
    // here). A patch's fairing system is kept for its weights below (the
    // same connectivity and, unless some cut vertex has no weight, the same
    // free vertices: one factorisation instead of two).
    std::array<TriMesh, 2> meshes;
    std::array<std::unique_ptr<FairingSystem>, 2> patchFairing;
    parallelFor(2, 2, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            meshes[k] = std::move(pieces[k].mesh);
            std::vector<int>& patch = result.patches[k];
            for (const std::vector<int>& hole : pieces[k].holes) {
                const std::vector<int> added = fillHole(meshes[k], hole, surface, edge);
                patch.insert(patch.end(), added.begin(), added.end());
            }
            if (request.style == CutStyle::Smooth) {
                patchFairing[k] = std::make_unique<FairingSystem>(meshes[k], patch);
                fairPositions(meshes[k], *patchFairing[k]);
            }
        }
    });

    std::map<JointId, int> pieceOf = jointPieces(part.skeleton, meshes, surface);
    const double minimum = minimumBoneLength(meanEdge);
    const SplitSkeleton split = splitCrossingBones(part.skeleton, surface, pieceOf, minimum);
    const std::map<BoneId, BoneId>& tailHalf = split.tailHalf;

    parallelFor(2, 2, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            MeshPiece& piece = pieces[k];
            Part& out = result.pieces[k];
            out.name = part.name;
            out.skeleton = skeletonOfPiece(split.skeleton, pieceOf, k);
            if (out.skeleton.boneCount() == 0) {
                // Its only bone would have been the bit of a bone beyond a
                // snapped crossing: say how short.
                const auto snapped = split.snapped.find(piece.side);
                if (snapped != split.snapped.end())
                    throw Error(MessageId::CutPieceBoneTooShort, shortNumber(snapped->second),
                                shortNumber(minimum));
                throw Error(MessageId::CutPieceWithoutBone);
            }
            joinComponents(out.skeleton, minimum);
            if (!out.skeleton.validate().empty())
                throw Error(MessageId::CutPieceNotOneTree);
            out.skeleton.setRoot(chooseCentralRoot(out.skeleton));
            out.skeleton.reorient();
            out.mesh = std::move(meshes[k]);
            const std::vector<int>& patch = result.patches[k];

            // Weights: the bones this piece kept (a split bone's far half stands
            // in for it), renormalised; the patch filled by least squares.
            auto pieceBone = [&](BoneId id) -> std::optional<BoneId> {
                if (out.skeleton.hasBone(id))
                    return id;
                auto half = tailHalf.find(id);
                if (half != tailHalf.end() && out.skeleton.hasBone(half->second))
                    return half->second;
                return std::nullopt;
            };
            WeightsById pieceWeights(out.mesh.vertexCount());
            // A kept vertex reads its list in place; a new one's is built in
            // one buffer for all.
            std::vector<std::pair<BoneId, double>> blended;
            for (int v = 0; v < static_cast<int>(piece.sources.size()); ++v) {
                const VertexSource& s = piece.sources[v];
                const std::vector<std::pair<BoneId, double>>* list = &blended;
                blended.clear();
                if (s.kind == VertexSource::Kind::Vertex) {
                    list = &weights[s.index];
                } else if (s.kind == VertexSource::Kind::Triangle) {
                    const auto& face = part.mesh.faces[s.index];
                    for (int c = 0; c < 3; ++c)
                        for (const auto& [bone, w] : weights[face[c]])
                            blended.emplace_back(bone, s.barycentric[c] * w);
                }
                pieceWeights[v].reserve(list->size());
                for (const auto& [bone, w] : *list)
                    if (auto id = pieceBone(bone))
                        pieceWeights[v].emplace_back(*id, w);
                normaliseWeights(pieceWeights[v]);
            }
            std::vector<int> unknown = patch;
            for (int v = 0; v < static_cast<int>(piece.sources.size()); ++v)
                if (pieceWeights[v].empty())
                    unknown.push_back(v);
            std::vector<BoneId> bones;
            for (const Bone& bone : out.skeleton.bones())
                bones.push_back(bone.id);
            std::sort(bones.begin(), bones.end());
            Eigen::MatrixXd values = Eigen::MatrixXd::Zero(out.mesh.vertexCount(), bones.size());
            for (int v = 0; v < out.mesh.vertexCount(); ++v)
                for (const auto& [bone, w] : pieceWeights[v])
                    values(v, std::lower_bound(bones.begin(), bones.end(), bone) - bones.begin()) =
                        w;
            const bool solved = patchFairing[k] && unknown == patchFairing[k]->free()
                                    ? patchFairing[k]->solve(values)
                                    : fairValues(out.mesh, unknown, values);
            if (!solved)
                throw Error(MessageId::CutPatchWeightsUnsolved);
            for (int v : unknown) {
                pieceWeights[v].clear();
                for (std::size_t b = 0; b < bones.size(); ++b)
                    if (values(v, b) > 1e-6)
                        pieceWeights[v].emplace_back(bones[b], values(v, b));
                normaliseWeights(pieceWeights[v]);
                if (pieceWeights[v].empty())
                    pieceWeights[v].emplace_back(bones.front(), 1.0);
            }
            out.weights.perVertex = std::move(pieceWeights);
            carryBoneAnnotations(part, out);
            result.sources[k] = std::move(piece.sources);
            result.sources[k].resize(out.mesh.vertexCount());  // patch vertices: New
            const std::vector<Message> problems = out.validateSolid();
            if (!problems.empty())
                throw Error(MessageId::CutInvalidPiece, problems.front());
            result.volumes[k] = signedVolume(out.mesh);
        }
    });
    result.milliseconds = millisecondsSince(start);
    return result;
}

}  // namespace rigmesh
