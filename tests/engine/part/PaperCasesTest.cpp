// The skeletons the paper shows (section 2.3): CDP catches a step in
// thickness that plain DP misses (Fig. 4), and branching shapes get one
// branching joint with a leaf per limb (Fig. 6).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "PartTestSupport.h"

namespace rigmesh {
namespace {

// A joint must lie this close to the step in thickness, relative to the
// sketch's x extent.
constexpr double kStepJointTolerance = 0.15;
// Vertical slices of the outline used to find the step.
constexpr int kWidthSlices = 40;
// Slices this close to either end (fraction of the x extent) are skipped:
// the rounded caps change width fastest of all.
constexpr double kCapMargin = 0.2;

// Half the vertical extent of the polygon's crossings with the line x; 0
// where the line misses it.
double halfWidthAt(const std::vector<Vec2>& polygon, double x) {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        if ((a.x() > x) != (b.x() > x)) {
            const double y = a.y() + (x - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
            low = std::min(low, y);
            high = std::max(high, y);
        }
    }
    return high > low ? (high - low) / 2.0 : 0.0;
}

// The x between the two neighbouring slices whose half-widths differ most,
// away from the caps; the profile is printed for inspection.
double thicknessStepX(const std::vector<Vec2>& outline) {
    double x0 = std::numeric_limits<double>::infinity();
    double x1 = -x0;
    for (const Vec2& p : outline) {
        x0 = std::min(x0, p.x());
        x1 = std::max(x1, p.x());
    }
    const double length = x1 - x0;
    double bestChange = -1.0;
    double stepX = 0.0;
    double previous = 0.0;
    std::cout << "[ measured ] kinked half-width profile (x: half-width):";
    for (int i = 0; i <= kWidthSlices; ++i) {
        const double x = x0 + length * i / kWidthSlices;
        const double width = halfWidthAt(outline, x);
        std::cout << " " << x << ":" << width;
        const bool interior =
            x - length / kWidthSlices >= x0 + kCapMargin * length && x <= x1 - kCapMargin * length;
        if (interior && std::abs(width - previous) > bestChange) {
            bestChange = std::abs(width - previous);
            stepX = x - 0.5 * length / kWidthSlices;
        }
        previous = width;
    }
    std::cout << "\n[ measured ] kinked thickness step at x = " << stepX << "\n";
    return stepX;
}

double xExtent(const std::vector<Vec2>& outline) {
    const auto [low, high] = std::minmax_element(
        outline.begin(), outline.end(), [](const Vec2& a, const Vec2& b) { return a.x() < b.x(); });
    return high->x() - low->x();
}

TEST(PaperCases, CdpPlacesAJointAtTheKinkedStep) {
    const Part& part = parttest::sharedPart("kinked").part;
    const double stepX = thicknessStepX(part.outline);
    const double tolerance = kStepJointTolerance * xExtent(part.outline);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Joint& joint : part.skeleton.joints())
        nearest = std::min(nearest, std::abs(joint.position.x() - stepX));
    std::cout << "[ measured ] kinked CDP: " << part.skeleton.jointCount()
              << " joints, nearest to the step " << nearest << " (tolerance " << tolerance << ")\n";
    EXPECT_LE(nearest, tolerance);
}

TEST(PaperCases, PlainDpGivesOneBoneOnKinked) {
    const Part& part = parttest::sharedPart("kinked", 1.0, false).part;
    EXPECT_EQ(part.skeleton.boneCount(), 1);
}

TEST(PaperCases, YBranchHasOneBranchingJoint) {
    const Skeleton& skeleton = parttest::sharedPart("y_branch").part.skeleton;
    EXPECT_EQ(parttest::jointsOfDegree(skeleton, 3).size(), 1u);
    for (const Joint& joint : skeleton.joints())
        EXPECT_LE(skeleton.degree(joint.id), 3) << "joint " << joint.id;
}

TEST(PaperCases, StarHasFiveLeavesAroundOneCentre) {
    const Skeleton& skeleton = parttest::sharedPart("star").part.skeleton;
    EXPECT_EQ(parttest::jointsOfDegree(skeleton, 1).size(), 5u);
    EXPECT_EQ(parttest::jointsOfDegree(skeleton, 5).size(), 1u);
}

TEST(PaperCases, BipedHasHeadHandsAndFeetAsLeaves) {
    const Skeleton& skeleton = parttest::sharedPart("biped").part.skeleton;
    std::vector<Joint> leaves = parttest::jointsOfDegree(skeleton, 1);
    ASSERT_EQ(leaves.size(), 5u);
    // Head: the highest leaf; feet: the two lowest; hands: the two left.
    std::sort(leaves.begin(), leaves.end(),
              [](const Joint& a, const Joint& b) { return a.position.y() < b.position.y(); });
    const Joint& head = leaves[4];
    const Joint& footA = leaves[0];
    const Joint& footB = leaves[1];
    const Joint& handA = leaves[2];
    const Joint& handB = leaves[3];
    const Joint& leftHand = handA.position.x() < handB.position.x() ? handA : handB;
    const Joint& rightHand = handA.position.x() < handB.position.x() ? handB : handA;
    // The hands are the leaves with extreme x.
    double minX = std::numeric_limits<double>::infinity();
    double maxX = -minX;
    for (const Joint& leaf : leaves) {
        minX = std::min(minX, leaf.position.x());
        maxX = std::max(maxX, leaf.position.x());
    }
    EXPECT_EQ(leftHand.position.x(), minX);
    EXPECT_EQ(rightHand.position.x(), maxX);
    // The head lies between the hands, the feet on either side of it.
    EXPECT_GT(head.position.x(), leftHand.position.x());
    EXPECT_LT(head.position.x(), rightHand.position.x());
    EXPECT_LT(std::min(footA.position.x(), footB.position.x()), head.position.x());
    EXPECT_GT(std::max(footA.position.x(), footB.position.x()), head.position.x());
    EXPECT_GT(head.position.y(), std::max(leftHand.position.y(), rightHand.position.y()));
}

}  // namespace
}  // namespace rigmesh
