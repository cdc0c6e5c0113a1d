#include "io/ObjSceneText.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <cstdio>
#include <string>

namespace rigmesh {
namespace {

// Nine significant digits print every float exactly (it round-trips).
void appendTriple(std::string& out, const char* tag, float x, float y, float z) {
    char line[128];
    std::snprintf(line, sizeof line, "%s %.9g %.9g %.9g\n", tag, static_cast<double>(x),
                  static_cast<double>(y), static_cast<double>(z));
    out += line;
}

std::string materialName(const aiScene& scene, unsigned index) {
    aiString name;
    if (index < scene.mNumMaterials &&
        scene.mMaterials[index]->Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS && name.length > 0)
        return name.C_Str();
    return "material" + std::to_string(index);
}

struct ObjWriter {
    const aiScene& scene;
    std::string obj;
    unsigned written = 0;  // vertices written so far (OBJ indices are global)

    void writeMesh(const aiMesh& mesh, const aiMatrix4x4& transform, const std::string& name) {
        obj += "o " + name + "\n";
        aiMatrix3x3 normalTransform(transform);
        normalTransform.Inverse().Transpose();
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = transform * mesh.mVertices[v];
            appendTriple(obj, "v", p.x, p.y, p.z);
        }
        const bool normals = mesh.mNormals != nullptr;
        if (normals)
            for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
                const aiVector3D n = (normalTransform * mesh.mNormals[v]).NormalizeSafe();
                appendTriple(obj, "vn", n.x, n.y, n.z);
            }
        obj += "usemtl " + materialName(scene, mesh.mMaterialIndex) + "\n";
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices < 3)
                continue;  // points and lines: our exports have none
            obj += "f";
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const std::string index = std::to_string(written + face.mIndices[k] + 1);
                obj += " " + index + (normals ? "//" + index : "");
            }
            obj += "\n";
        }
        written += mesh.mNumVertices;
    }

    void writeNode(const aiNode& node, const aiMatrix4x4& parent) {
        const aiMatrix4x4 transform = parent * node.mTransformation;
        for (unsigned m = 0; m < node.mNumMeshes; ++m) {
            const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
            const std::string name =
                mesh.mName.length > 0 ? mesh.mName.C_Str() : node.mName.C_Str();
            writeMesh(mesh, transform, name);
        }
        for (unsigned c = 0; c < node.mNumChildren; ++c)
            writeNode(*node.mChildren[c], transform);
    }
};

}  // namespace

ObjText objSceneText(const aiScene& scene, const std::string& mtlFileName) {
    ObjWriter writer{scene, "# RigMesh Studio\nmtllib " + mtlFileName + "\n"};
    if (scene.mRootNode != nullptr)
        writer.writeNode(*scene.mRootNode, aiMatrix4x4());
    ObjText text;
    text.obj = std::move(writer.obj);
    text.mtl = "# RigMesh Studio\n";
    for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
        aiColor3D diffuse(0.8f, 0.8f, 0.8f);
        scene.mMaterials[m]->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse);
        text.mtl += "newmtl " + materialName(scene, m) + "\n";
        appendTriple(text.mtl, "Kd", diffuse.r, diffuse.g, diffuse.b);
    }
    return text;
}

}  // namespace rigmesh
