// Shared helpers for the export/import tests: rigged parts built once from
// the shared sketches, scratch folders, and matching vertices by position.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "part/Part.h"
#include "pipeline/SketchToPart.h"
#include "pose/Clip.h"
#include "sketch/Sketch.h"

namespace rigmesh::iotest {

namespace fs = std::filesystem;

inline const Part& sharedPart(const std::string& name) {
    static std::map<std::string, Part> cache;
    auto it = cache.find(name);
    if (it == cache.end()) {
        const Sketch sketch =
            readSketchFile(std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json");
        it = cache.emplace(name, sketchToPart(sketch.points, name).part).first;
    }
    return it->second;
}

// An empty folder of its own per test.
inline fs::path scratchFolder() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)))
            c = '_';
    const fs::path folder = fs::temp_directory_path() / "rigmesh_test_io" / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

inline double meshSize(const TriMesh& mesh) {
    Vec3 lo = mesh.vertices.at(0), hi = lo;
    for (const Vec3& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    return (hi - lo).norm();
}

// For each vertex of `a`, the index of the nearest vertex of `b` (a uniform
// grid keeps it fast on the shared sketches' meshes).
std::vector<int> matchVertices(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace rigmesh::iotest
