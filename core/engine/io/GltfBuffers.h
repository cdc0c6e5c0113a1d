// Post-export passes over Assimp 5.2.5's glTF output.
//
// Its glTF2 exporter writes the joint indices as 32-bit floats, converts them
// in place to 16-bit integers and shrinks the buffer view to half, but copies
// the whole float-sized region from a buffer it only half filled: 8 bytes per
// vertex of uninitialised heap memory end up in the file, referenced by no
// buffer view. These passes zero every byte no buffer view covers, so equal
// inputs give byte-identical files, and rename the .bin of a .gltf.
#pragma once

#include <string>

namespace rigmesh {

// A .glb file with every byte of its binary chunk that no buffer view covers
// set to zero. Throws Error if the bytes are not a glTF 2.0 binary file.
std::string zeroUnreferencedGlbBytes(std::string glb);

// The JSON chunk of a .glb. Throws Error if the bytes are not a glTF 2.0
// binary file.
std::string glbJson(const std::string& glb);

// The .glb with its JSON chunk replaced by `json` (padded with spaces to a
// multiple of 4 bytes, as the format requires), the binary chunk unchanged.
std::string glbWithJson(const std::string& glb, const std::string& json);

// A .glb's JSON text and binary chunk (empty if none), and back: the JSON
// padded with spaces and the binary chunk with zeros to multiples of 4.
// Throws Error if the bytes are not a glTF 2.0 binary file.
struct GlbChunks {
    std::string json;
    std::string bin;
};
GlbChunks splitGlb(const std::string& glb);
std::string joinGlb(const GlbChunks& chunks);

// The .bin buffer of a .gltf (buffer 0) with every byte no buffer view
// covers set to zero. Throws Error on JSON that is not glTF.
std::string zeroUnreferencedBinBytes(const std::string& gltfJson, std::string bin);

// The .gltf text with buffer 0's uri set to `uri`. Throws Error on JSON that
// is not glTF.
std::string withBufferUri(const std::string& gltfJson, const std::string& uri);

// The uri of buffer 0, or "" if none (or the text is not glTF JSON).
std::string bufferUriOf(const std::string& gltfJson);

}  // namespace rigmesh
