// The Sketch tool's live preview off the GUI thread: the stroke being drawn
// is built into a part on a worker (model::buildPartAtDocumentLength, the
// build a release runs), at most once every kMinimumIntervalMs and one at a
// time. A request that a newer one replaces before it started is dropped,
// and so is a result cancel() came before: each request has a generation
// and only results newer than the last cancel are handed on. The GUI thread
// never waits for the worker: results come back as queued calls.
//
// A stroke that does not come back to its start (sketch/StrokeClosing.h,
// returnsToStart) is not built: the preview waits for a closed outline.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <exception>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "model/PartNode.h"

namespace rigmesh::model {
struct BuiltPart;  // model/PartBuilder.h
}

namespace rigmesh::widgets {

class SketchPreviewBuilder : public QObject {
    Q_OBJECT
  public:
    // 30 builds a second at most: a frame's time at 30 fps.
    static constexpr int kMinimumIntervalMs = 33;

    // What to build: buildPartAtDocumentLength's inputs and where it goes.
    struct Request {
        std::vector<Vec2> stroke;
        QString name;
        double documentLength = 0.0;
        model::BuildOptions options;
        model::Placement plane;

        friend bool operator==(const Request&, const Request&) = default;
    };
    // What came of a request: a part, the engine's refusal, or nothing
    // (the stroke is still open).
    struct Outcome {
        Request request;
        std::shared_ptr<const model::BuiltPart> built;
        std::exception_ptr error;  // a rigmesh::Error, as buildPart throws it
    };
    using Result = std::shared_future<std::shared_ptr<const Outcome>>;

    explicit SketchPreviewBuilder(QObject* parent = nullptr);
    ~SketchPreviewBuilder() override;

    // Builds `request` next, instead of any request not yet started.
    void request(Request request);
    // Forgets what was asked: the build not yet started is dropped and the
    // running one's result is not handed on.
    void cancel();
    // The build of exactly `request`, started (running or done) and the
    // last one started, or none: a release reuses it instead of building
    // the same stroke again. Only a worker thread may wait for it.
    std::optional<Result> started(const Request& request) const;
    // True while a build runs or one waits for its turn.
    bool busy() const;

  signals:
    // A build's outcome, on the GUI thread, oldest first; never one older
    // than a cancel().
    void built(const rigmesh::widgets::SketchPreviewBuilder::Outcome& outcome);

  private:
    struct Build;
    void startWhenDue();
    void start();
    void finish(const std::shared_ptr<Build>& build);

    std::optional<Request> waiting_;
    unsigned long waitingGeneration_ = 0;
    unsigned long generation_ = 0;
    unsigned long cancelledUpTo_ = 0;
    std::shared_ptr<Build> running_;
    std::shared_ptr<Build> last_;  // the last started, running or done
    QElapsedTimer sinceStart_;
    QTimer due_;
};

}  // namespace rigmesh::widgets
