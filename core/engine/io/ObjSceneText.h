// Wavefront OBJ (+ MTL) text of an export scene, written by us rather than by
// Assimp's ObjExporter. Assimp's exporter numbers the positions it
// writes in the order the faces first use them (ObjExporter::GetMeshes'
// vertex map), so vertex i of the .obj was not vertex i of the part: only 54%
// of an octopus's indices matched the rig JSON and the other formats. Here
// every mesh's vertices are written in their own order, one "v" and one "vn"
// line each, faces as "f a//a b//b c//c", so every output of one build
// indexes the same vertices. Internal to io/: the header only forward-declares
// Assimp.
#pragma once

#include <string>

struct aiScene;

namespace rigmesh {

struct ObjText {
    std::string obj;
    std::string mtl;
};

// The meshes of `scene` in node order (depth first), each placed by its
// node's global transform, as one object per mesh node; `mtlFileName` is
// named by the obj's mtllib line. Materials by name, with their diffuse
// colour.
ObjText objSceneText(const aiScene& scene, const std::string& mtlFileName);

}  // namespace rigmesh
