// The rigged part of a shared sketch (sketchToPart with default options),
// built once per test binary. Sketches kept with the tests
// (tests/data/sketches: "quadruped") are found too.
#pragma once

#include <map>
#include <string>

#include "SketchToSurfaceTestSupport.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::testsupport {

inline std::string testDataSketchPath(const std::string& name) {
    return std::string(RIGMESH_TEST_DATA) + "/sketches/" + name + ".json";
}

inline const Part& sharedSketchPart(const std::string& sketch) {
    static std::map<std::string, Part> cache;
    auto found = cache.find(sketch);
    if (found == cache.end()) {
        const std::string path = std::filesystem::exists(sharedSketchPath(sketch))
                                     ? sharedSketchPath(sketch)
                                     : testDataSketchPath(sketch);
        found = cache.emplace(sketch, sketchToPart(readSketchFile(path).points, sketch).part).first;
    }
    return found->second;
}

}  // namespace rigmesh::testsupport
