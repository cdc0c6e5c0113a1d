// Twigs of a curve skeleton (autorig/SkeletonFromCurve pruneTwigs, paper
// 2.3): a fat end the flow split in two gets one leaf, even where both
// halves reach farther than the reach rule keeps; two short limbs apart
// keep theirs. The curve is given here, as the flow would leave it on a
// figure of tubes and a ball: a body, two long legs at one end, a head at
// the other ending in two short twigs. In both figures the twigs are
// shorter than the head's radius plus their tip's (ratio 0.90 and 0.92)
// and reach farther than 10% of the diagonal from the head (3.60 and 3.87
// against 3.38 and 3.37), so only their tips' distance tells them apart.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>

#include "autorig/SkeletonFromCurve.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

// A tube of `radius` from a to b.
TriMesh tubeBetween(const Vec3& a, const Vec3& b, double radius) {
    TriMesh tube = makeCylinderTube(8, 16, radius, (b - a).norm());
    const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), b - a);
    for (Vec3& v : tube.vertices)
        v = 0.5 * (a + b) + turn * v;
    return tube;
}

void append(TriMesh& all, const TriMesh& piece) {
    const int offset = all.vertexCount();
    all.vertices.insert(all.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (const auto& [x, y, z] : piece.faces)
        all.faces.push_back({x + offset, y + offset, z + offset});
}

struct Figure {
    TriMesh mesh;
    CurveSkeleton curve;

    // Curve nodes from a to b (a already a node, `from`) every 0.5; returns
    // the last node's index.
    int chain(int from, const Vec3& b) {
        const Vec3 a = curve.nodes[from];
        const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 0.5)));
        int previous = from;
        for (int i = 1; i <= steps; ++i) {
            curve.nodes.push_back(a + (b - a) * (double(i) / steps));
            const int node = static_cast<int>(curve.nodes.size()) - 1;
            curve.edges.push_back({previous, node});
            previous = node;
        }
        return previous;
    }

    // Each mesh vertex contracts onto its nearest node, but the head's
    // (headFirst to headEnd) onto the head's node: the flow shrinks a ball
    // to its middle.
    void assignVertices(int headNode, int headFirst, int headEnd) {
        curve.nodeVertices.assign(curve.nodes.size(), {});
        for (int v = 0; v < mesh.vertexCount(); ++v) {
            if (v >= headFirst && v < headEnd) {
                curve.nodeVertices[headNode].push_back(v);
                continue;
            }
            int best = 0;
            double nearest = std::numeric_limits<double>::infinity();
            for (int n = 0; n < static_cast<int>(curve.nodes.size()); ++n)
                if (const double d = (mesh.vertices[v] - curve.nodes[n]).norm(); d < nearest) {
                    nearest = d;
                    best = n;
                }
            curve.nodeVertices[best].push_back(v);
        }
    }
};

// Body along x, legs from its left end, a head of radius 3 at its right end
// whose two twigs of radius 1.2 end at `tip` and its mirror image in y = 0.
Figure headWithTwoTwigs(const Vec3& tip) {
    Figure figure;
    const Vec3 hips(-10, 0, 0), head(12, 0, 0);
    const Vec3 otherTip(tip.x(), -tip.y(), tip.z());
    append(figure.mesh, tubeBetween(hips, head, 1.5));
    append(figure.mesh, tubeBetween(hips, Vec3(-10, 10, 0), 1.0));
    append(figure.mesh, tubeBetween(hips, Vec3(-10, -10, 0), 1.0));
    const int headFirst = figure.mesh.vertexCount();
    TriMesh ball = makeIcosphere(2, 3.0);
    for (Vec3& v : ball.vertices)
        v += head;
    append(figure.mesh, ball);
    const int headEnd = figure.mesh.vertexCount();
    append(figure.mesh, tubeBetween(head, tip, 1.2));
    append(figure.mesh, tubeBetween(head, otherTip, 1.2));
    figure.curve.nodes.push_back(hips);
    figure.chain(0, Vec3(-10, 10, 0));
    figure.chain(0, Vec3(-10, -10, 0));
    const int headNode = figure.chain(0, head);
    figure.chain(headNode, tip);
    figure.chain(headNode, otherTip);
    figure.assignVertices(headNode, headFirst, headEnd);
    return figure;
}

// Tips 1.6 apart, tip radii 1.03: one fat end.
TEST(CurveTwigs, AFatEndSplitInTwoGetsOneLeafThoughBothHalvesReachFar) {
    const Figure figure = headWithTwoTwigs(Vec3(15.3, 0.8, 0));
    EXPECT_EQ(leafCount(skeletonFromCurve(figure.curve, figure.mesh)), 3);  // legs, head
}

// Tips 5.2 apart, tip radii 1.13: two short limbs.
TEST(CurveTwigs, TwoShortLimbsApartKeepALeafEach) {
    const Figure figure = headWithTwoTwigs(Vec3(14.6, 2.6, 0));
    EXPECT_EQ(leafCount(skeletonFromCurve(figure.curve, figure.mesh)), 4);
}

}  // namespace
}  // namespace rigmesh
