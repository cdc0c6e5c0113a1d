// The one exception type the engine throws at its boundary. Its message is
// written for the user: it says what is wrong with their input and, where it
// helps, what to do instead.
#pragma once

#include <stdexcept>
#include <string>

namespace rigmesh {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace rigmesh
