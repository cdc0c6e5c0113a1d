#include "base/Version.h"

namespace rigmesh {

const char* engineVersion() { return "0.1.0"; }

}  // namespace rigmesh
