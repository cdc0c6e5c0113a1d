#include "rig/SkeletonFromRegions.h"

#include <map>

#include "base/Error.h"
#include "rig/DouglasPeucker.h"

namespace rigmesh {
namespace {

Vec3 onSketchPlane(const Vec2& p) {
    return Vec3(p.x(), p.y(), 0.0);
}

double meanRadius(const CylinderSections& cylinder) {
    double sum = 0.0;
    for (const auto& s : cylinder.sections)
        sum += s.radius();
    return sum / static_cast<double>(cylinder.sections.size());
}

// The sections CDP looks at: the body's only. A cap's shrinking width would
// look like a change of thickness and give a short bone at every tip.
std::vector<int> bodySections(const CylinderSections& cylinder) {
    std::vector<int> body;
    for (int s = 0; s < static_cast<int>(cylinder.sections.size()); ++s)
        if (!cylinder.sections[s].inCap)
            body.push_back(s);
    if (body.empty())
        body.push_back(static_cast<int>(cylinder.sections.size()) / 2);
    return body;
}

// The end joints move out to the middle of each cap, so the end bones reach
// into the rounded tips while staying inside them.
void extendIntoCaps(const CylinderSections& cylinder, std::vector<int>& kept) {
    const int last = static_cast<int>(cylinder.sections.size()) - 1;
    if (kept.size() < 2)
        return;
    if (cylinder.sections.front().inCap)
        kept.front() = kept.front() / 2;
    if (cylinder.sections.back().inCap)
        kept.back() = (kept.back() + last + 1) / 2;
}

// Step 1: joints along a cylinder's axis from (C)DP, as section indices.
std::vector<int> simplifyAxis(const CylinderSections& cylinder, const SkeletonOptions& options) {
    const std::vector<int> sections = bodySections(cylinder);
    if (sections.size() < 2) {
        // A body of one section: one bone from cap to cap, if there are caps.
        std::vector<int> ends{sections.front(), sections.front()};
        extendIntoCaps(cylinder, ends);
        if (ends.front() == ends.back())
            return {ends.front()};
        return ends;
    }
    std::vector<AxisSample> samples;
    for (int index : sections) {
        const CrossSection& s = cylinder.sections[index];
        samples.push_back({s.centre(), s.left, s.right});
    }
    const double threshold = options.relativeThreshold * meanRadius(cylinder);
    std::vector<int> kept = options.cylindrical ? cylindricalDouglasPeucker(samples, threshold)
                                                : douglasPeucker(samples, threshold);
    for (int& k : kept)
        k = sections[k];
    // An abrupt change of thickness splits on both sides of the step: merge
    // interior joints closer than the minimum bone length into one.
    const double minimumBone = options.relativeMinimumBone * meanRadius(cylinder);
    auto axisGap = [&](int a, int b) {
        return cylinder.axisPosition[b] - cylinder.axisPosition[a];
    };
    std::vector<int> merged{kept.front()};
    for (std::size_t i = 1; i + 1 < kept.size(); ++i) {
        if (axisGap(merged.back(), kept[i]) >= minimumBone) {
            merged.push_back(kept[i]);
        } else if (merged.size() > 1) {
            merged.back() = (merged.back() + kept[i]) / 2;
        }
    }
    if (kept.size() > 1) {
        if (merged.size() > 1 && axisGap(merged.back(), kept.back()) < minimumBone)
            merged.pop_back();
        merged.push_back(kept.back());
    }
    extendIntoCaps(cylinder, merged);
    return merged;
}

struct ConnectingBone {
    BoneId bone;
    double thickness;       // of the region it lies in
    bool betweenJunctions;  // else from a junction to a cylinder's end
};

}  // namespace

PartSkeleton buildSkeleton(const Decomposition& decomposition,
                           const std::vector<CylinderSections>& cylinders,
                           const SkeletonOptions& options) {
    PartSkeleton result;
    Skeleton& skeleton = result.skeleton;
    std::vector<JointId> firstJoint(cylinders.size()), lastJoint(cylinders.size());

    for (std::size_t c = 0; c < cylinders.size(); ++c) {
        std::vector<int> kept = simplifyAxis(cylinders[c], options);
        std::vector<JointId> joints;
        for (int s : kept)
            joints.push_back(skeleton.addJoint(onSketchPlane(cylinders[c].sections[s].centre())));
        std::vector<BoneId> bones;
        for (std::size_t m = 1; m < joints.size(); ++m)
            bones.push_back(skeleton.addBone(joints[m - 1], joints[m]));
        firstJoint[c] = joints.front();
        lastJoint[c] = joints.back();
        result.jointSections.push_back(std::move(kept));
        result.cylinderBones.push_back(std::move(bones));
    }

    // Step 2: junction joints and the bones across their sides (Fig. 6a).
    std::vector<ConnectingBone> connectingBones;
    std::vector<double> thickness(decomposition.connecting.size(), 0.0);
    std::vector<int> portCount(decomposition.connecting.size(), 0);
    for (std::size_t c = 0; c < cylinders.size(); ++c) {
        const CylinderRegion& region = decomposition.cylinders[c];
        if (region.startConnecting >= 0) {
            thickness[region.startConnecting] += cylinders[c].sections.front().radius();
            ++portCount[region.startConnecting];
        }
        if (region.endConnecting >= 0) {
            thickness[region.endConnecting] += cylinders[c].sections.back().radius();
            ++portCount[region.endConnecting];
        }
    }
    std::map<int, JointId> junctionJoint;
    for (std::size_t r = 0; r < decomposition.connecting.size(); ++r) {
        const ConnectingRegion& region = decomposition.connecting[r];
        if (portCount[r] > 0)
            thickness[r] /= portCount[r];
        for (int t : region.junctions)
            junctionJoint[t] = skeleton.addJoint(onSketchPlane(decomposition.axis.centroid(t)));
        for (const auto& link : region.junctionLinks)
            connectingBones.push_back(
                {skeleton.addBone(junctionJoint.at(link[0]), junctionJoint.at(link[1])),
                 thickness[r], true});
    }
    for (std::size_t c = 0; c < cylinders.size(); ++c) {
        const CylinderRegion& region = decomposition.cylinders[c];
        if (region.startJunction >= 0)
            connectingBones.push_back(
                {skeleton.addBone(junctionJoint.at(region.startJunction), firstJoint[c]),
                 thickness[region.startConnecting], false});
        if (region.endJunction >= 0)
            connectingBones.push_back(
                {skeleton.addBone(junctionJoint.at(region.endJunction), lastJoint[c]),
                 thickness[region.endConnecting], false});
    }

    // Step 3: collapse short bones inside thick regions (Fig. 6b). The
    // junction side is the head, so a collapsed bone leaves the joint at the
    // branching point; two junctions merge at their midpoint.
    for (const ConnectingBone& candidate : connectingBones) {
        if (!skeleton.hasBone(candidate.bone))
            continue;
        const Bone& bone = skeleton.bone(candidate.bone);
        const double factor =
            candidate.betweenJunctions ? options.junctionCollapseFactor : options.collapseFactor;
        if (skeleton.boneLength(candidate.bone) >= factor * candidate.thickness)
            continue;
        Vec3 merged = candidate.betweenJunctions ? Vec3(0.5 * (skeleton.joint(bone.head).position +
                                                               skeleton.joint(bone.tail).position))
                                                 : skeleton.joint(bone.head).position;
        skeleton.collapseBone(candidate.bone, merged);
    }

    // Step 4: root and orientation.
    skeleton.setRoot(chooseCentralRoot(skeleton));
    skeleton.reorient();
    auto problems = skeleton.validate();
    if (!problems.empty())
        throw Error("the skeleton of this shape is invalid: " + problems.front());
    return result;
}

std::vector<BoneId> bonesOfSection(const PartSkeleton& skeleton, int cylinder, int section,
                                   int sectionCount) {
    const auto& bones = skeleton.cylinderBones[cylinder];
    const auto& joints = skeleton.jointSections[cylinder];
    if (bones.empty())
        return {};
    if (section == -1)
        return {bones.front()};
    if (section == -2 || section >= sectionCount)
        return {bones.back()};
    if (section <= joints.front())
        return {bones.front()};  // start cap beyond the end joint
    if (section >= joints.back())
        return {bones.back()};
    std::vector<BoneId> owners;
    for (std::size_t m = 0; m < bones.size(); ++m)
        if (joints[m] <= section && section <= joints[m + 1])
            owners.push_back(bones[m]);
    return owners;
}

}  // namespace rigmesh
