#include "FuzzChecks.h"

#include <cmath>

#include "base/MessageText.h"
#include "mesh/MeshChecks.h"
#include "model/DocumentFile.h"
#include "pose/Skinning.h"

namespace rigmesh::fuzz {

std::string partProblem(const Part& part, Topology topology) {
    const TriMesh& mesh = part.mesh;
    for (const Vec3& v : mesh.vertices)
        if (!v.allFinite())
            return "a mesh vertex is not finite";
    for (const auto& face : mesh.faces)
        for (const int index : face)
            if (index < 0 || index >= mesh.vertexCount())
                return "a face refers to a missing vertex";
    const bool rigged = part.skeleton.jointCount() > 0;
    if (rigged && topology == Topology::ClosedManifold) {
        const MeshReport report = analyseMesh(mesh, false);
        if (!report.isClosed() || !report.isManifold())
            return "the mesh is not a closed manifold (" + std::to_string(report.boundaryEdges) +
                   " boundary edges, " + std::to_string(report.nonManifoldEdges) +
                   " non-manifold edges)";
    }
    if (rigged) {
        if (const auto problems = part.skeleton.validate(); !problems.empty())
            return "the skeleton is not a tree: " + englishText(problems.front());
        for (const Joint& joint : part.skeleton.joints())
            if (!joint.position.allFinite())
                return "a joint position is not finite";
        if (static_cast<int>(part.weights.perVertex.size()) != mesh.vertexCount())
            return "the weights do not have one list per vertex";
    }
    for (const auto& list : part.weights.perVertex) {
        double sum = 0;
        for (const auto& [bone, weight] : list) {
            if (!part.skeleton.hasBone(bone))
                return "a weight refers to a missing bone";
            if (!std::isfinite(weight) || weight < 0)
                return "a weight is negative or not finite";
            sum += weight;
        }
        if (rigged && std::abs(sum - 1.0) > 1e-6)
            return "a vertex's weights sum to " + std::to_string(sum);
    }
    return {};
}

std::string messageProblem(const std::string& message) {
    if (message.empty())
        return "rejected without a message";
    if (message.find('\n') != std::string::npos)
        return "a message of more than one line: " + message;
    if (oneLine(message, kMaxMessageCharacters) != message)
        return "a message longer than " + std::to_string(kMaxMessageCharacters) +
               " characters: " + message.substr(0, 300);
    if (message.find("json.exception") != std::string::npos)
        return "a message with the JSON library's own text: " + message;
    return {};
}

// Every key of every clip at 0 s or later (glTF refuses negative times).
std::string clipProblem(const model::PartNode& node) {
    std::vector<const Clip*> clips{&node.clip};
    for (const Clip& other : node.otherClips)
        clips.push_back(&other);
    for (const Clip* clip : clips)
        for (const double time : clip->keyTimes())
            if (!(time >= 0.0))
                return "a key at " + std::to_string(time) + " s, before 0 s";
    return {};
}

std::string documentProblem(const model::Document& document, Topology topology) {
    for (const model::PartNode& node : document.parts()) {
        if (!node.part)
            return "a part has no geometry";
        // A surface made here is closed whatever the document holds.
        const Topology expected =
            node.part->surfaceFromFile ? Topology::Any : Topology::ClosedManifold;
        if (std::string problem =
                partProblem(*node.part, topology == Topology::Any ? topology : expected);
            !problem.empty())
            return "part " + std::to_string(node.id) + ": " + problem;
        if (std::string problem = clipProblem(node); !problem.empty())
            return "part " + std::to_string(node.id) + ": " + problem;
        if (node.part->skeleton.jointCount() == 0)
            continue;
        for (const Vec3& v : posePart(*node.part, node.pose).mesh.vertices)
            if (!v.allFinite())
                return "part " + std::to_string(node.id) + " poses to a non-finite vertex";
        for (const double time : node.clip.keyTimes())
            for (const auto& [joint, q] : node.clip.evaluate(time).rotations)
                if (!q.coeffs().allFinite())
                    return "part " + std::to_string(node.id) +
                           "'s clip gives a non-finite rotation";
    }
    // What the studio saves, it must open again, unchanged.
    const QByteArray bytes = model::DocumentFile::toBytes(document);
    try {
        if (model::DocumentFile::toBytes(model::Document(model::DocumentFile::fromBytes(bytes))) !=
            bytes)
            return "the document does not load back to the same bytes";
    } catch (const model::DocumentFileError& e) {
        return std::string("the saved document does not load: ") + e.what();
    }
    return {};
}

}  // namespace rigmesh::fuzz
