// Assimp's aiProcess_JoinIdenticalVertices, done in linear time. Assimp 5.2.5 runs that step on
// every glTF export (and we need it for FBX and COLLADA, docs/EXCHANGE.md rule 8), but its
// bone-weight update searches each bone's new weight list for every weight: quadratic in the
// vertices a bone influences (2.6 s at 110k vertices, about n^1.8). We join here with a hash map
// and tell the exporter that the step has been applied. Internal to io/: the header only
// forward-declares Assimp.
#pragma once

struct aiMesh;
struct aiScene;

namespace rigmesh {

// Merges vertices with bit-identical position, normal and skin weights into
// the first of them; faces and bone weights are renumbered. Linear in
// vertices, faces and weights; leaves a mesh without such duplicates, or with
// UVs, colours, tangents or morph targets (Assimp joins those itself),
// untouched.
void joinIdenticalVertices(aiMesh& mesh);

// Marks aiProcess_JoinIdenticalVertices as applied to `scene`, so that
// Assimp::Exporter skips it. Returns false (and changes nothing) unless the
// linked Assimp is the 5.2 series whose private scene data this relies on.
bool markVerticesJoined(aiScene& scene);

}  // namespace rigmesh
