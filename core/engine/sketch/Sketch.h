// A user's sketched stroke as read from a file: an ordered list of points,
// y up, not yet cleaned (see StrokeCleaner.h).
#pragma once

#include <string>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct Sketch {
    std::string name;
    std::vector<rigmesh::Vec2> points;
};

// Reads {"name": ..., "description": ..., "points": [[x, y], ...]}. The name
// falls back to the file stem of `sourceName`, which also names the input in
// error messages. Bare NaN / Infinity tokens, which some writers emit, are read
// as non-finite coordinates (the stroke cleaner rejects them); null, strings
// and other non-numbers are errors. Throws rigmesh::Error.
Sketch parseSketchJson(const std::string& text, const std::string& sourceName);

// Reads the first path, polyline or polygon element of an SVG document (in
// document order, also inside groups, not inside defs, clip paths, masks,
// markers, patterns or symbols). Curves are flattened, the transforms of the
// element and its ancestors applied and y flipped so the result is y-up.
// Only the first subpath counts. Throws rigmesh::Error.
Sketch parseSketchSvg(const std::string& text, const std::string& sourceName);

// Reads a .json or .svg file (by extension, case-insensitive). Throws
// rigmesh::Error for other extensions and unreadable files.
Sketch readSketchFile(const std::string& path);

}  // namespace rigmesh
