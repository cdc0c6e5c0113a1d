#include "model/ClipModes.h"

#include <array>
#include <utility>

namespace rigmesh::model {

namespace {

constexpr std::array<std::pair<rigmesh::Interpolation, const char*>, 3> kInterpolations{{
    {rigmesh::Interpolation::Constant, "constant"},
    {rigmesh::Interpolation::Linear, "linear"},
    {rigmesh::Interpolation::Smooth, "smooth"},
}};
constexpr std::array<std::pair<rigmesh::PlaybackMode, const char*>, 3> kPlaybacks{{
    {rigmesh::PlaybackMode::Hold, "hold"},
    {rigmesh::PlaybackMode::Loop, "loop"},
    {rigmesh::PlaybackMode::PingPong, "ping_pong"},
}};

template <typename Enum, std::size_t N>
const char* nameOf(const std::array<std::pair<Enum, const char*>, N>& table, Enum value) {
    for (const auto& [entry, name] : table)
        if (entry == value)
            return name;
    return table[0].second;
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const std::array<std::pair<Enum, const char*>, N>& table,
                            std::string_view name) {
    for (const auto& [entry, entryName] : table)
        if (name == entryName)
            return entry;
    return std::nullopt;
}

}  // namespace

const char* interpolationName(rigmesh::Interpolation interpolation) {
    return nameOf(kInterpolations, interpolation);
}

const char* playbackName(rigmesh::PlaybackMode mode) {
    return nameOf(kPlaybacks, mode);
}

std::optional<rigmesh::Interpolation> interpolationFromName(std::string_view name) {
    return valueOf(kInterpolations, name);
}

std::optional<rigmesh::PlaybackMode> playbackFromName(std::string_view name) {
    return valueOf(kPlaybacks, name);
}

}  // namespace rigmesh::model
