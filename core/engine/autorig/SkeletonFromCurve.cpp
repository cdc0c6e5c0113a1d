#include "autorig/SkeletonFromCurve.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <set>
#include <vector>

#include "autorig/AxisChain.h"
#include "autorig/JointsInside.h"
#include "autorig/SurfaceProbe.h"
#include "base/Error.h"
#include "rig/DouglasPeucker.h"

namespace rigmesh {

namespace {

// The curve as an editable graph: nodes die (pruned, merged) but keep their
// index.
struct Graph {
    std::vector<Vec3> points;
    std::vector<double> radii;
    std::vector<std::set<int>> neighbours;
    std::vector<char> alive;
    // Per node: the mesh vertices that contracted onto it, and those of
    // the twigs pruned into it.
    std::vector<std::vector<int>> vertices;
    const TriMesh* mesh = nullptr;

    int degree(int n) const { return static_cast<int>(neighbours[n].size()); }
    double length(int a, int b) const { return (points[a] - points[b]).norm(); }
    void removeEdge(int a, int b) {
        neighbours[a].erase(b);
        neighbours[b].erase(a);
    }
    void kill(int n) {
        for (int m : std::vector<int>(neighbours[n].begin(), neighbours[n].end()))
            removeEdge(n, m);
        alive[n] = 0;
    }
    std::vector<int> aliveNodes() const {
        std::vector<int> nodes;
        for (int n = 0; n < static_cast<int>(alive.size()); ++n)
            if (alive[n])
                nodes.push_back(n);
        return nodes;
    }
};

// A node's radius: the mean distance to the vertices that contracted onto
// it; nodes without any take their neighbours' mean.
std::vector<double> nodeRadii(const CurveSkeleton& curve, const TriMesh& mesh) {
    const int count = static_cast<int>(curve.nodes.size());
    std::vector<double> radii(count, -1.0);
    for (int n = 0; n < count; ++n) {
        double sum = 0.0;
        int used = 0;
        for (int v : curve.nodeVertices[n])
            if (v >= 0 && v < mesh.vertexCount()) {
                sum += (mesh.vertices[v] - curve.nodes[n]).norm();
                ++used;
            }
        if (used > 0)
            radii[n] = sum / used;
    }
    std::vector<std::vector<int>> adjacent(count);
    for (const auto& [a, b] : curve.edges) {
        adjacent[a].push_back(b);
        adjacent[b].push_back(a);
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (int n = 0; n < count; ++n) {
            if (radii[n] >= 0.0)
                continue;
            double sum = 0.0;
            int known = 0;
            for (int m : adjacent[n])
                if (radii[m] >= 0.0) {
                    sum += radii[m];
                    ++known;
                }
            if (known > 0) {
                radii[n] = sum / known;
                changed = true;
            }
        }
    }
    for (double& r : radii)
        r = std::max(r, 0.0);
    return radii;
}

// Keeps the component with the most nodes and its shortest-path tree from
// its thickest node (the torso, where a person puts the root). A cycle (a
// handle; legs whose feet touch) is cut where the paths from there meet: at
// its far end, so the legs keep their own chains down to the feet.
Graph spanningTree(const CurveSkeleton& curve, const TriMesh& mesh) {
    const int count = static_cast<int>(curve.nodes.size());
    std::vector<std::vector<int>> adjacent(count);
    for (const auto& [a, b] : curve.edges)
        if (a != b && a >= 0 && b >= 0 && a < count && b < count) {
            adjacent[a].push_back(b);
            adjacent[b].push_back(a);
        }
    Graph graph;
    graph.points = curve.nodes;
    graph.radii = nodeRadii(curve, mesh);
    graph.neighbours.assign(count, {});
    graph.alive.assign(count, 0);
    graph.vertices = curve.nodeVertices;
    graph.mesh = &mesh;
    for (auto& list : graph.vertices)
        std::erase_if(list, [&](int v) { return v < 0 || v >= mesh.vertexCount(); });
    std::vector<int> component(count, -1);
    int best = -1, bestSize = 0;
    for (int start = 0; start < count; ++start) {
        if (component[start] >= 0)
            continue;
        int size = 0;
        std::deque<int> queue{start};
        component[start] = start;
        while (!queue.empty()) {
            const int n = queue.front();
            queue.pop_front();
            ++size;
            for (int m : adjacent[n])
                if (component[m] < 0) {
                    component[m] = start;
                    queue.push_back(m);
                }
        }
        if (size > bestSize) {
            best = start;
            bestSize = size;
        }
    }
    int thickest = best;
    for (int n = 0; n < count; ++n)
        if (component[n] == best && graph.radii[n] > graph.radii[thickest])
            thickest = n;
    std::vector<double> distance(count, std::numeric_limits<double>::infinity());
    std::vector<int> parent(count, -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    distance[thickest] = 0.0;
    queue.push({0.0, thickest});
    while (!queue.empty()) {
        const auto [d, n] = queue.top();
        queue.pop();
        if (d > distance[n])
            continue;
        graph.alive[n] = 1;
        if (parent[n] >= 0) {
            graph.neighbours[n].insert(parent[n]);
            graph.neighbours[parent[n]].insert(n);
        }
        for (int m : adjacent[n]) {
            const double through = d + graph.length(n, m);
            if (through < distance[m]) {
                distance[m] = through;
                parent[m] = n;
                queue.push({through, m});
            }
        }
    }
    return graph;
}

// The nodes from `start` through `next` on to the first node whose degree is
// not 2 (included).
std::vector<int> walkBranch(const Graph& graph, int start, int next) {
    std::vector<int> branch{start, next};
    while (graph.degree(branch.back()) == 2) {
        const int here = branch.back();
        const int previous = branch[branch.size() - 2];
        const int onward = *graph.neighbours[here].begin() == previous
                               ? *graph.neighbours[here].rbegin()
                               : *graph.neighbours[here].begin();
        branch.push_back(onward);
    }
    return branch;
}

double branchLength(const Graph& graph, const std::vector<int>& branch) {
    double length = 0.0;
    for (std::size_t i = 1; i < branch.size(); ++i)
        length += graph.length(branch[i - 1], branch[i]);
    return length;
}

// The farthest of the branch's vertices (its nodes' but the last) from the
// point where it leaves the rest of the curve.
double reachBeyond(const Graph& graph, const std::vector<int>& branch) {
    const Vec3& junction = graph.points[branch.back()];
    double farthest = 0.0;
    for (std::size_t i = 0; i + 1 < branch.size(); ++i)
        for (int v : graph.vertices[branch[i]])
            farthest = std::max(farthest, (graph.mesh->vertices[v] - junction).norm());
    return farthest;
}

// Removes the twig that falls shortest of its limit, one at a time (each
// removal can turn a junction into a plain branch node); never below two
// tips. A branch that reaches farther than `keepReach` from its junction
// stays whatever its length: it is a part of the body (a trunk's base, a
// fist beside its thumb, a head), not flow noise, and without it those
// vertices would be far from every bone. But not when its tip's ball
// overlaps that of another branch of the same junction, a twig or a
// longer one, reaching farther: one fat end that the flow split in two (a
// spider's head ending in its two fangs, sydney's raised hand on a finer
// wrap). The other branch stays and ends the limb (its junction becomes a
// plain node of its branch), its tip beside the pruned one's, so those
// vertices keep a bone near them.
void pruneTwigs(Graph& graph, const CurveRigOptions& options, double keepReach) {
    struct Twig {
        std::vector<int> branch;
        double ratio = 0.0;
        double reach = 0.0;
    };
    while (true) {
        std::vector<int> tips;
        for (int n : graph.aliveNodes())
            if (graph.degree(n) == 1)
                tips.push_back(n);
        if (tips.size() <= 2)
            return;
        std::vector<Twig> twigs;
        for (int tip : tips) {
            std::vector<int> branch = walkBranch(graph, tip, *graph.neighbours[tip].begin());
            const int junction = branch.back();
            if (graph.degree(junction) < 3)
                continue;
            const double limit = graph.radii[junction] + options.twigTipFactor * graph.radii[tip];
            const double ratio = limit > 0.0 ? branchLength(graph, branch) / limit : 1.0;
            if (ratio < 1.0)
                twigs.push_back({std::move(branch), ratio, 0.0});
        }
        for (Twig& twig : twigs)
            twig.reach = reachBeyond(graph, twig.branch);
        // Whether `twig` is the lesser half of a fat end split in two: a
        // branch of the same junction, twig or not, reaching farther, its
        // tip's ball overlapping the twig's.
        const auto splitHalf = [&](const Twig& twig) {
            const int tip = twig.branch.front();
            for (int otherTip : tips) {
                if (otherTip == tip)
                    continue;
                const std::vector<int> other =
                    walkBranch(graph, otherTip, *graph.neighbours[otherTip].begin());
                if (other.back() != twig.branch.back())
                    continue;
                const double otherReach = reachBeyond(graph, other);
                const bool overlap =
                    graph.length(tip, otherTip) < graph.radii[tip] + graph.radii[otherTip];
                const bool fartherOther =
                    otherReach > twig.reach || (otherReach == twig.reach && otherTip < tip);
                if (overlap && fartherOther)
                    return true;
            }
            return false;
        };
        const Twig* worst = nullptr;
        for (const Twig& twig : twigs)
            if ((!worst || twig.ratio < worst->ratio) &&
                (twig.reach <= keepReach || splitHalf(twig)))
                worst = &twig;
        if (!worst)
            return;
        std::vector<int> branch = worst->branch;
        const int junction = branch.back();
        branch.pop_back();  // the junction stays, and takes the twig's vertices
        for (int n : branch) {
            auto& into = graph.vertices[junction];
            into.insert(into.end(), graph.vertices[n].begin(), graph.vertices[n].end());
            graph.kill(n);
        }
    }
}

// Merges two junctions joined by a short branch into one node at the
// branch's middle, repeatedly.
void collapseJunctions(Graph& graph, const CurveRigOptions& options) {
    for (bool changed = true; changed;) {
        changed = false;
        for (int a : graph.aliveNodes()) {
            if (graph.degree(a) < 3)
                continue;
            for (int next :
                 std::vector<int>(graph.neighbours[a].begin(), graph.neighbours[a].end())) {
                const std::vector<int> branch = walkBranch(graph, a, next);
                const int b = branch.back();
                if (b == a || graph.degree(b) < 3)
                    continue;
                const double length = branchLength(graph, branch);
                if (length >=
                    options.junctionCollapseFactor * std::max(graph.radii[a], graph.radii[b]))
                    continue;
                // Walk to the middle of the branch by length.
                double walked = 0.0;
                Vec3 middle = graph.points[a];
                for (std::size_t i = 1; i < branch.size(); ++i) {
                    const double step = graph.length(branch[i - 1], branch[i]);
                    if (walked + step >= length / 2) {
                        const double t = step > 0.0 ? (length / 2 - walked) / step : 0.0;
                        middle =
                            (1 - t) * graph.points[branch[i - 1]] + t * graph.points[branch[i]];
                        break;
                    }
                    walked += step;
                }
                std::set<int> joined;
                for (int n : branch)
                    if (n != a)
                        for (int m : graph.neighbours[n])
                            joined.insert(m);
                for (int n : branch)
                    joined.erase(n);
                graph.radii[a] = std::max(graph.radii[a], graph.radii[b]);
                for (int n : branch)
                    if (n != a) {
                        auto& into = graph.vertices[a];
                        into.insert(into.end(), graph.vertices[n].begin(), graph.vertices[n].end());
                        graph.kill(n);
                    }
                graph.points[a] = middle;
                for (int m : joined) {
                    graph.neighbours[a].insert(m);
                    graph.neighbours[m].insert(a);
                }
                changed = true;
                break;
            }
            if (changed)
                break;
        }
    }
}

// Every branch between nodes whose degree is not 2, once.
std::vector<std::vector<int>> branches(const Graph& graph) {
    std::vector<std::vector<int>> result;
    std::set<std::pair<int, int>> walked;
    for (int n : graph.aliveNodes()) {
        if (graph.degree(n) == 2)
            continue;
        for (int next : graph.neighbours[n]) {
            if (walked.contains({n, next}))
                continue;
            std::vector<int> branch = walkBranch(graph, n, next);
            walked.insert({branch[branch.size() - 1], branch[branch.size() - 2]});
            result.push_back(std::move(branch));
        }
    }
    return result;
}

// The branch as CDP sees it (paper 2.1, 2.3): its samples smoothed (the
// flow's curve zig-zags by a fraction of an edge), and the samples inside a
// junction's ball left out, their radius swollen by the other branches'
// vertices: the junction joint stands for the branch's first sample there,
// as a sketched cylinder's end joint collapses into its junction.
std::vector<int> branchSamples(const Graph& graph, const std::vector<int>& branch) {
    const auto insideBall = [&](int junction, int node) {
        return graph.degree(junction) >= 3 && graph.length(junction, node) < graph.radii[junction];
    };
    std::size_t first = 1, last = branch.size() - 1;
    while (first < last && insideBall(branch.front(), branch[first]))
        ++first;
    while (last > first && insideBall(branch.back(), branch[last - 1]))
        --last;
    std::vector<int> samples{0};
    for (std::size_t i = first; i < last; ++i)
        samples.push_back(static_cast<int>(i));
    samples.push_back(static_cast<int>(branch.size() - 1));
    return samples;
}

std::vector<TubeSample> smoothedTube(const Graph& graph, const std::vector<int>& branch,
                                     const std::vector<int>& samples, int iterations) {
    std::vector<TubeSample> tube;
    for (int s : samples)
        tube.push_back({graph.points[branch[s]], graph.radii[branch[s]]});
    // A junction end takes the radius of the branch where it leaves the ball.
    if (tube.size() > 2) {
        if (graph.degree(branch.front()) >= 3)
            tube.front().radius = tube[1].radius;
        if (graph.degree(branch.back()) >= 3)
            tube.back().radius = tube[tube.size() - 2].radius;
    }
    for (int round = 0; round < iterations; ++round) {
        std::vector<TubeSample> next = tube;
        for (std::size_t i = 1; i + 1 < tube.size(); ++i) {
            next[i].point = 0.5 * tube[i].point + 0.25 * (tube[i - 1].point + tube[i + 1].point);
            next[i].radius =
                0.5 * tube[i].radius + 0.25 * (tube[i - 1].radius + tube[i + 1].radius);
        }
        tube = std::move(next);
    }
    return tube;
}

// A limb that CDP gives one bone, from the junction it leaves to its tip:
// that bone would start in the middle of the body part the limb leaves, so
// turning it would turn that part too. Paper 2.3 (Fig. 6) joins a junction's
// joint by a bone to the end of each cylindrical region's skeleton, so the
// limb keeps a joint of its own: at its narrowest cross-section beyond the
// junction's ball when it widens again past there by more than the CDP
// threshold (a neck below a head, an ear's base), else where it leaves the
// ball. The width is the distance to the surface (the radius of the largest
// ball there, as the chords measure a sketch's width), which the flow's node
// radii smooth away at a short neck. The tube's sample index, or none (no
// sample at least `minimumBone` from both ends).
std::optional<int> limbJoint(const Graph& graph, const std::vector<int>& branch,
                             const std::vector<TubeSample>& tube, const std::vector<double>& along,
                             const SurfaceProbe& surface, double threshold, double minimumBone) {
    const int last = static_cast<int>(tube.size()) - 1;
    const bool tipFirst = graph.degree(branch.front()) == 1 && graph.degree(branch.back()) >= 3;
    const bool tipLast = graph.degree(branch.back()) == 1 && graph.degree(branch.front()) >= 3;
    if (last < 2 || (!tipFirst && !tipLast))
        return std::nullopt;
    // From the junction's ball towards the tip.
    std::vector<int> order;
    for (int i = 1; i < last; ++i)
        order.push_back(tipLast ? i : last - i);
    const auto fits = [&](int k) {
        return along[k] >= minimumBone && along[last] - along[k] >= minimumBone;
    };
    std::vector<double> width(tube.size(), 0.0);
    for (int k : order)
        width[k] = surface.distance(tube[k].point);
    // widestBeyond[i]: the widest of the samples after order[i] (0 if none).
    std::vector<double> widestBeyond(order.size(), 0.0);
    for (std::size_t i = order.size() - 1; i-- > 0;)
        widestBeyond[i] = std::max(widestBeyond[i + 1], width[order[i + 1]]);
    std::optional<int> narrowest;
    double widerBeyond = 0.0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const int k = order[i];
        if (!fits(k))
            continue;
        if (!narrowest || width[k] < width[*narrowest]) {
            narrowest = k;
            widerBeyond = widestBeyond[i] - width[k];
        }
    }
    if (narrowest && widerBeyond > threshold)
        return narrowest;
    const int exit = order.front();
    return fits(exit) ? std::optional<int>(exit) : std::nullopt;
}

// The joints of a branch: CDP's kept samples, interior joints closer than
// the minimum bone merged (as SkeletonFromRegions does along a cylinder).
// Returns their samples (position and radius), the branch's two ends first
// and last.
std::vector<TubeSample> branchJoints(const Graph& graph, const std::vector<int>& branch,
                                     const SurfaceProbe& surface, const CurveRigOptions& options) {
    const std::vector<int> samples = branchSamples(graph, branch);
    const std::vector<TubeSample> tube =
        smoothedTube(graph, branch, samples, options.smoothingIterations);
    double radiusSum = 0.0;
    for (const TubeSample& sample : tube)
        radiusSum += sample.radius;
    std::vector<double> along(tube.size(), 0.0);
    for (std::size_t i = 1; i < tube.size(); ++i)
        along[i] = along[i - 1] + (tube[i].point - tube[i - 1].point).norm();
    // A thin limb's bones are measured against its length too: CDP by the
    // radius alone gives a spider's leg, fifty radii long, a bone for every
    // wobble of the flow's curve.
    const double scale = std::max(radiusSum / static_cast<double>(tube.size()),
                                  options.thinLimbLengthShare * along.back());
    const std::vector<int> kept =
        cylindricalDouglasPeuckerInSpace(tube, options.relativeThreshold * scale);
    const double minimumBone = options.relativeMinimumBone * scale;
    std::vector<int> merged{kept.front()};
    for (std::size_t i = 1; i + 1 < kept.size(); ++i)
        if (along[kept[i]] - along[merged.back()] >= minimumBone)
            merged.push_back(kept[i]);
    if (kept.size() > 1) {
        if (merged.size() > 1 && along[kept.back()] - along[merged.back()] < minimumBone)
            merged.pop_back();
        merged.push_back(kept.back());
    }
    if (merged.size() == 2)
        if (const std::optional<int> k = limbJoint(graph, branch, tube, along, surface,
                                                   options.relativeThreshold * scale, minimumBone))
            merged.insert(merged.begin() + 1, *k);
    std::vector<TubeSample> joints;
    for (int k : merged)
        joints.push_back(tube[k]);
    return joints;
}

// The branching joint where the body is thickest (the torso); the most
// central joint of a skeleton without branches.
JointId thickestRoot(const Skeleton& skeleton, const std::map<JointId, double>& radiusOf) {
    JointId best = kNoJoint;
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) >= 3 &&
            (best == kNoJoint || radiusOf.at(joint.id) > radiusOf.at(best)))
            best = joint.id;
    return best == kNoJoint ? chooseCentralRoot(skeleton) : best;
}

}  // namespace

int leafCount(const Skeleton& skeleton) {
    int leaves = 0;
    for (const Joint& joint : skeleton.joints())
        leaves += skeleton.degree(joint.id) == 1 ? 1 : 0;
    return leaves;
}

Skeleton skeletonFromCurve(const CurveSkeleton& curve, const TriMesh& mesh,
                           const CurveRigOptions& options) {
    if (curve.nodes.size() < 2 || curve.edges.empty())
        throw Error(MessageId::AutoRigFlowGaveNoCurve);
    Graph graph = spanningTree(curve, mesh);
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
    pruneTwigs(graph, options, options.keepReachFraction * diagonal);
    collapseJunctions(graph, options);

    const SurfaceProbe surface(mesh);
    Skeleton skeleton;
    std::map<int, JointId> jointOfNode;
    std::map<JointId, double> radiusOf;
    auto jointAt = [&](int node) {
        const auto found = jointOfNode.find(node);
        if (found != jointOfNode.end())
            return found->second;
        const JointId joint = skeleton.addJoint(graph.points[node]);
        radiusOf[joint] = graph.radii[node];
        return jointOfNode[node] = joint;
    };
    for (const std::vector<int>& branch : branches(graph)) {
        const std::vector<TubeSample> joints = branchJoints(graph, branch, surface, options);
        JointId previous = jointAt(branch.front());
        for (std::size_t i = 1; i < joints.size(); ++i) {
            JointId next;
            if (i + 1 == joints.size()) {
                next = jointAt(branch.back());
            } else {
                next = skeleton.addJoint(joints[i].point);
                radiusOf[next] = joints[i].radius;
            }
            skeleton.addBone(previous, next);
            previous = next;
        }
    }
    if (skeleton.boneCount() == 0)
        throw Error(MessageId::AutoRigCurveTooShort);
    // Half the local radius deep: a tip joint ends about where a sketched
    // part's sits, in the middle of its cap.
    pullJointsInside(skeleton, mesh, [&](JointId joint) { return 0.5 * radiusOf[joint]; });
    skeleton.setRoot(thickestRoot(skeleton, radiusOf));
    skeleton.reorient();
    if (leafCount(skeleton) <= 2) {
        const double covered = farthestFromBones(mesh, skeleton);
        if (covered > options.coverageFraction * diagonal) {
            Skeleton axis = mainAxisChain(mesh);
            if (farthestFromBones(mesh, axis) < covered)
                skeleton = std::move(axis);
        }
    }
    const std::vector<Message> problems = skeleton.validate();
    if (!problems.empty())
        throw Error(MessageId::AutoRigSkeletonFailed, problems.front());
    return skeleton;
}

bool flowGaveNoSkeleton(MessageId id) {
    // extractCurveSkeleton's and skeletonFromCurve's own refusals above.
    return id == MessageId::AutoRigFlowContracted || id == MessageId::AutoRigFlowGaveNoCurve ||
           id == MessageId::AutoRigCurveTooShort || id == MessageId::AutoRigSkeletonFailed;
}

}  // namespace rigmesh
