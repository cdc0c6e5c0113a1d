// How a long rigging step reports how far it got and learns that the user
// cancelled: the engine has no Qt, so a plain callback.
#pragma once

#include <functional>

#include "base/Error.h"

namespace rigmesh {

// Called now and then with the fraction done (0..1); returns false to stop.
using RigProgress = std::function<bool(double fraction)>;

// Reports `fraction` and throws Error(AutoRigCancelled) when told to stop.
inline void reportRigProgress(const RigProgress& progress, double fraction) {
    if (progress && !progress(fraction))
        throw Error(MessageId::AutoRigCancelled);
}

}  // namespace rigmesh
