// The error of a stroke that crosses itself, carrying where it crosses as
// data (in the stroke's coordinates), so a view can mark the place instead
// of parsing it out of the message, whose text names it for the command
// line.
#pragma once

#include "base/Error.h"
#include "base/Types.h"

namespace rigmesh {

class StrokeCrossingError : public Error {
  public:
    StrokeCrossingError(const Vec2& crossing, const std::string& crossingText)
        : Error(MessageId::StrokeCrossesItselfNear, crossingText), crossing_(crossing) {}

    // Where the stroke crosses itself.
    const Vec2& crossing() const { return crossing_; }

  private:
    Vec2 crossing_;
};

}  // namespace rigmesh
