// Part::validate(): the invariants every part keeps (see Part.h).
#include <cmath>
#include <set>
#include <string>

#include "mesh/MeshTopologyCheck.h"
#include "part/Part.h"

namespace rigmesh {
namespace {

constexpr std::size_t kMaxProblems = 12;
// A vertex's weights sum to 1 within this (they are normalised in double).
constexpr double kWeightSumTolerance = 1e-6;

class Problems {
  public:
    template <class... Args>
    void add(MessageId id, const Args&... args) {
        add(Message{id, {messageArgument(args)...}});
    }
    void add(Message problem) {
        if (list_.size() < kMaxProblems)
            list_.push_back(std::move(problem));
    }
    bool full() const { return list_.size() >= kMaxProblems; }
    std::vector<Message> take() { return std::move(list_); }

  private:
    std::vector<Message> list_;
};

void checkMesh(const TriMesh& mesh, Problems& problems) {
    for (int v = 0; v < mesh.vertexCount() && !problems.full(); ++v)
        if (!mesh.vertices[v].allFinite())
            problems.add(MessageId::PartVertexNotFinite, v);
    const int n = mesh.vertexCount();
    for (int f = 0; f < mesh.faceCount() && !problems.full(); ++f) {
        const auto& face = mesh.faces[f];
        if (face[0] < 0 || face[0] >= n || face[1] < 0 || face[1] >= n || face[2] < 0 ||
            face[2] >= n)
            problems.add(MessageId::PartFaceMissingVertex, f);
        else if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2])
            problems.add(MessageId::PartFaceRepeatsVertex, f);
    }
}

// The words for one kind of per-vertex bone list (skin weights, known
// closest bones).
struct BoneListMessages {
    MessageId count, missingBone, outOfOrder, notPositive, sum;
};

constexpr BoneListMessages kWeightMessages{
    MessageId::PartWeightsCount, MessageId::PartWeightsMissingBone,
    MessageId::PartWeightsOutOfOrder, MessageId::PartWeightsNotPositive, MessageId::PartWeightsSum};
constexpr BoneListMessages kClosestBoneMessages{
    MessageId::PartClosestBonesCount, MessageId::PartClosestBonesMissingBone,
    MessageId::PartClosestBonesOutOfOrder, MessageId::PartClosestBonesNotPositive, MessageId::None};

// A per-vertex list of (bone id, value) pairs: bones the skeleton has, in
// increasing id order, values finite and positive; with `sumsToOne` (the
// skin weights) they also sum to 1.
void checkBoneLists(const std::vector<std::vector<std::pair<BoneId, double>>>& lists,
                    int vertexCount, const Skeleton& skeleton, const BoneListMessages& says,
                    Problems& problems) {
    const bool sumsToOne = says.sum != MessageId::None;
    if (lists.empty())
        return;
    if (static_cast<int>(lists.size()) != vertexCount) {
        problems.add(says.count, lists.size(), vertexCount);
        return;
    }
    for (int v = 0; v < vertexCount && !problems.full(); ++v) {
        double sum = 0.0;
        bool first = true;
        BoneId previous = 0;
        bool ok = true;
        for (const auto& [bone, value] : lists[v]) {
            if (!skeleton.hasBone(bone)) {
                problems.add(says.missingBone, v, bone);
                ok = false;
            } else if (!first && bone <= previous) {
                problems.add(says.outOfOrder, v);
                ok = false;
            } else if (!std::isfinite(value) || value < 0.0 || (sumsToOne && value == 0.0)) {
                problems.add(says.notPositive, v);
                ok = false;
            }
            if (!ok)
                break;
            first = false;
            previous = bone;
            sum += value;
        }
        if (ok && sumsToOne && std::abs(sum - 1.0) > kWeightSumTolerance)
            problems.add(says.sum, v, std::to_string(sum));
    }
}

// The pieces cover the vertices and faces in order, and each piece's faces
// use its own vertices.
void checkMeshPieces(const TriMesh& mesh, const std::vector<PartMeshPiece>& pieces,
                     Problems& problems) {
    if (pieces.empty())
        return;
    int firstVertex = 0, firstFace = 0;
    for (const PartMeshPiece& piece : pieces) {
        if (piece.vertexCount < 0 || piece.faceCount < 0 ||
            piece.vertexCount > mesh.vertexCount() - firstVertex ||
            piece.faceCount > mesh.faceCount() - firstFace) {
            problems.add(MessageId::PartPiecesDoNotFit);
            return;
        }
        for (int f = firstFace; f < firstFace + piece.faceCount; ++f)
            for (int corner : mesh.faces[f])
                if (corner < firstVertex || corner >= firstVertex + piece.vertexCount) {
                    problems.add(MessageId::PartPieceUsesOthersVertex, piece.name);
                    return;
                }
        firstVertex += piece.vertexCount;
        firstFace += piece.faceCount;
    }
    if (firstVertex != mesh.vertexCount() || firstFace != mesh.faceCount())
        problems.add(MessageId::PartPiecesDoNotCover);
}

}  // namespace

std::vector<Message> Part::validate() const {
    Problems problems;
    for (const Vec2& p : outline)
        if (!p.allFinite()) {
            problems.add(MessageId::PartOutlineNotFinite);
            break;
        }
    checkMesh(mesh, problems);
    const int n = mesh.vertexCount();
    if (!origins.empty() && static_cast<int>(origins.size()) != n)
        problems.add(MessageId::PartOriginsNotPerVertex);
    if (!mirror.empty() && static_cast<int>(mirror.size()) != n)
        problems.add(MessageId::PartMirrorNotPerVertex);
    for (int v = 0; v < static_cast<int>(mirror.size()) && v < n; ++v)
        if (mirror[v] < 0 || mirror[v] >= n) {
            problems.add(MessageId::PartMirrorMissingVertex);
            break;
        }

    const int bones = skeleton.boneCount();
    if (skeleton.jointCount() > 0) {
        for (Message& problem : skeleton.validate())
            problems.add(std::move(problem));
        if (bones > 0 && static_cast<int>(weights.perVertex.size()) != n)
            problems.add(MessageId::PartWeightsNotPerVertex);
        else
            checkBoneLists(weights.perVertex, n, skeleton, kWeightMessages, problems);
    } else {
        // An unrigged part (a static import): no bones, no weights.
        if (bones > 0)
            problems.add(MessageId::PartBonesWithoutJoints);
        for (const auto& list : weights.perVertex)
            if (!list.empty()) {
                problems.add(MessageId::PartUnriggedHasWeights);
                break;
            }
    }
    for (BoneId bone : weights.failedBones)
        if (!skeleton.hasBone(bone)) {
            problems.add(MessageId::PartFailedBoneMissing);
            break;
        }
    checkBoneLists(knownClosestBones, n, skeleton, kClosestBoneMessages, problems);
    std::set<std::string> names;
    for (const auto& [bone, name] : boneNames)
        if (!skeleton.hasBone(bone) || name.empty() || !names.insert(name).second) {
            problems.add(MessageId::PartBoneNameInvalid);
            break;
        }
    for (BoneId bone : lockedBones)
        if (!skeleton.hasBone(bone)) {
            problems.add(MessageId::PartLockedBoneMissing, bone);
            break;
        }
    for (const auto& [bone, frame] : boneFrames)
        if (!skeleton.hasBone(bone) || !frame.coeffs().allFinite() ||
            std::abs(frame.squaredNorm() - 1.0) > 1e-6) {
            problems.add(MessageId::PartBoneFrameInvalid);
            break;
        }
    checkMeshPieces(mesh, meshPieces, problems);
    return problems.take();
}

std::vector<Message> Part::validateSolid() const {
    std::vector<Message> problems = validate();
    if (!problems.empty())
        return problems;
    if (skeleton.boneCount() == 0)
        problems.push_back({MessageId::PartHasNoSkeleton, {}});
    // Closed, manifold and oriented are topology: the angles, area and
    // volume analyseMesh also measures are not needed here, and the full
    // analysis only to say what is wrong.
    if (isClosedOrientedManifold(mesh))
        return problems;
    const MeshReport report = analyseMeshTopology(mesh);
    if (!report.isClosed())
        problems.push_back(
            {MessageId::PartSurfaceBoundaryEdges, {std::to_string(report.boundaryEdges)}});
    if (!report.isManifold())
        problems.push_back({MessageId::PartSurfaceNotAManifold, {}});
    if (report.inconsistentlyOrientedEdges > 0)
        problems.push_back({MessageId::PartSurfaceNotOriented, {}});
    return problems;
}

}  // namespace rigmesh
