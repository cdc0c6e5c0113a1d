#pragma once

namespace rigmesh {

// The engine's version, the project's version.
const char* engineVersion();

}  // namespace rigmesh
