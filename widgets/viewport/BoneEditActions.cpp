#include "viewport/BoneEditActions.h"

#include <QMenu>

#include "UserAction.h"
#include "base/Error.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/BoneEditCommand.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

struct BoneUnder {
    model::PartId part = model::kNoPart;
    BoneId bone = 0;
    Vec3 at = Vec3::Zero();  // on the rest bone, document coordinates
};

std::optional<BoneUnder> boneUnder(const Viewport& viewport, const QPointF& pixel) {
    const std::optional<BoneHit> hit = viewport.boneAt(pixel);
    if (!hit)
        return std::nullopt;
    const model::PartNode& node = viewport.document()->part(hit->part);
    const Skeleton& skeleton = node.part->skeleton;
    for (const Bone& bone : skeleton.bones()) {
        if (!((bone.head == hit->from && bone.tail == hit->to) ||
              (bone.head == hit->to && bone.tail == hit->from)))
            continue;
        // Where along the bone as drawn (posed) the cursor is, applied to
        // the rest bone the edit works on.
        const QSizeF size(viewport.size());
        const QVector3D a =
            viewport.camera().project(viewport.jointWorldPosition(hit->part, bone.head), size);
        const QVector3D b =
            viewport.camera().project(viewport.jointWorldPosition(hit->part, bone.tail), size);
        const Vec2 ab(b.x() - a.x(), b.y() - a.y());
        const Vec2 ap(pixel.x() - a.x(), pixel.y() - a.y());
        const double t =
            ab.squaredNorm() > 0.0 ? std::clamp(ap.dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.5;
        const Vec3 rest =
            (1.0 - t) * skeleton.joint(bone.head).position + t * skeleton.joint(bone.tail).position;
        return BoneUnder{hit->part, bone.id, node.placement.toWorld(rest)};
    }
    return std::nullopt;
}

template <typename Make>
bool pushEdit(Viewport& viewport, Make&& make) {
    model::Document& document = *viewport.document();
    runUserAction(
        {},
        [&](const QString& failure) {
            emit viewport.statusMessage(Viewport::tr("Bone not changed: %1").arg(failure));
        },
        [&] {
            std::unique_ptr<model::BoneEditCommand> command = make(document);
            const QString summary = command->summary();
            model::pushCommand(document, std::move(command));
            emit viewport.statusMessage(summary);
        });
    viewport.update();
    return true;
}

}  // namespace

bool splitBoneUnder(Viewport& viewport, const QPointF& pixel) {
    const std::optional<BoneUnder> under = boneUnder(viewport, pixel);
    if (!under)
        return false;
    return pushEdit(viewport, [&](model::Document& document) {
        return model::BoneEditCommand::split(document, under->part, under->bone, under->at);
    });
}

bool deleteBoneUnder(Viewport& viewport, const QPointF& pixel) {
    const std::optional<BoneUnder> under = boneUnder(viewport, pixel);
    if (!under)
        return false;
    return pushEdit(viewport, [&](model::Document& document) {
        return model::BoneEditCommand::remove(document, under->part, under->bone);
    });
}

bool showBoneMenu(Viewport& viewport, const QPointF& pixel, const QPoint& globalPosition) {
    const std::optional<BoneUnder> under = boneUnder(viewport, pixel);
    if (!under)
        return false;
    QMenu menu(&viewport);
    QAction* split = menu.addAction(Viewport::tr("Split Bone Here"));
    split->setShortcut(QKeySequence(Qt::Key_K));
    QAction* remove = menu.addAction(Viewport::tr("Delete Bone"));
    remove->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_K));
    // A disconnected bone (Skeleton.h) can be connected to its parent.
    const Skeleton& skeleton = viewport.document()->part(under->part).part->skeleton;
    QAction* connectBone = nullptr;
    if (skeleton.isAttached(skeleton.bone(under->bone).head))
        connectBone = menu.addAction(Viewport::tr("Connect Bone"));
    QAction* chosen = menu.exec(globalPosition);
    if (chosen == split)
        splitBoneUnder(viewport, pixel);
    else if (chosen == remove)
        deleteBoneUnder(viewport, pixel);
    else if (chosen != nullptr && chosen == connectBone)
        pushEdit(viewport, [&](model::Document& document) {
            return model::BoneEditCommand::connect(document, under->part, under->bone);
        });
    return true;
}

}  // namespace rigmesh::widgets
