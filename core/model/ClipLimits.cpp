#include "model/ClipLimits.h"

#include <string>

#include "base/Error.h"

namespace rigmesh::model {

double clipSpanFrames(const rigmesh::Clip& clip) {
    if (clip.keyCount() == 0)
        return 0.0;
    const std::vector<double> times = clip.keyTimes();
    return (times.back() - times.front()) * clip.framesPerSecond();
}

void checkClipSpan(const rigmesh::Clip& clip, const std::string& owner) {
    if (!(clipSpanFrames(clip) <= kMaxClipFrames))
        throw Error("the clip of " + owner + " spans more than " +
                    std::to_string(static_cast<long>(kMaxClipFrames)) +
                    " frames from its first to its last key");
}

}  // namespace rigmesh::model
