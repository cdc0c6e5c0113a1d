// Whether a validate() result (Part::validate, Skeleton::validate) says
// something, in English: a test names the problem it expects by words of it.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "base/Message.h"

namespace rigmesh::testsupport {

inline bool mentions(const std::vector<Message>& problems, const std::string& words) {
    return std::any_of(problems.begin(), problems.end(), [&](const Message& problem) {
        return englishText(problem).find(words) != std::string::npos;
    });
}

}  // namespace rigmesh::testsupport
