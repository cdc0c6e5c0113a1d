// The error of a recipe step that cannot be applied. what() reads
//   step 3 (pose): part "arm" has no joint 42
// with the step's number (from 1), its command and the reason, a message of
// its own, so the studio shows the whole in the user's language.
#pragma once

#include <string>

#include "base/Error.h"

namespace rigmesh::model {

class RecipeError : public rigmesh::Error {
  public:
    RecipeError(int step, std::string command, Message reason);

    int step() const { return step_; }
    const std::string& command() const { return command_; }
    // The reason in English.
    std::string reason() const { return englishText(message().nested.front()); }

  private:
    int step_;
    std::string command_;
};

}  // namespace rigmesh::model
