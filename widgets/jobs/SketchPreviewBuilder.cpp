#include "jobs/SketchPreviewBuilder.h"

#include <QCoreApplication>
#include <QPointer>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "model/PartBuilder.h"
#include "sketch/StrokeClosing.h"

namespace rigmesh::widgets {

// One build: written by its worker, read on the GUI thread after the worker
// posted it back (and by a release's job through the future).
struct SketchPreviewBuilder::Build {
    unsigned long generation = 0;
    Request request;
    std::promise<std::shared_ptr<const Outcome>> promise;
    Result result;
};

SketchPreviewBuilder::SketchPreviewBuilder(QObject* parent) : QObject(parent) {
    due_.setSingleShot(true);
    connect(&due_, &QTimer::timeout, this, &SketchPreviewBuilder::startWhenDue);
}

SketchPreviewBuilder::~SketchPreviewBuilder() = default;

void SketchPreviewBuilder::request(Request request) {
    // The pen held still: what is being built (or shown) already is this.
    if (last_ && last_->generation > cancelledUpTo_ && last_->request == request) {
        waiting_.reset();
        due_.stop();
        return;
    }
    waiting_ = std::move(request);
    waitingGeneration_ = ++generation_;
    startWhenDue();
}

void SketchPreviewBuilder::cancel() {
    cancelledUpTo_ = generation_;
    waiting_.reset();
    due_.stop();
}

std::optional<SketchPreviewBuilder::Result> SketchPreviewBuilder::started(
    const Request& request) const {
    if (last_ && last_->request == request)
        return last_->result;
    return std::nullopt;
}

bool SketchPreviewBuilder::busy() const {
    return running_ || waiting_;
}

void SketchPreviewBuilder::startWhenDue() {
    if (running_ || !waiting_)
        return;
    const qint64 since = sinceStart_.isValid() ? sinceStart_.elapsed() : kMinimumIntervalMs;
    if (since < kMinimumIntervalMs) {
        if (!due_.isActive())
            due_.start(static_cast<int>(kMinimumIntervalMs - since));
        return;
    }
    start();
}

void SketchPreviewBuilder::start() {
    auto build = std::make_shared<Build>();
    build->generation = waitingGeneration_;
    build->request = std::move(*waiting_);
    build->result = build->promise.get_future().share();
    waiting_.reset();
    running_ = build;
    last_ = build;
    sinceStart_.start();
    QPointer<SketchPreviewBuilder> self(this);
    // Detached, as JobRunner's workers: a builder destroyed first drops the
    // result (the QPointer is null by then).
    std::thread([build, self] {
        // Below the GUI thread's priority, as JobRunner's workers: the pen
        // keeps its time slices on a busy machine.
        setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 5);
        auto outcome = std::make_shared<Outcome>();
        outcome->request = build->request;
        try {
            if (returnsToStart(build->request.stroke))
                outcome->built =
                    std::make_shared<const model::BuiltPart>(model::buildPartAtDocumentLength(
                        build->request.documentLength, build->request.stroke, build->request.name,
                        build->request.options));
        } catch (const std::exception&) {
            outcome->error = std::current_exception();
        }
        build->promise.set_value(std::move(outcome));
        QMetaObject::invokeMethod(
            qApp,
            [build, self] {
                if (self)
                    self->finish(build);
            },
            Qt::QueuedConnection);
    }).detach();
}

void SketchPreviewBuilder::finish(const std::shared_ptr<Build>& build) {
    if (build == running_)
        running_.reset();
    if (build->generation > cancelledUpTo_)
        emit built(*build->result.get());  // ready: set before it was posted
    startWhenDue();
}

}  // namespace rigmesh::widgets
