// The files named on the studio's command line (rigmesh-studio FILE ...),
// opened as a desktop's "Open With" expects: a RigMesh document as File >
// Open does, any other file (glTF, FBX, OBJ, ...) imported into a new
// document as File > Import does (one undo step), as Blender opens a .blend
// and imports the rest.
#pragma once

#include <QString>

namespace rigmesh::widgets {

class MainWindow;

// Opens or imports `path` in `window`; a missing or unreadable file is
// refused with a message naming it (a file that is no 3D scene is refused
// by the import, with its reason).
void openFromCommandLine(MainWindow& window, const QString& path);

}  // namespace rigmesh::widgets
