#include "io/FbxRotationCurves.h"

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <string>

#include "io/FbxRecords.h"

namespace rigmesh {
namespace {

template <typename T>
T readLittle(const std::vector<std::uint8_t>& bytes, std::size_t at) {
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof value);  // FBX is little-endian, as we are
    return value;
}

// A curve's values: where its KeyValueFloat array's floats are, and how many.
struct CurveValues {
    FbxRecord* record = nullptr;  // the KeyValueFloat record
    std::size_t at = 0;
    std::size_t count = 0;
};

std::optional<CurveValues> floatValues(FbxRecord& curve, bool wide) {
    for (FbxRecord& child : curve.children) {
        if (child.name != "KeyValueFloat")
            continue;
        const std::vector<FbxProperty> properties = fbxProperties(child, wide);
        if (properties.size() != 1 || properties[0].type != 'f')
            return std::nullopt;
        const std::size_t at = properties[0].at;
        const auto count = readLittle<std::uint32_t>(child.body, at);
        const auto encoding = readLittle<std::uint32_t>(child.body, at + 4);
        if (encoding != 0)  // compressed: not what Assimp writes
            return std::nullopt;
        return CurveValues{&child, at + 12, count};
    }
    return std::nullopt;
}

// Of the Euler triples equal to `angles` (degrees), the one nearest `previous`.
std::array<double, 3> nearestEquivalent(const std::array<double, 3>& angles,
                                        const std::array<double, 3>& previous) {
    const std::array<std::array<double, 3>, 2> bases = {
        angles, std::array<double, 3>{angles[0] + 180.0, 180.0 - angles[1], angles[2] + 180.0}};
    std::array<double, 3> best = angles;
    double bestDistance = INFINITY;
    for (std::array<double, 3> candidate : bases) {
        double distance = 0;
        for (int k = 0; k < 3; ++k) {
            candidate[k] += 360.0 * std::round((previous[k] - candidate[k]) / 360.0);
            distance = std::max(distance, std::abs(candidate[k] - previous[k]));
        }
        if (distance < bestDistance) {
            bestDistance = distance;
            best = candidate;
        }
    }
    return best;
}

}  // namespace

void makeFbxRotationsContinuous(FbxFile& fbx) {
    // Curve node ids of rotations, curves by id, and which component of
    // which curve node each curve drives (Connections: C "OP" curve node "d|X").
    std::map<std::int64_t, std::array<std::int64_t, 3>> rotationNodes;
    std::map<std::int64_t, FbxRecord*> curves;
    for (FbxRecord& objects : fbx.top) {
        if (objects.name != "Objects")
            continue;
        for (FbxRecord& object : objects.children) {
            const std::vector<FbxProperty> properties = fbxProperties(object, fbx.wide);
            if (properties.size() < 2 || properties[0].type != 'L' || properties[1].type != 'S')
                continue;
            const auto id = readLittle<std::int64_t>(object.body, properties[0].at);
            if (object.name == "AnimationCurveNode" &&
                fbxStringAt(object, properties[1]).starts_with(std::string("R\0\1", 3)))
                rotationNodes.emplace(id, std::array<std::int64_t, 3>{0, 0, 0});
            else if (object.name == "AnimationCurve")
                curves.emplace(id, &object);
        }
    }
    for (const FbxRecord& connections : fbx.top) {
        if (connections.name != "Connections")
            continue;
        for (const FbxRecord& link : connections.children) {
            const std::vector<FbxProperty> properties = fbxProperties(link, fbx.wide);
            if (properties.size() != 4 || properties[0].type != 'S' || properties[1].type != 'L' ||
                properties[2].type != 'L' || properties[3].type != 'S' ||
                fbxStringAt(link, properties[0]) != "OP")
                continue;
            const auto node =
                rotationNodes.find(readLittle<std::int64_t>(link.body, properties[2].at));
            const std::string component = fbxStringAt(link, properties[3]);
            if (node == rotationNodes.end() || component.size() != 3 ||
                component.substr(0, 2) != "d|" || component[2] < 'X' || component[2] > 'Z')
                continue;
            node->second[static_cast<std::size_t>(component[2] - 'X')] =
                readLittle<std::int64_t>(link.body, properties[1].at);
        }
    }
    for (const auto& [node, ids] : rotationNodes) {
        std::array<CurveValues, 3> values;
        bool complete = true;
        for (int k = 0; k < 3 && complete; ++k) {
            const auto curve = curves.find(ids[static_cast<std::size_t>(k)]);
            std::optional<CurveValues> found;
            if (curve != curves.end())
                found = floatValues(*curve->second, fbx.wide);
            complete = found && (k == 0 || found->count == values[0].count);
            if (complete)
                values[static_cast<std::size_t>(k)] = *found;
        }
        if (!complete)
            continue;
        std::array<double, 3> previous{};
        for (std::size_t key = 0; key < values[0].count; ++key) {
            std::array<double, 3> angles;
            for (std::size_t k = 0; k < 3; ++k)
                angles[k] = readLittle<float>(values[k].record->body, values[k].at + 4 * key);
            if (key > 0)
                angles = nearestEquivalent(angles, previous);
            previous = angles;
            for (std::size_t k = 0; k < 3; ++k) {
                const auto single = static_cast<float>(angles[k]);
                std::memcpy(values[k].record->body.data() + values[k].at + 4 * key, &single, 4);
            }
        }
    }
}

std::vector<std::uint8_t> withContinuousFbxRotations(const std::vector<std::uint8_t>& file) {
    FbxFile fbx = parseFbx(file);
    makeFbxRotationsContinuous(fbx);
    return writeFbx(file, fbx);
}

}  // namespace rigmesh
