// The error of a recipe step that cannot be applied. what() reads
//   step 3 (pose): part "arm" has no joint 42
// with the step's number (from 1), its command and the reason.
#pragma once

#include <string>

#include "base/Error.h"

namespace rigmesh::model {

class RecipeError : public rigmesh::Error {
  public:
    RecipeError(int step, std::string command, std::string reason);

    int step() const { return step_; }
    const std::string& command() const { return command_; }
    const std::string& reason() const { return reason_; }

  private:
    int step_;
    std::string command_;
    std::string reason_;
};

}  // namespace rigmesh::model
