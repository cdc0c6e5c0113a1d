// Vertex positions, by index, read straight from the mesh files `rigmesh
// build` writes, with small readers of our own: the point is to see the
// order in the file, which importers (Assimp's among them) may change.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "CliRunner.h"

namespace rigmesh::test {

using Positions = std::vector<std::array<double, 3>>;

// "v x y z" lines in file order.
inline Positions objPositions(const std::filesystem::path& path) {
    std::istringstream in(readWholeFile(path));
    Positions positions;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("v ", 0) != 0)
            continue;
        std::istringstream fields(line.substr(2));
        std::array<double, 3> p{};
        fields >> p[0] >> p[1] >> p[2];
        positions.push_back(p);
    }
    return positions;
}

// "OFF", the counts, then one vertex per line.
inline Positions offPositions(const std::filesystem::path& path) {
    std::istringstream in(readWholeFile(path));
    std::string magic;
    std::size_t vertices = 0, faces = 0, edges = 0;
    in >> magic >> vertices >> faces >> edges;
    if (magic != "OFF")
        throw std::runtime_error("not an OFF file: " + path.string());
    Positions positions(vertices);
    for (auto& p : positions) {
        in >> p[0] >> p[1] >> p[2];
        std::string rest;
        std::getline(in, rest);  // colours, if any
    }
    return positions;
}

// Binary little-endian PLY whose first element is the vertex.
inline Positions plyPositions(const std::filesystem::path& path) {
    const std::string bytes = readWholeFile(path);
    const std::size_t headerEnd = bytes.find("end_header\n");
    if (headerEnd == std::string::npos)
        throw std::runtime_error("no PLY header in " + path.string());
    std::istringstream header(bytes.substr(0, headerEnd));
    std::size_t count = 0, stride = 0;
    std::array<std::size_t, 3> offset{};
    std::array<bool, 3> isDouble{};
    bool inVertex = false;
    for (std::string line; std::getline(header, line);) {
        std::istringstream fields(line);
        std::string keyword, type, name;
        fields >> keyword;
        if (keyword == "format" && line.find("binary_little_endian") == std::string::npos)
            throw std::runtime_error("not a binary little-endian PLY: " + path.string());
        if (keyword == "element") {
            std::size_t elements = 0;
            fields >> name >> elements;
            if (name != "vertex" && !inVertex && stride == 0)
                throw std::runtime_error("the PLY's first element is not the vertex");
            inVertex = name == "vertex";
            if (inVertex)
                count = elements;
        } else if (keyword == "property" && inVertex) {
            fields >> type >> name;
            const std::size_t size =
                type == "double" || type == "float64"                                        ? 8
                : type == "float" || type == "float32"                                       ? 4
                : type == "int" || type == "uint" || type == "int32" || type == "uint32"     ? 4
                : type == "short" || type == "ushort" || type == "int16" || type == "uint16" ? 2
                                                                                             : 1;
            const int axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
            if (axis >= 0) {
                offset[static_cast<std::size_t>(axis)] = stride;
                isDouble[static_cast<std::size_t>(axis)] = size == 8;
            }
            stride += size;
        }
    }
    const std::size_t start = headerEnd + std::strlen("end_header\n");
    Positions positions;
    for (std::size_t v = 0; v < count; ++v) {
        std::array<double, 3> p{};
        for (std::size_t k = 0; k < 3; ++k) {
            const char* at = bytes.data() + start + v * stride + offset[k];
            if (isDouble[k]) {
                std::memcpy(&p[k], at, 8);
            } else {
                float f = 0;
                std::memcpy(&f, at, 4);
                p[k] = f;
            }
        }
        positions.push_back(p);
    }
    return positions;
}

// The POSITION accessor of the first primitive of the first mesh.
inline Positions gltfPositions(const nlohmann::json& gltf, const std::string& bin) {
    const auto& primitive = gltf.at("meshes").at(0).at("primitives").at(0);
    const auto& accessor =
        gltf.at("accessors").at(primitive.at("attributes").at("POSITION").get<int>());
    const auto& view = gltf.at("bufferViews").at(accessor.at("bufferView").get<int>());
    if (accessor.at("componentType").get<int>() != 5126 || accessor.at("type") != "VEC3")
        throw std::runtime_error("POSITION is not VEC3 of floats");
    const std::size_t start =
        view.value("byteOffset", std::size_t{0}) + accessor.value("byteOffset", std::size_t{0});
    const std::size_t stride = view.value("byteStride", std::size_t{12});
    Positions positions;
    for (std::size_t v = 0; v < accessor.at("count").get<std::size_t>(); ++v) {
        float xyz[3];
        std::memcpy(xyz, bin.data() + start + v * stride, sizeof xyz);
        positions.push_back({xyz[0], xyz[1], xyz[2]});
    }
    return positions;
}

inline Positions gltfFilePositions(const std::filesystem::path& path) {
    const auto gltf = nlohmann::json::parse(readWholeFile(path));
    const std::string uri = gltf.at("buffers").at(0).at("uri");
    return gltfPositions(gltf, readWholeFile(path.parent_path() / uri));
}

// GLB: 12-byte header, then the JSON chunk and the BIN chunk.
inline Positions glbPositions(const std::filesystem::path& path) {
    const std::string bytes = readWholeFile(path);
    auto u32 = [&](std::size_t at) {
        std::uint32_t value = 0;
        std::memcpy(&value, bytes.data() + at, 4);
        return std::size_t{value};
    };
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0)
        throw std::runtime_error("not a GLB: " + path.string());
    const std::size_t jsonLength = u32(12);
    const auto gltf = nlohmann::json::parse(bytes.substr(20, jsonLength));
    const std::size_t binAt = 20 + jsonLength;
    return gltfPositions(gltf, bytes.substr(binAt + 8, u32(binAt)));
}

// Binary FBX: the first "Vertices" record's double array (uncompressed).
inline Positions fbxPositions(const std::filesystem::path& path) {
    const std::string bytes = readWholeFile(path);
    if (bytes.compare(0, 18, "Kaydara FBX Binary") != 0)
        throw std::runtime_error("not a binary FBX: " + path.string());
    std::uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 23, 4);
    const bool wide = version >= 7500;
    auto read = [&](std::size_t at, std::size_t size) {
        std::uint64_t value = 0;
        std::memcpy(&value, bytes.data() + at, size);
        return static_cast<std::size_t>(value);
    };
    const std::size_t field = wide ? 8 : 4;
    // Depth-first over the records in [at, end); returns the array's offset.
    auto find = [&](auto&& self, std::size_t at, std::size_t end) -> std::size_t {
        while (at + 3 * field + 1 <= end) {
            const std::size_t recordEnd = read(at, field);
            if (recordEnd == 0)
                return 0;  // null record: end of this list
            const std::size_t propertyBytes = read(at + 2 * field, field);
            const std::size_t nameLength = read(at + 3 * field, 1);
            const std::size_t nameAt = at + 3 * field + 1;
            const std::size_t properties = nameAt + nameLength;
            if (bytes.compare(nameAt, nameLength, "Vertices") == 0 && nameLength == 8)
                return properties;
            if (const std::size_t found = self(self, properties + propertyBytes, recordEnd))
                return found;
            at = recordEnd;
        }
        return 0;
    };
    const std::size_t array = find(find, 27, bytes.size());
    if (array == 0 || bytes[array] != 'd')
        throw std::runtime_error("no Vertices double array in " + path.string());
    const std::size_t length = read(array + 1, 4);
    if (read(array + 5, 4) != 0)
        throw std::runtime_error("the FBX vertex array is compressed");
    Positions positions(length / 3);
    for (std::size_t i = 0; i < length; ++i)
        std::memcpy(&positions[i / 3][i % 3], bytes.data() + array + 13 + 8 * i, 8);
    return positions;
}

// COLLADA: the first <float_array> whose id ends in "positions-array".
inline Positions daePositions(const std::filesystem::path& path) {
    const std::string text = readWholeFile(path);
    const std::size_t id = text.find("positions-array\"");
    if (id == std::string::npos)
        throw std::runtime_error("no positions array in " + path.string());
    const std::size_t open = text.find('>', id) + 1;
    std::istringstream numbers(text.substr(open, text.find('<', open) - open));
    Positions positions;
    for (std::array<double, 3> p{}; numbers >> p[0] >> p[1] >> p[2];)
        positions.push_back(p);
    return positions;
}

}  // namespace rigmesh::test
