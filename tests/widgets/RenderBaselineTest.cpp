// Rendered frames of fixed documents (the example, and each weight view)
// compared with baseline PNGs within a tolerance, F3D style: on mismatch (or a missing baseline)
// the new image is written next to the test binary for a person to inspect and, if right, to copy
// over the baseline.
#include <gtest/gtest.h>

#include <QImage>
#include <QOpenGLWidget>
#include <QTemporaryDir>

#include <cmath>
#include <string>
#include <vector>

#include "DocumentView.h"
#include "EmbeddedExamples.h"
#include "MainWindow.h"
#include "SketchToSurfaceTestSupport.h"
#include "StudioTestSupport.h"
#include "model/commands/CreatePartCommand.h"
#include "model/recipe/RecipeRunner.h"
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

// Compares `frame` with tests/data/baselines/NAME.png within the tolerances;
// on mismatch (or no baseline) writes the frame next to the test binary.
void expectMatchesBaseline(const QImage& frame, const QString& name) {
    const QString baselinePath = QStringLiteral(RIGMESH_BASELINES "/") + name + ".png";
    const QString outputPath = QStringLiteral(RIGMESH_TEST_OUTPUT "/") + name + ".png";
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

// The example biped in a 480 x 480 view, framed; `prepare` may change the
// document and the view before the frame is grabbed.
template <typename Prepare>
QImage exampleFrame(Prepare&& prepare) {
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
    prepare(*window.currentDocument(), *viewport);
    const QImage frame = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    EXPECT_EQ(frame.size(), QSize(480, 480) * viewport->devicePixelRatioF());
    return frame;
}

// A part built from `points` alone in a 480 x 480 view, framed: the surface
// as an artist first sees it (no crease, dimple or faceted limb).
QImage sketchFrame(const std::vector<Vec2>& points, const std::string& name) {
    QTemporaryDir recovery;
    widgets::MainWindow window(recovery.path());
    auto document = std::make_unique<model::Document>();
    document->undoStack()->push(
        model::CreatePartCommand::create(*document, points, QString::fromStdString(name))
            .release());
    window.addDocument(std::move(document));
    widgets::Viewport* viewport = window.currentView()->viewport();
    viewport->setFixedSize(480, 480);
    test::settle(&window);
    viewport->frameAll();
    QTest::qWait(20);
    return viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
}

class SurfaceBaseline : public testing::TestWithParam<std::string> {};

TEST_P(SurfaceBaseline, FrameMatchesTheBaseline) {
    const std::string name = GetParam();
    const std::vector<Vec2> points =
        name == "blob_bump"
            ? testsupport::blobWithBump()
            : readSketchFile(std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json").points;
    expectMatchesBaseline(sketchFrame(points, name),
                          QStringLiteral("surface_") + QString::fromStdString(name));
}

INSTANTIATE_TEST_SUITE_P(Sketches, SurfaceBaseline, testing::Values("biped", "star", "blob_bump"),
                         [](const auto& param) { return param.param; });

TEST(RenderBaseline, ExampleDocumentFrameMatchesTheBaseline) {
    expectMatchesBaseline(exampleFrame([](model::Document&, widgets::Viewport&) {}),
                          QStringLiteral("example_document"));
}

// Each weight view of the biped with its right arm's bone
// selected and one Replace dab painted on the chest (so the difference view
// shows something): the colours come from the GPU, so a shader or upload
// change shows here.
class WeightViewBaseline
    : public testing::TestWithParam<std::pair<widgets::WeightView, const char*>> {};

TEST_P(WeightViewBaseline, FrameMatchesTheBaseline) {
    const auto [view, name] = GetParam();
    expectMatchesBaseline(
        exampleFrame([view = view](model::Document& document, widgets::Viewport& viewport) {
            const model::PartNode& node = document.parts().front();
            const Skeleton& skeleton = node.part->skeleton;
            JointId hand = kNoJoint;
            for (const Joint& joint : skeleton.joints())
                if (skeleton.degree(joint.id) == 1 &&
                    (hand == kNoJoint || joint.position.x() > skeleton.joint(hand).position.x()))
                    hand = joint.id;
            document.setSelection({node.id, hand});
            const BoneId bone = *boneForJoint(skeleton, hand);
            model::RecipeRunner(document).apply({{"command", "paint_weights"},
                                                 {"part", 0},
                                                 {"bone", bone},
                                                 {"mode", "replace"},
                                                 {"value", 0.6},
                                                 {"strength", 1.0},
                                                 {"center", {0.0, 1.0, 0.3}},
                                                 {"radius", 0.5}},
                                                1);
            viewport.setWeightView(view);
            QTest::qWait(20);
            test::waitForGlobalDifferences(&viewport);
        }),
        QStringLiteral("weights_") + QString::fromLatin1(name));
}

INSTANTIATE_TEST_SUITE_P(
    Views, WeightViewBaseline,
    testing::Values(std::pair{widgets::WeightView::SelectedBone, "selected_bone"},
                    std::pair{widgets::WeightView::DominantBone, "dominant_bone"},
                    std::pair{widgets::WeightView::Influences, "influences"},
                    std::pair{widgets::WeightView::GlobalDifference, "global_difference"}),
    [](const auto& param) { return std::string(param.param.second); });

}  // namespace
}  // namespace rigmesh
