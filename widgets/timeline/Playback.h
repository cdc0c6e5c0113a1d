// Playing the timeline: real time, never slow motion. Each tick
// works out the frame from the time since play started, so when drawing a
// frame takes longer than a frame lasts the frames in between are dropped,
// as Blender's "Frame Dropping" sync does. The frame range loops.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include "model/Document.h"

namespace rigmesh::widgets {

// The frame `seconds` after playing started at `from` over `timeline`'s
// range, looping; a start outside the range plays from the range's start.
int playbackFrame(int from, const model::TimelineSettings& timeline, double seconds);

class Playback : public QObject {
    Q_OBJECT
  public:
    explicit Playback(QObject* parent = nullptr);

    // Stops playing the previous document.
    void setDocument(model::Document* document);
    bool isPlaying() const { return timer_.isActive(); }
    // Since the last play(): frames shown, and frames skipped to keep time.
    int framesShown() const { return shown_; }
    int framesDropped() const { return dropped_; }

  public slots:
    void play();
    void pause();
    void toggle();

  signals:
    void playingChanged(bool playing);

  private:
    void tick();

    QPointer<model::Document> document_;
    QTimer timer_;
    QElapsedTimer clock_;
    int from_ = 0;
    int steps_ = 0;  // frames advanced since play(), before wrapping
    int shown_ = 0, dropped_ = 0;
};

}  // namespace rigmesh::widgets
