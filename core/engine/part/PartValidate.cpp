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
    void add(std::string text) {
        if (list_.size() < kMaxProblems)
            list_.push_back(std::move(text));
    }
    bool full() const { return list_.size() >= kMaxProblems; }
    std::vector<std::string> take() { return std::move(list_); }

  private:
    std::vector<std::string> list_;
};

void checkMesh(const TriMesh& mesh, Problems& problems) {
    for (int v = 0; v < mesh.vertexCount() && !problems.full(); ++v)
        if (!mesh.vertices[v].allFinite())
            problems.add("Vertex " + std::to_string(v) + " has a non-finite position.");
    const int n = mesh.vertexCount();
    for (int f = 0; f < mesh.faceCount() && !problems.full(); ++f) {
        const auto& face = mesh.faces[f];
        if (face[0] < 0 || face[0] >= n || face[1] < 0 || face[1] >= n || face[2] < 0 ||
            face[2] >= n)
            problems.add("Face " + std::to_string(f) + " refers to a missing vertex.");
        else if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2])
            problems.add("Face " + std::to_string(f) + " repeats a vertex.");
    }
}

// A per-vertex list of (bone id, value) pairs: bones the skeleton has, in
// increasing id order, values finite and positive.
void checkBoneLists(const std::vector<std::vector<std::pair<BoneId, double>>>& lists,
                    int vertexCount, const Skeleton& skeleton, const std::string& what,
                    bool sumsToOne, Problems& problems) {
    if (lists.empty())
        return;
    if (static_cast<int>(lists.size()) != vertexCount) {
        problems.add("The " + what + " have " + std::to_string(lists.size()) + " entries for " +
                     std::to_string(vertexCount) + " vertices.");
        return;
    }
    for (int v = 0; v < vertexCount && !problems.full(); ++v) {
        // Spelled out only for a problem: a string per vertex was most of a
        // valid part's check.
        auto where = [&] { return "The " + what + " of vertex " + std::to_string(v); };
        double sum = 0.0;
        bool first = true;
        BoneId previous = 0;
        bool ok = true;
        for (const auto& [bone, value] : lists[v]) {
            if (!skeleton.hasBone(bone)) {
                problems.add(where() + " name bone " + std::to_string(bone) +
                             ", which the skeleton does not have.");
                ok = false;
            } else if (!first && bone <= previous) {
                problems.add(where() + " are not in bone order.");
                ok = false;
            } else if (!std::isfinite(value) || value < 0.0 || (sumsToOne && value == 0.0)) {
                problems.add(where() + " hold a value that is not finite and positive.");
                ok = false;
            }
            if (!ok)
                break;
            first = false;
            previous = bone;
            sum += value;
        }
        if (ok && sumsToOne && std::abs(sum - 1.0) > kWeightSumTolerance)
            problems.add(where() + " sum to " + std::to_string(sum) + ", not 1.");
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
            problems.add("The mesh pieces do not fit the mesh.");
            return;
        }
        for (int f = firstFace; f < firstFace + piece.faceCount; ++f)
            for (int corner : mesh.faces[f])
                if (corner < firstVertex || corner >= firstVertex + piece.vertexCount) {
                    problems.add("Mesh piece '" + piece.name + "' uses another piece's vertex.");
                    return;
                }
        firstVertex += piece.vertexCount;
        firstFace += piece.faceCount;
    }
    if (firstVertex != mesh.vertexCount() || firstFace != mesh.faceCount())
        problems.add("The mesh pieces do not cover the mesh.");
}

}  // namespace

std::vector<std::string> Part::validate() const {
    Problems problems;
    for (const Vec2& p : outline)
        if (!p.allFinite()) {
            problems.add("The outline has a non-finite point.");
            break;
        }
    checkMesh(mesh, problems);
    const int n = mesh.vertexCount();
    if (!origins.empty() && static_cast<int>(origins.size()) != n)
        problems.add("The vertex origins do not have one entry per vertex.");
    if (!mirror.empty() && static_cast<int>(mirror.size()) != n)
        problems.add("The mirror map does not have one entry per vertex.");
    for (int v = 0; v < static_cast<int>(mirror.size()) && v < n; ++v)
        if (mirror[v] < 0 || mirror[v] >= n) {
            problems.add("The mirror map refers to a missing vertex.");
            break;
        }

    const int bones = skeleton.boneCount();
    if (skeleton.jointCount() > 0) {
        for (std::string& problem : skeleton.validate())
            problems.add(std::move(problem));
        if (bones > 0 && static_cast<int>(weights.perVertex.size()) != n)
            problems.add("The skin weights do not have one entry per vertex.");
        else
            checkBoneLists(weights.perVertex, n, skeleton, "skin weights", true, problems);
    } else {
        // An unrigged part (a static import): no bones, no weights.
        if (bones > 0)
            problems.add("The skeleton has bones but no joints.");
        for (const auto& list : weights.perVertex)
            if (!list.empty()) {
                problems.add("An unrigged part has skin weights.");
                break;
            }
    }
    for (BoneId bone : weights.failedBones)
        if (!skeleton.hasBone(bone)) {
            problems.add("The failed bones name a missing bone.");
            break;
        }
    checkBoneLists(knownClosestBones, n, skeleton, "known closest bones", false, problems);
    std::set<std::string> names;
    for (const auto& [bone, name] : boneNames)
        if (!skeleton.hasBone(bone) || name.empty() || !names.insert(name).second) {
            problems.add("A bone name is empty, repeated or names a missing bone.");
            break;
        }
    for (BoneId bone : lockedBones)
        if (!skeleton.hasBone(bone)) {
            problems.add("Bone " + std::to_string(bone) +
                         " is locked but the skeleton has no such bone.");
            break;
        }
    for (const auto& [bone, frame] : boneFrames)
        if (!skeleton.hasBone(bone) || !frame.coeffs().allFinite() ||
            std::abs(frame.squaredNorm() - 1.0) > 1e-6) {
            problems.add("A bone frame is not a unit rotation or names a missing bone.");
            break;
        }
    checkMeshPieces(mesh, meshPieces, problems);
    return problems.take();
}

std::vector<std::string> Part::validateSolid() const {
    std::vector<std::string> problems = validate();
    if (!problems.empty())
        return problems;
    if (skeleton.boneCount() == 0)
        problems.push_back("The part has no skeleton.");
    // Closed, manifold and oriented are topology: the angles, area and
    // volume analyseMesh also measures are not needed here.
    const MeshReport report = analyseMeshTopology(mesh);
    if (!report.isClosed())
        problems.push_back("The surface has " + std::to_string(report.boundaryEdges) +
                           " boundary edges.");
    if (!report.isManifold())
        problems.push_back("The surface is not a manifold.");
    if (report.inconsistentlyOrientedEdges > 0)
        problems.push_back("The surface is not consistently oriented.");
    return problems;
}

}  // namespace rigmesh
