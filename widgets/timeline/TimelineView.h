// The timeline's key area: a view over a TimelineItemModel drawn
// as Blender's timeline and dope sheet are. A ruler of frames (the time in
// seconds on hover) over one row per part with its keys as diamonds, each
// part expandable into one row per joint (with hold bars where a joint keeps
// its rotation to the next key); the current frame is a blue line. Rows
// that do not fit scroll (the wheel, or the scroll bar that then shows).
//
// Mouse: the ruler scrubs (click to jump, drag to scrub, live); a click on a
// key selects it (Shift adds or removes), a drag from empty space selects
// the keys in a box (Shift adds); dragging selected keys moves them in whole
// frames, previewed live and one undo step on release (KeyDrag); Esc puts
// them back. A joint row's diamond stands for its part's key (keys are
// whole poses). Keys: Delete / X, Ctrl+C, Ctrl+V (signals to the dock).
#pragma once

#include <QPointer>
#include <QWidget>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "model/TimelineItemModel.h"

class QScrollBar;

namespace rigmesh::widgets {

class KeyDrag;

class TimelineView : public QWidget {
    Q_OBJECT
  public:
    // Exact key times of the selected keys, per part.
    using KeySelection = std::map<model::PartId, std::set<double>>;

    explicit TimelineView(QWidget* parent = nullptr);
    ~TimelineView() override;

    void setModel(model::TimelineItemModel* model);
    model::TimelineItemModel* model() const { return model_; }

    const KeySelection& selectedKeys() const { return selection_; }
    void setSelectedKeys(KeySelection selection);
    int selectedKeyCount() const;

    void setExpanded(model::PartId part, bool expanded);
    bool isExpanded(model::PartId part) const { return expanded_.contains(part); }

    // Geometry (tests, the dock): pixel x of a frame's centre and back, the
    // centre of a row's diamond at a frame, the ruler.
    double xOfFrame(double frame) const;
    int frameAt(double x) const;
    std::optional<QPointF> keyPosition(model::PartId part, int frame,
                                       rigmesh::JointId joint = rigmesh::kNoJoint) const;
    QRect rulerRect() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

  signals:
    void deleteRequested();
    void copyRequested();
    void pasteRequested();
    void selectionChanged();
    // A key drag that failed (widgets/UserAction.h); the keys are as they were.
    void statusMessage(const QString& message, int timeoutMs = 0);

  protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    struct Row {
        QModelIndex index;  // column 0
        model::PartId part = model::kNoPart;
        rigmesh::JointId joint = rigmesh::kNoJoint;
        int top = 0;  // pixel
    };
    std::vector<Row> rows() const;
    // Every row, scrolled out of view or not.
    int rowCount() const;
    // The scroll bar's range, page and place for the rows and the height.
    void updateScrollBar();
    // Where the key area ends on the right (left of the scroll bar).
    int keyAreaRight() const;
    std::optional<Row> rowAt(int y) const;
    // The key under the pixel, as (part, exact time).
    std::optional<std::pair<model::PartId, double>> keyAt(const QPointF& pixel) const;
    // The frames of the key area: the range with a frame's margin each side.
    double firstFrame() const;
    double pixelsPerFrame() const;
    void scrubTo(double x);
    void selectInBox(const QRect& box, bool add);
    void paintRuler(class QPainter& painter) const;
    void paintRows(class QPainter& painter) const;
    bool isShortcut(const QKeyEvent* event) const;
    void cancelGesture();

    QPointer<model::TimelineItemModel> model_;
    std::set<model::PartId> expanded_;
    KeySelection selection_;
    int scrollRows_ = 0;  // rows scrolled out of view at the top
    QScrollBar* scrollBar_ = nullptr;

    enum class Gesture { None, Scrub, PressKey, DragKeys, BoxSelect };
    Gesture gesture_ = Gesture::None;
    QPointF pressPos_;
    QRect box_;
    bool boxAdds_ = false;
    std::unique_ptr<KeyDrag> drag_;
};

}  // namespace rigmesh::widgets
