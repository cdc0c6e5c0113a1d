#include "timeline/TimelineView.h"

#include <QHelpEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "UserAction.h"
#include "timeline/KeyDrag.h"

namespace rigmesh::widgets {

namespace {

constexpr int kHeaderWidth = 170;
constexpr int kRulerHeight = 24;
constexpr int kRowHeight = 20;
constexpr double kDiamond = 5.5;     // half diagonal of a part key
constexpr double kPickRadius = 7.0;  // pixels around a diamond that pick it
constexpr double kDragThreshold = 3.0;

const QColor kBackground(0x2b, 0x2c, 0x2f);
const QColor kOutOfRange(0x23, 0x23, 0x26);
const QColor kRowLine(0x38, 0x39, 0x3d);
const QColor kHeader(0x33, 0x34, 0x38);
const QColor kText(0xd8, 0xd8, 0xd8);
const QColor kCursor(0x47, 0x8c, 0xe6);  // Blender's playhead blue
const QColor kKey(0xe0, 0xe0, 0xe0);
const QColor kSelectedKey(0xff, 0xa0, 0x20);  // Blender's selected keyframe orange
const QColor kHold(0x5a, 0x5c, 0x62);

// A tick spacing in frames (1, 2, 5, 10, 20, 50, ...) at least `minimum` apart.
int tickStep(double pixelsPerFrame, double minimum) {
    for (int scale = 1;; scale *= 10)
        for (const int step : {1, 2, 5})
            if (step * scale * pixelsPerFrame >= minimum || step * scale >= 10'000'000)
                return step * scale;
}

QPolygonF diamond(const QPointF& c, double r) {
    return QPolygonF(
        {c + QPointF(0, -r), c + QPointF(r, 0), c + QPointF(0, r), c + QPointF(-r, 0)});
}

}  // namespace

TimelineView::TimelineView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("timelineView"));
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    // The rows scroll under the ruler; the bar shows when they do not fit.
    scrollBar_ = new QScrollBar(Qt::Vertical, this);
    scrollBar_->setObjectName(QStringLiteral("timelineRowsScrollBar"));
    scrollBar_->hide();
    connect(scrollBar_, &QScrollBar::valueChanged, this, [this](int value) {
        scrollRows_ = value;
        update();
    });
}

TimelineView::~TimelineView() = default;

void TimelineView::setModel(model::TimelineItemModel* model) {
    cancelGesture();
    if (model_)
        disconnect(model_, nullptr, this, nullptr);
    model_ = model;
    selection_.clear();
    scrollRows_ = 0;
    if (model_) {
        auto refresh = [this] {
            updateScrollBar();
            update();
        };
        connect(model_, &QAbstractItemModel::dataChanged, this, refresh);
        connect(model_, &QAbstractItemModel::headerDataChanged, this, refresh);
        connect(model_, &QAbstractItemModel::rowsInserted, this, refresh);
        connect(model_, &QAbstractItemModel::rowsRemoved, this, [this] {
            // Keys of parts that went away are no longer selected.
            std::erase_if(selection_, [this](const auto& entry) {
                return !model_->indexOfPart(entry.first).isValid();
            });
            updateScrollBar();
            update();
        });
        connect(model_, &QAbstractItemModel::modelReset, this, refresh);
    }
    updateScrollBar();
    update();
}

int TimelineView::rowCount() const {
    int total = 0;
    for (int r = 0; model_ && r < model_->rowCount(); ++r) {
        ++total;
        const QModelIndex partIndex = model_->index(r, 0);
        if (expanded_.contains(static_cast<model::PartId>(
                partIndex.data(model::TimelineItemModel::PartIdRole).toUInt())))
            total += model_->rowCount(partIndex);
    }
    return total;
}

void TimelineView::updateScrollBar() {
    const int visible = std::max(1, (height() - kRulerHeight) / kRowHeight);
    const int hidden = std::max(0, rowCount() - visible);
    const QSignalBlocker block(scrollBar_);
    scrollBar_->setRange(0, hidden);
    scrollBar_->setPageStep(visible);
    scrollRows_ = std::clamp(scrollRows_, 0, hidden);
    scrollBar_->setValue(scrollRows_);
    scrollBar_->setVisible(hidden > 0);
    scrollBar_->setGeometry(width() - scrollBar_->sizeHint().width(), kRulerHeight,
                            scrollBar_->sizeHint().width(), height() - kRulerHeight);
}

int TimelineView::keyAreaRight() const {
    return width() - (scrollBar_->isVisible() ? scrollBar_->width() : 0);
}

void TimelineView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    updateScrollBar();
}

void TimelineView::setSelectedKeys(KeySelection selection) {
    std::erase_if(selection, [](const auto& entry) { return entry.second.empty(); });
    if (selection == selection_)
        return;
    selection_ = std::move(selection);
    update();
    emit selectionChanged();
}

int TimelineView::selectedKeyCount() const {
    int count = 0;
    for (const auto& [part, times] : selection_)
        count += static_cast<int>(times.size());
    return count;
}

void TimelineView::setExpanded(model::PartId part, bool expanded) {
    if (expanded)
        expanded_.insert(part);
    else
        expanded_.erase(part);
    updateScrollBar();
    update();
}

QSize TimelineView::sizeHint() const {
    return {900, kRulerHeight + 4 * kRowHeight};
}

QSize TimelineView::minimumSizeHint() const {
    return {kHeaderWidth + 200, kRulerHeight + 2 * kRowHeight};
}

double TimelineView::firstFrame() const {
    return model_ ? model_->document()->timeline().startFrame - 1.0 : -1.0;
}

double TimelineView::pixelsPerFrame() const {
    if (!model_)
        return 10.0;
    const auto& timeline = model_->document()->timeline();
    const double frames =
        timeline.endFrame - timeline.startFrame + 3.0;  // a frame's margin each side
    return std::max(1e-3, (keyAreaRight() - kHeaderWidth) / frames);
}

double TimelineView::xOfFrame(double frame) const {
    return kHeaderWidth + (frame - firstFrame() + 0.5) * pixelsPerFrame();
}

int TimelineView::frameAt(double x) const {
    const double frame = std::floor((x - kHeaderWidth) / pixelsPerFrame() + firstFrame());
    return static_cast<int>(std::clamp(frame, 0.0, double(model::kMaxFrame)));
}

QRect TimelineView::rulerRect() const {
    return {kHeaderWidth, 0, keyAreaRight() - kHeaderWidth, kRulerHeight};
}

std::vector<TimelineView::Row> TimelineView::rows() const {
    std::vector<Row> out;
    if (!model_)
        return out;
    int skipped = 0, top = kRulerHeight;
    auto add = [&](const QModelIndex& index, model::PartId part, JointId joint) {
        if (skipped++ < scrollRows_)
            return;
        out.push_back({index, part, joint, top});
        top += kRowHeight;
    };
    for (int r = 0; r < model_->rowCount() && top < height(); ++r) {
        const QModelIndex partIndex = model_->index(r, 0);
        const auto part = static_cast<model::PartId>(
            partIndex.data(model::TimelineItemModel::PartIdRole).toUInt());
        add(partIndex, part, kNoJoint);
        if (!expanded_.contains(part))
            continue;
        for (int j = 0; j < model_->rowCount(partIndex) && top < height(); ++j) {
            const QModelIndex jointIndex = model_->index(j, 0, partIndex);
            add(jointIndex, part,
                static_cast<JointId>(
                    jointIndex.data(model::TimelineItemModel::JointIdRole).toUInt()));
        }
    }
    return out;
}

std::optional<TimelineView::Row> TimelineView::rowAt(int y) const {
    for (const Row& row : rows())
        if (y >= row.top && y < row.top + kRowHeight)
            return row;
    return std::nullopt;
}

std::optional<QPointF> TimelineView::keyPosition(model::PartId part, int frame,
                                                 rigmesh::JointId joint) const {
    for (const Row& row : rows())
        if (row.part == part && row.joint == joint)
            return QPointF(xOfFrame(frame), row.top + kRowHeight / 2.0);
    return std::nullopt;
}

std::optional<std::pair<model::PartId, double>> TimelineView::keyAt(const QPointF& pixel) const {
    const std::optional<Row> row = rowAt(static_cast<int>(pixel.y()));
    if (!row || pixel.x() < kHeaderWidth)
        return std::nullopt;
    const double ppf = pixelsPerFrame();
    const auto& keys = model_->keyFrames(row->part);
    const int lo = frameAt(pixel.x() - kPickRadius), hi = frameAt(pixel.x() + kPickRadius);
    std::optional<std::pair<model::PartId, double>> best;
    double bestDistance = kPickRadius;
    for (auto it = keys.lower_bound(lo); it != keys.end() && it->first <= hi; ++it) {
        const QModelIndex cell = model_->index(row->index.row(), it->first, row->index.parent());
        if (!cell.data(model::TimelineItemModel::KeyRole).toBool())
            continue;
        const double distance = std::abs(xOfFrame(it->first) - pixel.x());
        if (distance <= bestDistance && distance <= std::max(kPickRadius, ppf / 2)) {
            bestDistance = distance;
            best = std::make_pair(row->part, it->second);
        }
    }
    return best;
}

void TimelineView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    if (!model_)
        return;
    painter.setRenderHint(QPainter::Antialiasing);
    paintRows(painter);
    paintRuler(painter);
    // The current frame over everything: a line and its number in the ruler.
    const int current = model_->document()->currentFrame();
    const double x = xOfFrame(current);
    if (x >= kHeaderWidth) {
        painter.setPen(QPen(kCursor, 2));
        painter.drawLine(QPointF(x, kRulerHeight), QPointF(x, height()));
        const QString label = QString::number(current);
        const int w = fontMetrics().horizontalAdvance(label) + 10;
        const QRectF box(x - w / 2.0, 2, w, kRulerHeight - 4);
        painter.setPen(Qt::NoPen);
        painter.setBrush(kCursor);
        painter.drawRoundedRect(box, 4, 4);
        painter.setPen(Qt::white);
        painter.drawText(box, Qt::AlignCenter, label);
    }
    if (gesture_ == Gesture::BoxSelect) {
        painter.setPen(QPen(QColor(255, 255, 255, 160), 1, Qt::DashLine));
        painter.setBrush(QColor(255, 255, 255, 25));
        painter.drawRect(box_);
    }
}

void TimelineView::paintRuler(QPainter& painter) const {
    painter.fillRect(QRect(0, 0, width(), kRulerHeight), kHeader);
    const double ppf = pixelsPerFrame();
    const int step = tickStep(ppf, 40);
    const int minor = std::max(1, tickStep(ppf, 6));
    const int first = std::max(0, static_cast<int>(std::ceil(firstFrame())));
    const int last = frameAt(width());
    painter.setPen(kText);
    for (int f = first - first % minor; f <= last; f += minor) {
        if (f < first)
            continue;
        const double x = xOfFrame(f);
        const bool major = f % step == 0;
        painter.setPen(major ? kText : kHold);
        painter.drawLine(QPointF(x, kRulerHeight - (major ? 8 : 4)), QPointF(x, kRulerHeight));
        if (major)
            painter.drawText(QRectF(x - 30, 0, 60, kRulerHeight - 8), Qt::AlignCenter,
                             QString::number(f));
    }
    painter.setPen(kText);
    const QString clipLabel = tr("Frames");
    painter.drawText(QRect(8, 0, kHeaderWidth - 16, kRulerHeight), Qt::AlignVCenter, clipLabel);
}

void TimelineView::paintRows(QPainter& painter) const {
    const auto& timeline = model_->document()->timeline();
    const double ppf = pixelsPerFrame();
    // Outside the range: darker, as Blender shades frames outside the scene range.
    const double startX = xOfFrame(timeline.startFrame) - ppf / 2;
    const double endX = xOfFrame(timeline.endFrame) + ppf / 2;
    painter.fillRect(QRectF(kHeaderWidth, kRulerHeight, startX - kHeaderWidth, height()),
                     kOutOfRange);
    painter.fillRect(QRectF(endX, kRulerHeight, width() - endX, height()), kOutOfRange);
    const int lo = std::max(0, frameAt(kHeaderWidth)), hi = frameAt(width());
    for (const Row& row : rows()) {
        const double centre = row.top + kRowHeight / 2.0;
        const bool jointRow = row.joint != kNoJoint;
        painter.setPen(kRowLine);
        painter.drawLine(QPointF(0, row.top + kRowHeight - 0.5),
                         QPointF(width(), row.top + kRowHeight - 0.5));
        // Header: expander and name (joints indented), the part's clip.
        painter.fillRect(QRect(0, row.top, kHeaderWidth, kRowHeight - 1), kHeader);
        painter.setPen(kText);
        QString label = row.index.data(Qt::DisplayRole).toString();
        if (!jointRow) {
            const bool open = expanded_.contains(row.part);
            painter.setBrush(kText);
            painter.setPen(Qt::NoPen);
            const QPointF c(10, centre);
            painter.drawPolygon(
                open ? QPolygonF({c + QPointF(-4, -2), c + QPointF(4, -2), c + QPointF(0, 3)})
                     : QPolygonF({c + QPointF(-2, -4), c + QPointF(3, 0), c + QPointF(-2, 4)}));
            painter.setPen(kText);
            label += QStringLiteral("  ·  ") +
                     row.index.data(model::TimelineItemModel::ClipNameRole).toString();
        }
        const int indent = jointRow ? 30 : 20;
        painter.drawText(
            QRect(indent, row.top, kHeaderWidth - indent - 4, kRowHeight), Qt::AlignVCenter,
            fontMetrics().elidedText(label, Qt::ElideRight, kHeaderWidth - indent - 4));
        // Keys, read from the model cell by cell over the part's key frames.
        const auto& keys = model_->keyFrames(row.part);
        const auto& selected =
            selection_.contains(row.part) ? selection_.at(row.part) : std::set<double>{};
        for (auto it = keys.lower_bound(lo); it != keys.end() && it->first <= hi; ++it) {
            const QModelIndex cell = model_->index(row.index.row(), it->first, row.index.parent());
            if (!cell.data(model::TimelineItemModel::KeyRole).toBool())
                continue;
            const QPointF c(xOfFrame(it->first), centre);
            if (cell.data(model::TimelineItemModel::HoldRole).toBool()) {
                const auto next = std::next(it);
                if (next != keys.end()) {
                    painter.fillRect(QRectF(c.x(), centre - 2, xOfFrame(next->first) - c.x(), 4),
                                     kHold);
                }
            }
            const bool isSelected = selected.contains(it->second);
            painter.setPen(QPen(Qt::black, 1));
            painter.setBrush(isSelected ? kSelectedKey : kKey);
            painter.drawPolygon(diamond(c, jointRow ? kDiamond - 1.5 : kDiamond));
        }
    }
}

bool TimelineView::event(QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        // Delete, X, Ctrl+C and Ctrl+V act on keys here, not on the window's
        // actions (Delete Part).
        if (isShortcut(static_cast<QKeyEvent*>(event))) {
            event->accept();
            return true;
        }
    } else if (event->type() == QEvent::ToolTip && model_) {
        auto* help = static_cast<QHelpEvent*>(event);
        if (help->pos().x() >= kHeaderWidth && help->pos().y() < kRulerHeight) {
            // Seconds on hover over the ruler.
            const int frame = frameAt(help->pos().x());
            QToolTip::showText(
                help->globalPos(),
                tr("Frame %1 = %2 s")
                    .arg(frame)
                    .arg(model_->document()->timeline().timeOfFrame(frame), 0, 'f', 3),
                this);
        } else if (const auto key = keyAt(help->pos())) {
            const auto& timeline = model_->document()->timeline();
            QToolTip::showText(help->globalPos(),
                               tr("Key at frame %1 (%2 s)")
                                   .arg(timeline.frameOfTime(key->second))
                                   .arg(key->second, 0, 'f', 3),
                               this);
        } else {
            QToolTip::hideText();
        }
        return true;
    }
    return QWidget::event(event);
}

bool TimelineView::isShortcut(const QKeyEvent* event) const {
    const auto mods = event->modifiers() & ~Qt::KeypadModifier;
    if (mods == Qt::NoModifier)
        return event->key() == Qt::Key_Delete || event->key() == Qt::Key_X ||
               event->key() == Qt::Key_Backspace || event->key() == Qt::Key_Escape;
    return mods == Qt::ControlModifier && (event->key() == Qt::Key_C || event->key() == Qt::Key_V);
}

void TimelineView::keyPressEvent(QKeyEvent* event) {
    const auto mods = event->modifiers() & ~Qt::KeypadModifier;
    if (event->key() == Qt::Key_Escape && gesture_ != Gesture::None) {
        cancelGesture();
    } else if (mods == Qt::NoModifier &&
               (event->key() == Qt::Key_Delete || event->key() == Qt::Key_X ||
                event->key() == Qt::Key_Backspace)) {
        emit deleteRequested();
    } else if (mods == Qt::ControlModifier && event->key() == Qt::Key_C) {
        emit copyRequested();
    } else if (mods == Qt::ControlModifier && event->key() == Qt::Key_V) {
        emit pasteRequested();
    } else {
        QWidget::keyPressEvent(event);
    }
}

void TimelineView::wheelEvent(QWheelEvent* event) {
    if (!model_)
        return;
    // Scroll the rows, three at a time per notch.
    const int notches = event->angleDelta().y() / 120;
    scrollRows_ -= 3 * notches;
    updateScrollBar();
    update();
}

void TimelineView::scrubTo(double x) {
    model::Document* document = model_->document();
    const int frame = frameAt(x);
    if (frame != document->currentFrame())
        document->setCurrentFrame(frame);
}

void TimelineView::mousePressEvent(QMouseEvent* event) {
    if (!model_ || event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    setFocus(Qt::MouseFocusReason);
    pressPos_ = event->position();
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    if (pressPos_.y() < kRulerHeight) {
        if (pressPos_.x() >= kHeaderWidth) {
            gesture_ = Gesture::Scrub;
            scrubTo(pressPos_.x());
        }
        return;
    }
    if (pressPos_.x() < kHeaderWidth) {
        if (const std::optional<Row> row = rowAt(static_cast<int>(pressPos_.y()))) {
            const model::PartId part = row->part;
            if (row->joint == kNoJoint && pressPos_.x() < 20)
                setExpanded(part, !isExpanded(part));
            model_->document()->setSelection({part, row->joint});
        }
        return;
    }
    if (const auto key = keyAt(pressPos_)) {
        KeySelection selection = selection_;
        const bool selected =
            selection_.contains(key->first) && selection_.at(key->first).contains(key->second);
        if (shift) {
            if (selected)
                selection[key->first].erase(key->second);
            else
                selection[key->first].insert(key->second);
        } else if (!selected) {
            selection = {{key->first, {key->second}}};
        }
        setSelectedKeys(std::move(selection));
        gesture_ = (shift && selected) ? Gesture::None : Gesture::PressKey;
        return;
    }
    gesture_ = Gesture::BoxSelect;
    boxAdds_ = shift;
    box_ = QRect(pressPos_.toPoint(), QSize(1, 1));
    update();
}

void TimelineView::mouseMoveEvent(QMouseEvent* event) {
    if (!model_)
        return;
    const QPointF pos = event->position();
    const auto report = [this](const QString& failure) { emit statusMessage(failure, 8000); };
    switch (gesture_) {
        case Gesture::Scrub:
            scrubTo(pos.x());
            break;
        case Gesture::PressKey:
            if (std::abs(pos.x() - pressPos_.x()) < kDragThreshold || selection_.empty())
                break;
            {
                std::map<model::PartId, std::vector<double>> keys;
                for (const auto& [part, times] : selection_)
                    keys[part].assign(times.begin(), times.end());
                drag_ = std::make_unique<KeyDrag>(*model_->document(), std::move(keys));
            }
            gesture_ = Gesture::DragKeys;
            [[fallthrough]];
        case Gesture::DragKeys: {
            const int frames =
                static_cast<int>(std::lround((pos.x() - pressPos_.x()) / pixelsPerFrame()));
            if (!runUserAction(tr("Timeline"), report, [&] { drag_->moveTo(frames); })) {
                // The keys go back where the drag found them.
                runUserAction(tr("Timeline"), report, [&] { drag_->cancel(); });
                drag_.reset();
                gesture_ = Gesture::None;
            }
            break;
        }
        case Gesture::BoxSelect:
            box_ = QRect(pressPos_.toPoint(), pos.toPoint()).normalized();
            update();
            break;
        case Gesture::None:
            break;
    }
}

void TimelineView::mouseReleaseEvent(QMouseEvent* event) {
    if (!model_ || event->button() != Qt::LeftButton)
        return;
    const Gesture gesture = gesture_;
    gesture_ = Gesture::None;
    const auto report = [this](const QString& failure) { emit statusMessage(failure, 8000); };
    if (gesture == Gesture::DragKeys && drag_) {
        std::unique_ptr<KeyDrag> drag = std::move(drag_);
        // A move that throws leaves the keys where the drag found them
        // (KeyDrag::finish pushes through model/GuardedUndo).
        runUserAction(tr("Timeline"), report, [&] {
            KeySelection moved;
            for (const auto& [part, times] : drag->finish())
                moved[part].insert(times.begin(), times.end());
            setSelectedKeys(std::move(moved));
            // The clips changed under the current frame: show what they say now.
            model_->document()->setCurrentFrame(model_->document()->currentFrame());
        });
    } else if (gesture == Gesture::BoxSelect) {
        selectInBox(box_, boxAdds_);
        update();
    }
}

void TimelineView::selectInBox(const QRect& box, bool add) {
    KeySelection selection = add ? selection_ : KeySelection{};
    const int lo = frameAt(box.left()), hi = frameAt(box.right());
    for (const Row& row : rows()) {
        if (row.top + kRowHeight / 2 < box.top() || row.top + kRowHeight / 2 > box.bottom())
            continue;
        const auto& keys = model_->keyFrames(row.part);
        for (auto it = keys.lower_bound(lo); it != keys.end() && it->first <= hi; ++it) {
            const double x = xOfFrame(it->first);
            const QModelIndex cell = model_->index(row.index.row(), it->first, row.index.parent());
            if (x >= box.left() && x <= box.right() &&
                cell.data(model::TimelineItemModel::KeyRole).toBool())
                selection[row.part].insert(it->second);
        }
    }
    setSelectedKeys(std::move(selection));
}

void TimelineView::cancelGesture() {
    if (drag_) {
        drag_->cancel();
        drag_.reset();
    }
    gesture_ = Gesture::None;
    update();
}

}  // namespace rigmesh::widgets
