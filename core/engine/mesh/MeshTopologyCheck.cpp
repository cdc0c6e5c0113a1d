#include "mesh/MeshTopologyCheck.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace rigmesh {
namespace {

// A face's corner at a vertex v, (v, from, to) in the face's order: around a
// closed, oriented surface the faces at v chain up, each one's `to` the next
// one's `from`.
struct Turn {
    int from, to;
};

// Up to this many faces at a vertex, plain scans beat sorting.
constexpr int kScanned = 16;

// The turn at a vertex leaving along `from`, or -1 when none or more than
// one does. Few turns are scanned whole, without a branch per turn.
int turnFrom(const Turn* turns, int count, int from) {
    if (count > kScanned) {
        const Turn* found =
            std::lower_bound(turns, turns + count, from, [](Turn t, int f) { return t.from < f; });
        return found != turns + count && found->from == from ? int(found - turns) : -1;
    }
    int found = -1, matches = 0;
    for (int i = 0; i < count; ++i) {
        const bool match = turns[i].from == from;
        matches += match;
        found = match ? i : found;
    }
    return matches == 1 ? found : -1;
}

// True when the turns at one vertex form a single cycle: following `to` ->
// the one turn with that `from` goes once round all of them (then their
// `from`s are distinct: a walk that met a turn twice before its first would
// never come back to it). Then each edge from the vertex is in one face each
// way, and the faces there make one fan (one disk, not two touching at the
// vertex).
bool oneFan(Turn* turns, int count) {
    if (count > kScanned) {
        std::sort(turns, turns + count, [](Turn a, Turn b) { return a.from < b.from; });
        for (int i = 1; i < count; ++i)
            if (turns[i].from == turns[i - 1].from)
                return false;
    }
    int at = 0;
    for (int step = 1; step <= count; ++step) {
        at = turnFrom(turns, count, turns[at].to);
        if (at < 0)
            return false;
        if (at == 0)
            return step == count;
    }
    return false;
}

}  // namespace

bool isClosedOrientedManifold(const TriMesh& mesh) {
    const int n = mesh.vertexCount();
    if (mesh.faces.empty())
        return false;
    // Each vertex's turns, packed: those of v at turns[start[v] .. start[v + 1]).
    std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);
    for (const auto& face : mesh.faces) {
        for (int v : face) {
            if (v < 0 || v >= n)
                return false;
            ++start[v + 1];
        }
        if (face[0] == face[1] || face[1] == face[2] || face[2] == face[0])
            return false;
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<Turn> turns(3 * mesh.faces.size());
    std::vector<int> cursor(start.begin(), start.end() - 1);
    for (const auto& face : mesh.faces) {
        turns[cursor[face[0]]++] = {face[1], face[2]};
        turns[cursor[face[1]]++] = {face[2], face[0]};
        turns[cursor[face[2]]++] = {face[0], face[1]};
    }
    for (int v = 0; v < n; ++v)
        if (start[v + 1] > start[v] && !oneFan(&turns[start[v]], start[v + 1] - start[v]))
            return false;
    return true;
}

}  // namespace rigmesh
