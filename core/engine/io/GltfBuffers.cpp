#include "io/GltfBuffers.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

#include "base/Error.h"

namespace rigmesh {
namespace {

using nlohmann::json;

json parseGltf(const std::string& text) {
    json gltf = json::parse(text, nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object())
        throw Error(MessageId::ExportGltfInvalidJson);
    return gltf;
}

std::uint32_t readU32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int b = 3; b >= 0; --b)  // little-endian
        value = (value << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(b)]);
    return value;
}

// Zeroes `data` outside every buffer view of buffer 0 in `gltf`.
void zeroUncovered(const json& gltf, char* data, std::size_t size) {
    std::vector<bool> covered(size, false);
    if (gltf.contains("bufferViews"))
        for (const json& view : gltf["bufferViews"]) {
            if (view.value("buffer", 0) != 0)
                continue;
            const std::size_t offset = view.value("byteOffset", std::size_t{0});
            const std::size_t length = view.value("byteLength", std::size_t{0});
            if (offset > size || length > size - offset)
                throw Error(MessageId::ExportGltfBufferViewOutside);
            std::fill(covered.begin() + static_cast<std::ptrdiff_t>(offset),
                      covered.begin() + static_cast<std::ptrdiff_t>(offset + length), true);
        }
    for (std::size_t i = 0; i < size; ++i)
        if (!covered[i])
            data[i] = 0;
}

void writeU32(std::string& bytes, std::size_t at, std::uint32_t value) {
    for (int b = 0; b < 4; ++b)  // little-endian
        bytes[at + static_cast<std::size_t>(b)] = static_cast<char>((value >> (8 * b)) & 0xFFu);
}

Error invalidGlb() {
    return Error("cannot export: the glTF exporter wrote an invalid .glb");
}

// Header (magic, version, length), then chunks of (length, type, data); the
// first chunk is the JSON. Returns the JSON chunk's length.
std::size_t checkedJsonLength(const std::string& glb) {
    if (glb.size() < 20 || glb.compare(0, 4, "glTF") != 0)
        throw invalidGlb();
    const std::size_t jsonLength = readU32(glb, 12);
    if (readU32(glb, 16) != 0x4E4F534Au || jsonLength > glb.size() - 20)
        throw invalidGlb();
    return jsonLength;
}

}  // namespace

std::string glbJson(const std::string& glb) {
    return glb.substr(20, checkedJsonLength(glb));
}

std::string glbWithJson(const std::string& glb, const std::string& json) {
    const std::size_t oldLength = checkedJsonLength(glb);
    std::string padded = json;
    padded.append((4 - padded.size() % 4) % 4, ' ');
    std::string out = glb.substr(0, 20) + padded + glb.substr(20 + oldLength);
    writeU32(out, 8, static_cast<std::uint32_t>(out.size()));
    writeU32(out, 12, static_cast<std::uint32_t>(padded.size()));
    return out;
}

GlbChunks splitGlb(const std::string& glb) {
    const std::size_t jsonLength = checkedJsonLength(glb);
    GlbChunks chunks;
    chunks.json = glb.substr(20, jsonLength);
    const std::size_t binHeader = 20 + jsonLength;
    if (binHeader == glb.size())
        return chunks;
    if (glb.size() - binHeader < 8 || readU32(glb, binHeader + 4) != 0x004E4942u)
        throw invalidGlb();
    const std::size_t binLength = readU32(glb, binHeader);
    if (binLength > glb.size() - binHeader - 8)
        throw invalidGlb();
    chunks.bin = glb.substr(binHeader + 8, binLength);
    return chunks;
}

std::string joinGlb(const GlbChunks& chunks) {
    std::string json = chunks.json, bin = chunks.bin;
    json.append((4 - json.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    std::string out(20, '\0');
    out.replace(0, 4, "glTF");
    writeU32(out, 4, 2);
    writeU32(out, 12, static_cast<std::uint32_t>(json.size()));
    writeU32(out, 16, 0x4E4F534Au);
    out += json;
    if (!bin.empty()) {
        std::string header(8, '\0');
        writeU32(header, 0, static_cast<std::uint32_t>(bin.size()));
        writeU32(header, 4, 0x004E4942u);
        out += header + bin;
    }
    writeU32(out, 8, static_cast<std::uint32_t>(out.size()));
    return out;
}

std::string zeroUnreferencedGlbBytes(std::string glb) {
    const std::size_t jsonLength = checkedJsonLength(glb);
    const auto invalid = invalidGlb;
    const json gltf = parseGltf(glb.substr(20, jsonLength));
    const std::size_t binHeader = 20 + jsonLength;
    if (binHeader == glb.size())
        return glb;  // no binary chunk
    if (glb.size() - binHeader < 8 || readU32(glb, binHeader + 4) != 0x004E4942u)
        throw invalid();
    const std::size_t binLength = readU32(glb, binHeader);
    if (binLength > glb.size() - binHeader - 8)
        throw invalid();
    zeroUncovered(gltf, glb.data() + binHeader + 8, binLength);
    return glb;
}

std::string zeroUnreferencedBinBytes(const std::string& gltfJson, std::string bin) {
    zeroUncovered(parseGltf(gltfJson), bin.data(), bin.size());
    return bin;
}

std::string withBufferUri(const std::string& gltfJson, const std::string& uri) {
    json gltf = parseGltf(gltfJson);
    if (!gltf.contains("buffers") || gltf["buffers"].empty())
        throw Error(MessageId::ExportGltfNoBuffer);
    gltf["buffers"][0]["uri"] = uri;
    return gltf.dump(2) + "\n";
}

std::string bufferUriOf(const std::string& gltfJson) {
    const json gltf = json::parse(gltfJson, nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object() || !gltf.contains("buffers") ||
        !gltf["buffers"].is_array() || gltf["buffers"].empty() || !gltf["buffers"][0].is_object())
        return "";
    const json& uri = gltf["buffers"][0].value("uri", json());
    return uri.is_string() ? uri.get<std::string>() : "";
}

}  // namespace rigmesh
