// Skeleton refinement from the view (paper 3.3): right-click a bone for
// Split Bone Here and Delete Bone; K splits the bone under the cursor at the
// cursor, Shift+K deletes it. Each pushes a BoneEditCommand (one undo step)
// and says in the status bar what was solved again and how long it took.
#pragma once

#include <QPoint>
#include <QPointF>

namespace rigmesh::widgets {

class Viewport;

// False (and nothing changes) if no bone is under the pixel.
bool splitBoneUnder(Viewport& viewport, const QPointF& pixel);
bool deleteBoneUnder(Viewport& viewport, const QPointF& pixel);
// The context menu for the bone under `pixel`; returns false if there is none.
bool showBoneMenu(Viewport& viewport, const QPointF& pixel, const QPoint& globalPosition);

}  // namespace rigmesh::widgets
