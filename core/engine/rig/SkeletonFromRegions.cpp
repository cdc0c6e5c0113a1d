#include "rig/SkeletonFromRegions.h"

#include <cmath>
#include <map>

#include "base/Error.h"
#include "rig/DouglasPeucker.h"

namespace rigmesh {
namespace {

Vec3 onSketchPlane(const Vec2& p) {
    return Vec3(p.x(), p.y(), 0.0);
}

// The mean radius of the body's smoothed chords: like everything CDP looks
// at, independent of how finely the sections are sampled.
double meanRadius(const CylinderSections& cylinder) {
    double sum = 0.0;
    for (const auto& chord : cylinder.axisChords)
        sum += chord.radius();
    return sum / static_cast<double>(cylinder.axisChords.size());
}

// The body sections (not cap slices) in order.
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

// A cylinder's joints along its axis.
struct AxisJoints {
    std::vector<int> sections;  // the section each joint stands at (owns the weights)
    std::vector<Vec2> positions;
};

AxisJoints atSectionCentres(const CylinderSections& cylinder, const std::vector<int>& sections) {
    AxisJoints joints{sections, {}};
    for (int s : sections)
        joints.positions.push_back(cylinder.sections[s].centre());
    return joints;
}

// The body section taken nearest to smoothed chord `chord`.
int sectionNearestChord(const CylinderSections& cylinder, const std::vector<int>& body, int chord) {
    int best = body.front();
    for (int s : body)
        if (std::abs(cylinder.sections[s].chordParameter - chord) <
            std::abs(cylinder.sections[best].chordParameter - chord))
            best = s;
    return best;
}

// Step 1: joints along a cylinder's axis from (C)DP, as section indices. CDP
// runs on the smoothed chords of the chordal axis (the paper's v_1 .. v_n),
// not on the resampled sections: the sections follow the edge length and the
// local thickness, and a denser sampling of the same shape would find more
// samples over the threshold (a 0.33-long bone at a biped's shoulder once
// thin parts got finer). The body's chords only: a cap's shrinking width
// would look like a change of thickness and give a short bone at every tip.
AxisJoints simplifyAxis(const CylinderSections& cylinder, const SkeletonOptions& options) {
    const std::vector<int> body = bodySections(cylinder);
    const auto& chords = cylinder.axisChords;
    if (chords.size() < 2 || body.size() < 2) {
        // A body of one section: one bone from cap to cap, if there are caps.
        std::vector<int> ends{body.front(), body.front()};
        extendIntoCaps(cylinder, ends);
        if (ends.front() == ends.back())
            ends.pop_back();
        return atSectionCentres(cylinder, ends);
    }
    std::vector<AxisSample> samples;
    for (const CrossSection& chord : chords)
        samples.push_back({chord.centre(), chord.left, chord.right});
    const double threshold = options.relativeThreshold * meanRadius(cylinder);
    const std::vector<int> kept = options.cylindrical
                                      ? cylindricalDouglasPeucker(samples, threshold)
                                      : douglasPeucker(samples, threshold);
    // An abrupt change of thickness splits on both sides of the step: merge
    // interior joints closer (along the chords' centres) than the minimum
    // bone length into one.
    std::vector<double> position(chords.size(), 0.0);
    for (std::size_t i = 1; i < chords.size(); ++i)
        position[i] = position[i - 1] + (chords[i].centre() - chords[i - 1].centre()).norm();
    const double minimumBone = options.relativeMinimumBone * meanRadius(cylinder);
    auto axisGap = [&](int a, int b) { return position[b] - position[a]; };
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
    // Each joint stands at its chord's centre and owns the section nearest
    // it (the weights follow the sections); two joints never share a
    // section. End joints in a cap move to its middle section.
    std::vector<int> joints;
    std::vector<int> jointChords;
    for (int chord : merged) {
        const int section = sectionNearestChord(cylinder, body, chord);
        if (joints.empty() || section > joints.back()) {
            joints.push_back(section);
            jointChords.push_back(chord);
        }
    }
    extendIntoCaps(cylinder, joints);
    AxisJoints result = atSectionCentres(cylinder, joints);
    for (std::size_t j = 1; j + 1 < joints.size(); ++j)
        result.positions[j] = cylinder.axisChords[jointChords[j]].centre();
    return result;
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
        AxisJoints axisJoints = simplifyAxis(cylinders[c], options);
        std::vector<JointId> joints;
        for (const Vec2& p : axisJoints.positions)
            joints.push_back(skeleton.addJoint(onSketchPlane(p)));
        std::vector<BoneId> bones;
        for (std::size_t m = 1; m < joints.size(); ++m)
            bones.push_back(skeleton.addBone(joints[m - 1], joints[m]));
        firstJoint[c] = joints.front();
        lastJoint[c] = joints.back();
        result.jointSections.push_back(std::move(axisJoints.sections));
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
        throw Error(MessageId::SkeletonInvalid, problems.front());
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
