// The records of a binary FBX file as the post-export passes read and
// rewrite them (io/FbxSentinels, io/FbxRotationCurves). Binary FBX node
// record: end offset (absolute), property count, property list length, name
// length (1 byte), name, properties, then the nested records terminated by
// a null record (fields of 32 bits before version 7500, 64 bits from it).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rigmesh {

struct FbxRecord {
    std::vector<std::uint8_t> body;  // property count .. properties (no end offset)
    std::vector<FbxRecord> children;
    std::string name;
    bool noProperties = false;
    bool nested = false;  // had a nested list (possibly only a null record)

    // The FBX SDK's rule (as Blender's encode_bin.py writes it): a nested
    // list, hence a null record, for a node with children, a node without
    // properties, and always for AnimationStack and AnimationLayer (Assimp's
    // reader drops the animation otherwise: "expected compound scope").
    bool needsNullRecord() const {
        return nested || !children.empty() || noProperties || name == "AnimationStack" ||
               name == "AnimationLayer";
    }
};

// The top-level records of a binary FBX, and where the footer starts.
struct FbxFile {
    bool wide = false;  // 64-bit fields (version >= 7500)
    std::vector<FbxRecord> top;
    std::size_t footer = 0;
};

// Throws Error if the bytes are not a binary FBX or a record is out of range.
FbxFile parseFbx(const std::vector<std::uint8_t>& file);
// The file again (its header and footer from `file`), every nested list
// closed by a null record by the rule above.
std::vector<std::uint8_t> writeFbx(const std::vector<std::uint8_t>& file, const FbxFile& fbx);

// One property of a record: its type code and where its data starts in the
// record's body (after the type code).
struct FbxProperty {
    char type = 0;
    std::size_t at = 0;
};
// The properties of `record` in order; empty when they do not parse.
std::vector<FbxProperty> fbxProperties(const FbxRecord& record, bool wide);

// The text of a string property ('S': a 4-byte length, then the bytes) of
// `record`, as fbxProperties found it.
inline std::string fbxStringAt(const FbxRecord& record, const FbxProperty& property) {
    std::uint32_t length = 0;
    for (std::size_t i = 0; i < 4; ++i)
        length |= std::uint32_t(record.body[property.at + i]) << (8 * i);
    const auto from = record.body.begin() + static_cast<std::ptrdiff_t>(property.at + 4);
    return std::string(from, from + length);
}

// Appends the `bytes` low bytes of `value`, least significant first (FBX
// numbers are little-endian).
inline void putFbxLittleEndian(std::vector<std::uint8_t>& out, std::uint64_t value,
                               std::size_t bytes) {
    for (std::size_t i = 0; i < bytes; ++i)
        out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

}  // namespace rigmesh
