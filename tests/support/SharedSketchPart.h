// The rigged part of a shared sketch (sketchToPart with default options),
// built once per test binary.
#pragma once

#include <map>
#include <string>

#include "SketchToSurfaceTestSupport.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::testsupport {

inline const Part& sharedSketchPart(const std::string& sketch) {
    static std::map<std::string, Part> cache;
    auto found = cache.find(sketch);
    if (found == cache.end())
        found = cache.emplace(sketch, sketchToPart(sharedSketchPoints(sketch), sketch).part).first;
    return found->second;
}

}  // namespace rigmesh::testsupport
