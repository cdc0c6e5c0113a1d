// The skeleton of a sketched part (paper 2.3, Fig. 6).
//
// 1. Cylindrical regions: the smooth chordal axis (the smoothed chords,
//    CylinderSections::axisChords, which do not depend on the edge length) is
//    down-sampled with the Cylindrical Douglas-Peucker algorithm (or plain DP,
//    for comparison): each kept chord is a joint, placed at the body section
//    nearest it, and each range a bone.
// 2. Connecting regions: a joint at the centre of each junction triangle; a
//    bone from it to the end joint of each cylinder that leaves it, and to the
//    junctions it was merged with.
// 3. Short bones inside thick connecting regions are collapsed, so a Y gets
//    one branching joint rather than a cluster of tiny bones.
// 4. The root is the most central joint (preferring branching joints); bones
//    point away from it.
// Joints lie in the sketch plane (z = 0), the plane of symmetry of the
// surface, so they are inside it.
#pragma once

#include <vector>

#include "rig/Skeleton.h"
#include "surface/CrossSections.h"

namespace rigmesh {

struct SkeletonOptions {
    bool cylindrical = true;  // CDP (paper) or plain Douglas-Peucker
    // DP/CDP threshold as a fraction of the cylinder's mean cross-section
    // radius, so the result does not depend on the part's size.
    double relativeThreshold = 0.35;
    // Joints along a cylinder closer than this fraction of its mean radius
    // are merged (a step in thickness makes CDP split on both sides of it).
    double relativeMinimumBone = 0.5;
    // A bone inside a connecting region shorter than this times the region's
    // thickness (mean radius of the cylinders that meet there) is collapsed.
    double collapseFactor = 1.0;
    // The same for bones between two junction joints of one connecting
    // region: they usually span its width, so a star's body or a biped's
    // chest gets one branching joint.
    double junctionCollapseFactor = 2.0;
};

struct PartSkeleton {
    Skeleton skeleton;
    // Per cylinder: the section indices where its joints sit (DP output) and
    // the bone spanning each range between consecutive ones.
    std::vector<std::vector<int>> jointSections;
    std::vector<std::vector<BoneId>> cylinderBones;
};

PartSkeleton buildSkeleton(const Decomposition& decomposition,
                           const std::vector<CylinderSections>& cylinders,
                           const SkeletonOptions& options = {});

// The bones of cylinder `c` that own cross section `section` (two at a joint
// between bones, one elsewhere; -1 = the start tip, -2 = the end tip).
std::vector<BoneId> bonesOfSection(const PartSkeleton& skeleton, int cylinder, int section,
                                   int sectionCount);

}  // namespace rigmesh
