// A rendered frame of a fixed document compared with a baseline PNG within a
// tolerance, F3D style: on mismatch (or a missing baseline) the new image is
// written next to the test binary for a person to inspect and, if right, to
// copy over the baseline.
#include <gtest/gtest.h>

#include <QImage>
#include <QOpenGLWidget>
#include <QTemporaryDir>

#include "DocumentView.h"
#include "EmbeddedExamples.h"
#include "MainWindow.h"
#include "StudioTestSupport.h"
#include "model/commands/CreatePartCommand.h"
#include "sketch/Sketch.h"

namespace rigmesh {
namespace {

// Mean absolute difference per channel (0-255) allowed, and the share of
// pixels allowed to differ by more than a small threshold: llvmpipe is
// deterministic on one machine, but drivers differ slightly elsewhere.
constexpr double kMeanDifference = 2.0;
constexpr double kDifferingPixelShare = 0.02;
constexpr int kPixelThreshold = 40;

double meanDifference(const QImage& a, const QImage& b, double* differingShare) {
    double sum = 0;
    long differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int d = std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) +
                          std::abs(qBlue(p) - qBlue(q));
            sum += d / 3.0;
            if (d > kPixelThreshold)
                ++differing;
        }
    *differingShare = double(differing) / (double(a.width()) * a.height());
    return sum / (double(a.width()) * a.height());
}

TEST(RenderBaseline, ExampleDocumentFrameMatchesTheBaseline) {
    QTemporaryDir recovery;
    widgets::MainWindow window(recovery.path());
    auto document = std::make_unique<model::Document>();
    const Sketch sketch = parseSketchJson(resources::exampleSketchJson(), "example.json");
    document->undoStack()->push(
        model::CreatePartCommand::create(*document, sketch.points, "biped").release());
    window.addDocument(std::move(document));
    widgets::Viewport* viewport = window.currentView()->viewport();
    viewport->setFixedSize(480, 480);
    test::settle(&window);
    viewport->frameAll();
    const QImage frame = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    ASSERT_EQ(frame.size(), QSize(480, 480) * viewport->devicePixelRatioF());

    const QString baselinePath = QStringLiteral(RIGMESH_BASELINES "/example_document.png");
    const QString outputPath = QStringLiteral(RIGMESH_TEST_OUTPUT "/example_document.png");
    const QImage baseline = QImage(baselinePath).convertToFormat(QImage::Format_RGB32);
    if (baseline.isNull() || baseline.size() != frame.size()) {
        frame.save(outputPath);
        FAIL() << "no usable baseline at " << baselinePath.toStdString() << "; wrote "
               << outputPath.toStdString();
    }
    double share = 0;
    const double mean = meanDifference(frame, baseline, &share);
    if (mean > kMeanDifference || share > kDifferingPixelShare)
        frame.save(outputPath);
    EXPECT_LE(mean, kMeanDifference) << "new image: " << outputPath.toStdString();
    EXPECT_LE(share, kDifferingPixelShare) << "new image: " << outputPath.toStdString();
}

}  // namespace
}  // namespace rigmesh
