// The weight of one bone at one vertex of a part (0 where it has none), for
// tests that check what painting and clean-ups did.
#pragma once

#include "part/Part.h"

namespace rigmesh::testsupport {

inline double weightOf(const Part& part, int vertex, BoneId bone) {
    for (const auto& [b, w] : part.weights.perVertex[vertex])
        if (b == bone)
            return w;
    return 0.0;
}

}  // namespace rigmesh::testsupport
