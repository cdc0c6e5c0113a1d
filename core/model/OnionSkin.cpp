#include "model/OnionSkin.h"

#include <iterator>

namespace rigmesh::model {

OnionPoses onionPoses(const Document& document, PartId part) {
    const rigmesh::Clip& clip = document.part(part).clip;
    const auto& keys = clip.keys();
    const double now = document.currentTime();
    const double half = 0.5 / document.timeline().framesPerSecond;
    OnionPoses out;
    const auto after = keys.upper_bound(now + half);
    if (after != keys.end())
        out.next = &after->second;
    auto before = keys.lower_bound(now - half);
    if (before != keys.begin())
        out.previous = &std::prev(before)->second;
    return out;
}

}  // namespace rigmesh::model
