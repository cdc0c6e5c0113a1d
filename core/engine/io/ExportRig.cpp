#include "io/ExportRig.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>

#include "autorig/SurfaceProbe.h"
#include "base/Error.h"
#include "mesh/MeshChecks.h"
#include "pose/PoseHierarchy.h"

namespace rigmesh {
namespace {

// The shortest rotation taking `axis` onto `along` (no roll). Opposite
// vectors turn half a turn about an axis perpendicular to both.
Eigen::Quaterniond boneFrame(const Vec3& axis, const Vec3& along) {
    if (!(along.norm() > 0))
        return Eigen::Quaterniond::Identity();
    const Vec3 direction = along.normalized();
    if (axis.dot(direction) < -1.0 + 1e-12) {
        const Vec3 turn = axis.unitOrthogonal();
        return Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, turn));
    }
    return Eigen::Quaterniond::FromTwoVectors(axis, direction).normalized();
}

// A kept frame whose +Y is farther than this (radians) off its bone is
// turned onto it: one degree, far above the single precision of the frames
// Blender writes along its bones.
constexpr double kKeptFrameOffBone = M_PI / 180.0;

// The axis of `frame` (+-X, +-Y or +-Z, in global coordinates) nearest the
// direction `along`.
Vec3 nearestFrameAxis(const Eigen::Quaterniond& frame, const Vec3& along) {
    const Vec3 local = frame.conjugate() * along;
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(local[k]) > std::abs(local[axis]))
            axis = k;
    Vec3 unit = Vec3::Zero();
    unit[axis] = local[axis] < 0 ? -1.0 : 1.0;
    return frame * unit;
}

// Leaf tails on the surface nearer than this (times the part's size) count
// as on it: a plane cut's vertices lie within 1e-6 of the size of its plane
// (CutPartTest), and ray-cast parity cannot tell a point there inside.
constexpr double kOnSurface = 1e-6;
// How far inside Blender is shown such a tail (times the part's size): ten
// times the step check_tails_inside_in_blender.py takes past a hit, a
// thousand times single precision, far below what a rigger sees.
constexpr double kPullInside = 1e-4;

// Shows Blender every leaf tail that lies on the part's surface (a cut's
// new joint on the flat cap, docs/CUTTING.md) a little inside instead,
// along the bone towards its head (at most a tenth of the bone). The model
// keeps the joint on the cut, where both pieces' copies meet so that the
// pieces snap back together (CutThenMerge in tests/engine/cut/CutPartTest.cpp).
// `partTails`: per node, the tail in the part's own coordinates.
void pullTailsOffSurface(ExportRig& rig, const Part& part, const std::vector<Vec3>& partTails) {
    const bool anyLeaf = std::any_of(rig.nodes.begin(), rig.nodes.end(),
                                     [](const ExportBoneNode& node) { return node.leaf; });
    if (!anyLeaf || part.mesh.faces.empty())
        return;
    const double size = boundingBox(part.mesh).diagonal().norm();
    const SurfaceProbe surface(part.mesh);
    for (std::size_t i = 0; i < rig.nodes.size(); ++i) {
        ExportBoneNode& node = rig.nodes[i];
        const Vec3 along = node.tail - node.head;
        if (!node.leaf || !(along.norm() > 0) || surface.distance(partTails[i]) > kOnSurface * size)
            continue;
        const double pull = std::min(kPullInside * size * rig.unitScale, 0.1 * along.norm());
        node.shownTail = node.tail - pull * along.normalized();
    }
}

}  // namespace

std::string sanitizedName(const std::string& name) {
    std::string out;
    for (unsigned char c : name)
        out += std::isalnum(c) ? static_cast<char>(c) : '_';
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0])))
        out = "part_" + out;
    return out;
}

ExportRig makeExportRig(const Part& part, const std::string& partName,
                        const Eigen::Affine3d& placement, double unitScale, BoneAxes axes) {
    const Skeleton& skeleton = part.skeleton;
    if (skeleton.jointCount() == 0 || !skeleton.hasJoint(skeleton.root()))
        throw Error(MessageId::ExportRigNoSkeleton, partName);
    const PoseHierarchy hierarchy(skeleton);
    ExportRig rig;
    rig.placementRotation = Eigen::Quaterniond(placement.rotation()).normalized();
    rig.unitScale = unitScale;
    rig.nodeOfBone.assign(skeleton.boneCount(), -1);
    auto place = [&](const Vec3& x) -> Vec3 { return unitScale * (placement * x); };

    // The bones whose frame joint is each joint, then breadth first from the
    // root, a chain's bones after the bone it hangs from.
    std::vector<std::vector<int>> bonesFrom(hierarchy.jointCount());
    for (int b = 0; b < hierarchy.boneCount(); ++b)
        if (hierarchy.reachable(hierarchy.boneHeadJoint(b)) &&
            hierarchy.boneRotationJoint(b) == hierarchy.boneTailJoint(b))
            bonesFrom[hierarchy.boneHeadJoint(b)].push_back(b);
    struct Queued {
        int bone, parent;
        std::vector<JointId> turnedBy;
    };
    std::deque<Queued> queue;
    std::vector<Vec3> partTails;  // per node
    const JointId root = hierarchy.jointId(hierarchy.root());
    for (int b : bonesFrom[hierarchy.root()])
        queue.push_back({b, -1, {root}});
    for (int chain : hierarchy.children(hierarchy.root()))
        if (hierarchy.attached(chain))
            for (int b : bonesFrom[chain])
                queue.push_back({b, -1, {root, hierarchy.jointId(chain)}});
    while (!queue.empty()) {
        const auto [b, parent, turnedBy] = queue.front();
        queue.pop_front();
        const int frame = hierarchy.boneHeadJoint(b), end = hierarchy.boneTailJoint(b);
        ExportBoneNode node;
        node.bone = b;
        node.parent = parent;
        node.headJoint = hierarchy.jointId(frame);
        node.tailJoint = hierarchy.jointId(end);
        node.turnedBy = turnedBy;
        node.connected = parent >= 0 && !hierarchy.attached(frame);
        if (parent < 0) {
            node.rootJoint = root;
            node.rootPosition = place(hierarchy.restPosition(hierarchy.root()));
        }
        const BoneId id = skeleton.bones()[b].id;
        const auto kept = part.boneNames.find(id);
        // A kept name goes out as it is ("Bone.001", "Bip01 L Thigh"): glTF,
        // FBX and COLLADA (as Assimp writes and reads them) carry any name,
        // and an importer matching bones by name needs it unchanged.
        node.name =
            kept != part.boneNames.end() ? kept->second : partName + "_bone" + std::to_string(id);
        node.head = place(hierarchy.restPosition(frame));
        node.tail = place(hierarchy.restPosition(end));
        node.shownTail = node.tail;
        std::vector<int> chains;  // attached chain roots hanging from this bone
        for (int child : hierarchy.children(end))
            if (hierarchy.attached(child))
                chains.push_back(child);
        node.leaf = bonesFrom[end].empty() &&
                    std::none_of(chains.begin(), chains.end(),
                                 [&](int chain) { return !bonesFrom[chain].empty(); });
        if (const auto keptFrame = part.boneFrames.find(id); keptFrame != part.boneFrames.end()) {
            node.restFrame = (rig.placementRotation * keptFrame->second).normalized();
            // A frame kept from a file whose bones run along another axis
            // (DirectX's .x) is turned onto the bone by the shortest turn, which
            // keeps its roll: Blender's FBX importer lays every bone along its
            // node's +Y. Frames Blender wrote (+Y along the bone) stay as read.
            // Blender's glTF importer points a bone at its child bones snapped
            // to the nearest axis of its frame (docs/EXCHANGE.md rule 22), so
            // in glTF a frame is turned only where the bone's children all
            // start at its tail (a leaf's end bone does) and no axis of the
            // frame runs within a degree of the bone: its nearest axis is
            // turned onto the bone (rule 27).
            const Vec3 along = node.tail - node.head;
            const bool childrenAtTail = std::all_of(chains.begin(), chains.end(), [&](int chain) {
                return bonesFrom[chain].empty() ||
                       hierarchy.restPosition(chain) == hierarchy.restPosition(end);
            });
            const Vec3 boneAxis = axes == BoneAxes::PlusY ? Vec3(node.restFrame * Vec3::UnitY())
                                                          : nearestFrameAxis(node.restFrame, along);
            const bool turn = axes == BoneAxes::PlusY || childrenAtTail;
            if (turn && along.norm() > 0 &&
                boneAxis.dot(along.normalized()) < std::cos(kKeptFrameOffBone))
                node.restFrame = (boneFrame(boneAxis, along) * node.restFrame).normalized();
        } else {
            const bool minusZ = axes == BoneAxes::GltfRootLeavesMinusZ && parent < 0 && node.leaf;
            node.restFrame = boneFrame(minusZ ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitY()),
                                       node.tail - node.head);
        }
        if (parent < 0) {
            node.restTranslation = node.head;
            node.restRotation = node.restFrame;
        } else {
            const ExportBoneNode& up = rig.nodes[static_cast<std::size_t>(parent)];
            node.restTranslation = up.restFrame.conjugate() * (node.head - up.head);
            node.restRotation = (up.restFrame.conjugate() * node.restFrame).normalized();
        }
        const int index = static_cast<int>(rig.nodes.size());
        rig.nodeOfBone[b] = index;
        rig.nodes.push_back(node);
        partTails.push_back(hierarchy.restPosition(end));
        for (int child : bonesFrom[end])
            queue.push_back({child, index, {}});
        for (int chain : chains)
            for (int child : bonesFrom[chain])
                queue.push_back({child, index, {hierarchy.jointId(chain)}});
    }
    pullTailsOffSurface(rig, part, partTails);
    return rig;
}

Eigen::Affine3d ExportBoneNode::inverseBind() const {
    Eigen::Affine3d bind = Eigen::Affine3d::Identity();
    bind.translate(head);
    bind.rotate(restFrame);
    return bind.inverse(Eigen::Isometry);
}

Vec3 ExportRig::localTranslation(int node, const Pose& pose) const {
    const ExportBoneNode& n = nodes[node];
    if (n.parent >= 0)
        return n.restTranslation;
    // Under the Armature: where the root's transform takes the head.
    const Eigen::Quaterniond rootTurn =
        placementRotation * pose.rotation(n.rootJoint).normalized() * placementRotation.conjugate();
    return n.restTranslation + unitScale * (placementRotation * pose.rootTranslation) +
           (rootTurn * (n.head - n.rootPosition) - (n.head - n.rootPosition));
}

Eigen::Quaterniond ExportRig::localRotation(int node, const Pose& pose) const {
    const ExportBoneNode& n = nodes[static_cast<std::size_t>(node)];
    // The bone's own rotation after the root's (under the Armature) and its
    // chain root's (a disconnected bone).
    Eigen::Quaterniond q = pose.rotation(n.tailJoint).normalized();
    for (auto joint = n.turnedBy.rbegin(); joint != n.turnedBy.rend(); ++joint)
        q = (pose.rotation(*joint).normalized() * q).normalized();
    const Eigen::Quaterniond axisAligned = placementRotation * q * placementRotation.conjugate();
    const Eigen::Quaterniond parentFrame =
        n.parent < 0 ? Eigen::Quaterniond::Identity()
                     : nodes[static_cast<std::size_t>(n.parent)].restFrame;
    return (parentFrame.conjugate() * axisAligned * n.restFrame).normalized();
}

ExportBoneNode endBoneOf(const ExportBoneNode& leaf) {
    ExportBoneNode end;
    end.name = leaf.name + "_end";
    end.headJoint = end.tailJoint = leaf.tailJoint;
    end.connected = true;  // its head is the leaf's tail
    end.head = leaf.shownTail;
    end.tail = leaf.head;
    end.shownTail = end.tail;
    end.leaf = true;
    // Half a turn about an axis across both the frame's +Y and the leaf (in
    // the leaf's frame): both then run backwards, the bone axis Blender's FBX
    // and COLLADA importers read (+Y) and the direction its glTF importer
    // snaps to the nearest frame axis (BoneAxes). Generated frames have the
    // leaf on +Y or -Z: the turn is about +X, and the end keeps the leaf's X
    // axis (its roll).
    const Vec3 along = leaf.restFrame.conjugate() * (leaf.shownTail - leaf.head);
    Vec3 across = along.cross(Vec3::UnitY());
    across = across.norm() > 1e-9 * along.norm() && across.norm() > 0 ? across.normalized()
                                                                      : Vec3(Vec3::UnitX());
    end.restTranslation = along;
    end.restRotation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, across));
    end.restFrame = (leaf.restFrame * end.restRotation).normalized();
    return end;
}

double ExportBoneNode::roll() const {
    const Vec3 along = tail - head;
    if (!(along.norm() > 0))
        return 0.0;
    const Eigen::Quaterniond plain = boneFrame(Vec3::UnitY(), along);
    const Vec3 axis = along.normalized();
    const Vec3 from = plain * Vec3::UnitX(), to = restFrame * Vec3::UnitX();
    return std::atan2(axis.dot(from.cross(to)), from.dot(to));
}

}  // namespace rigmesh
