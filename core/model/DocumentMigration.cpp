#include "model/DocumentMigration.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>

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

// The weight notes as ids and arguments (part/PartJson.cpp) from the English
// sentence rig/BoneHeatSolver wrote into version 5 and older files.
json weightWarningsFromEnglish(const std::string& sentence) {
    json out = json::array();
    std::smatch match;
    if (sentence.find("could not be factored") != std::string::npos) {
        out.push_back({{"id", "notFactored"}, {"args", json::array()}});
    } else if (std::regex_search(sentence, match,
                                 std::regex("could not be solved for bone(s?) ([0-9, ]+)"))) {
        out.push_back({{"id", match[1].length() > 0 ? "bonesUnsolved" : "boneUnsolved"},
                       {"args", json::array({match[2].str()})}});
    }
    if (std::regex_search(sentence, match, std::regex("([0-9]+) vertices see no bone")))
        out.push_back({{"id", "verticesSeeNoBone"}, {"args", json::array({match[1].str()})}});
    return out;
}

void weightWarningsAsIds(json& root) {
    if (!root.contains("parts") || !root["parts"].is_array())
        return;  // the reader says what is missing
    for (json& node : root["parts"]) {
        if (!node.is_object() || !node.contains("part") || !node["part"].is_object())
            continue;
        json& part = node["part"];
        if (!part.contains("weights") || !part["weights"].is_object())
            continue;
        json& weights = part["weights"];
        if (!weights.contains("warning") || !weights["warning"].is_string())
            continue;
        weights["warnings"] = weightWarningsFromEnglish(weights["warning"].get<std::string>());
        weights.erase("warning");
    }
}

}  // namespace

void migrateDocument(json& root, std::int64_t version) {
    if (version < 3)
        addTimelineAndClipList(root);
    if (version < 6)
        weightWarningsAsIds(root);
}

}  // namespace rigmesh::model
