#include "model/ClipModes.h"

namespace rigmesh::model {

const char* interpolationName(rigmesh::Interpolation interpolation) {
    return interpolation == rigmesh::Interpolation::Smooth ? "smooth" : "linear";
}

const char* playbackName(rigmesh::PlaybackMode mode) {
    return mode == rigmesh::PlaybackMode::Loop ? "loop" : "hold";
}

std::optional<rigmesh::Interpolation> interpolationFromName(std::string_view name) {
    if (name == "linear")
        return rigmesh::Interpolation::Linear;
    if (name == "smooth")
        return rigmesh::Interpolation::Smooth;
    return std::nullopt;
}

std::optional<rigmesh::PlaybackMode> playbackFromName(std::string_view name) {
    if (name == "hold")
        return rigmesh::PlaybackMode::Hold;
    if (name == "loop")
        return rigmesh::PlaybackMode::Loop;
    return std::nullopt;
}

}  // namespace rigmesh::model
