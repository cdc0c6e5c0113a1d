// The timeline dock, at the bottom of the main window as in
// Blender: transport (start, previous frame, play/pause, next frame, end),
// the current frame, the frame range and rate; the selected part's clips
// (choose the active one; new, duplicate, rename, delete) with their
// interpolation and playback; auto-key and onion skin; and the key area
// (TimelineView) over the document's TimelineItemModel. Every change is an
// undoable command except the current frame, playing, auto-key and onion
// skin, which are view state.
#pragma once

#include <QPointer>
#include <QWidget>
#include <memory>

#include "model/Document.h"
#include "model/TimelineEdits.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QToolButton;
class QLabel;

namespace rigmesh::model {
class TimelineItemModel;
}

namespace rigmesh::widgets {

class Playback;
class TimelineView;

class TimelineDock : public QWidget {
    Q_OBJECT
  public:
    explicit TimelineDock(QWidget* parent = nullptr);
    ~TimelineDock() override;

    void setDocument(model::Document* document);
    model::Document* document() const { return document_; }
    TimelineView* view() const { return view_; }
    Playback* playback() const { return playback_; }
    model::TimelineItemModel* model() const { return model_.get(); }
    bool onionSkin() const;

    // The part whose clips the controls show: the selected one, else the first.
    model::PartId clipPart() const;
    // Clip edits on clipPart() by name (the buttons ask for the names).
    void newClip(const QString& name);
    void duplicateClip(const QString& name);
    void renameClip(const QString& name);
    void deleteClip();
    void activateClip(const QString& name);

  public slots:
    void togglePlayback();
    void stepFrames(int delta);
    void jumpToStart();
    void jumpToEnd();
    void insertKey();
    void deleteSelectedKeys();
    void copySelectedKeys();
    void pasteKeys();

  signals:
    void statusMessage(const QString& message, int timeoutMs = 0);
    void onionSkinToggled(bool on);

  protected:
    // A new palette (Preferences > Theme) redraws the transport icons.
    void changeEvent(QEvent* event) override;

  private:
    void buildControls();
    // The style's media icons in the palette's button text colour: Qt's
    // own are dark grey, lost on the dark theme's buttons.
    void refreshTransportIcons();
    void refresh();
    void refreshClipControls();
    void applyTimeline();
    void applyClipSettings();
    // Runs a command maker; an Error goes to the status bar.
    template <typename Make>
    void run(const QString& failure, Make make);

    QPointer<model::Document> document_;
    std::unique_ptr<model::TimelineItemModel> model_;
    TimelineView* view_;
    Playback* playback_;
    model::KeyClipboard clipboard_;

    QToolButton* playButton_ = nullptr;
    QSpinBox* frame_ = nullptr;
    QSpinBox* start_ = nullptr;
    QSpinBox* end_ = nullptr;
    QDoubleSpinBox* rate_ = nullptr;
    QLabel* clipLabel_ = nullptr;
    QComboBox* clip_ = nullptr;
    QToolButton* clipMenu_ = nullptr;
    QComboBox* interpolation_ = nullptr;
    QComboBox* playbackMode_ = nullptr;
    QToolButton* autoKey_ = nullptr;
    QToolButton* onion_ = nullptr;
};

}  // namespace rigmesh::widgets
