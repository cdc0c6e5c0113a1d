#include "model/DocumentMigration.h"

#include <algorithm>
#include <cmath>

#include "model/Timeline.h"

namespace rigmesh::model {

namespace {

using nlohmann::json;

// A number from an unchecked tree, or `fallback` when it is not a finite one.
double numberOr(const json& object, const char* key, double fallback) {
    if (!object.is_object() || !object.contains(key) || !object[key].is_number())
        return fallback;
    const double value = object[key].get<double>();
    return std::isfinite(value) ? value : fallback;
}

void addTimelineAndClipList(json& root) {
    if (!root.contains("parts") || !root["parts"].is_array())
        return;  // the reader says what is missing
    json& parts = root["parts"];
    double rate = 24.0;
    if (!parts.empty() && parts[0].is_object() && parts[0].contains("clip"))
        rate = numberOr(parts[0]["clip"], "framesPerSecond", rate);
    rate = std::clamp(rate, kMinFrameRate, kMaxFrameRate);
    double lastFrame = 48;
    for (json& part : parts) {
        if (!part.is_object())
            continue;
        part["otherClips"] = json::array();
        if (!part.contains("clip") || !part["clip"].is_object() || !part["clip"].contains("keys") ||
            !part["clip"]["keys"].is_array())
            continue;
        for (const json& key : part["clip"]["keys"])
            lastFrame = std::max(lastFrame, std::ceil(numberOr(key, "time", 0.0) * rate));
    }
    root["timeline"] = {{"startFrame", 0},
                        {"endFrame", static_cast<int>(std::min<double>(lastFrame, kMaxFrame))},
                        {"framesPerSecond", rate},
                        {"currentFrame", 0}};
}

}  // namespace

void migrateDocument(json& root, std::int64_t version) {
    if (version < 3)
        addTimelineAndClipList(root);
}

}  // namespace rigmesh::model
