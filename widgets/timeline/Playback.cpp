#include "timeline/Playback.h"

#include <cmath>

namespace rigmesh::widgets {

int playbackFrame(int from, const model::TimelineSettings& timeline, double seconds) {
    const int start = timeline.startFrame, length = timeline.endFrame - timeline.startFrame + 1;
    const int base = from >= start && from <= timeline.endFrame ? from : start;
    // A hair over the exact product, so frame n shows at n / fps, not one tick later.
    const double advanced = std::floor(seconds * timeline.framesPerSecond + 1e-9);
    const double offset = std::fmod(base - start + advanced, static_cast<double>(length));
    return start + static_cast<int>(offset);
}

Playback::Playback(QObject* parent) : QObject(parent) {
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &Playback::tick);
}

void Playback::setDocument(model::Document* document) {
    pause();
    document_ = document;
}

void Playback::play() {
    if (!document_ || isPlaying())
        return;
    const model::TimelineSettings& timeline = document_->timeline();
    from_ = document_->currentFrame();
    if (from_ < timeline.startFrame || from_ > timeline.endFrame) {
        from_ = timeline.startFrame;
        document_->setCurrentFrame(from_);
    }
    steps_ = shown_ = dropped_ = 0;
    clock_.start();
    // Ticks at twice the frame rate (at most every 4 ms): a frame shows
    // within half a frame of its time.
    timer_.start(std::max(4, static_cast<int>(500.0 / timeline.framesPerSecond)));
    emit playingChanged(true);
}

void Playback::pause() {
    if (!isPlaying())
        return;
    timer_.stop();
    emit playingChanged(false);
}

void Playback::toggle() {
    isPlaying() ? pause() : play();
}

void Playback::tick() {
    if (!document_) {
        pause();
        return;
    }
    const model::TimelineSettings& timeline = document_->timeline();
    const double seconds = clock_.nsecsElapsed() * 1e-9;
    const int steps = static_cast<int>(std::floor(seconds * timeline.framesPerSecond + 1e-9));
    if (steps == steps_)
        return;
    dropped_ += steps - steps_ - 1;
    steps_ = steps;
    ++shown_;
    document_->setCurrentFrame(playbackFrame(from_, timeline, seconds));
}

}  // namespace rigmesh::widgets
