// One diagnostics path (widgets/UserAction.h, model/GuardedUndo.h): a
// command whose redo() or undo() throws a std::logic_error, reached through
// Undo, Redo, the History dock, a viewport tool or a finished job, is said
// as "<action>: internal error (...)" in the status bar, leaves the document
// as it was, and the studio keeps working; a rigmesh::Error keeps its own
// message.
#include <QDockWidget>
#include <QStatusBar>
#include <QUndoView>
#include <cmath>
#include <new>
#include <stdexcept>

#include "StudioFixture.h"
#include "ThrowingCommand.h"
#include "UserAction.h"
#include "base/Error.h"
#include "jobs/JobRunner.h"
#include "model/DocumentFile.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/RenamePartCommand.h"
#include "viewport/ViewportTool.h"

namespace rigmesh {
namespace {

using test::kBrokenOnPurpose;
using test::ThrowingCommand;
using Throws = ThrowingCommand::Throws;

const QString kInternal = QStringLiteral(": internal error (a command broken on purpose)");

// A tool whose press pushes a command that throws half-way.
class BrokenTool : public widgets::ViewportTool {
  public:
    QString name() const override { return QStringLiteral("Broken"); }
    QString hint() const override { return QStringLiteral("Press to fail"); }
    void press(widgets::Viewport& viewport, QMouseEvent*) override {
        model::Document& document = *viewport.document();
        model::pushCommand(
            document, std::make_unique<ThrowingCommand>(document, document.parts().front().id,
                                                        QStringLiteral("New"), Throws::OnRedo));
    }
    void move(widgets::Viewport&, QMouseEvent*) override {}
    void release(widgets::Viewport&, QMouseEvent*) override {}
    void cancel(widgets::Viewport&) override { ++cancels; }
    int cancels = 0;
};

class StudioFailures : public test::StudioFixture {
  protected:
    void SetUp() override {
        StudioFixture::SetUp();
        std::vector<Vec2> points;
        for (int i = 0; i < 64; ++i) {
            const double t = 2.0 * M_PI * i / 64.0;
            points.emplace_back(1.5 * std::cos(t), 0.6 * std::sin(t));
        }
        auto create = model::CreatePartCommand::create(*document(), points, "Body");
        part = create->partId();
        model::pushCommand(*document(), std::move(create));
        viewport()->frameAll();
    }
    QString status() const { return window->statusBar()->currentMessage(); }
    QByteArray bytes() const { return model::DocumentFile::toBytes(*document()); }
    QAction* action(const char* name) const { return window->findChild<QAction*>(name); }
    QString name() const { return document()->part(part).name; }
    // The studio still works: a step pushes, undoes and redoes.
    void expectStudioStillWorks() {
        const QString before = name();
        model::pushCommand(*document(), std::make_unique<model::RenamePartCommand>(
                                            *document(), part, QStringLiteral("Still works")));
        EXPECT_EQ(name(), QStringLiteral("Still works"));
        action("undoAction")->trigger();
        EXPECT_EQ(name(), before);
        action("redoAction")->trigger();
        EXPECT_EQ(name(), QStringLiteral("Still works"));
    }

    model::PartId part = model::kNoPart;
};

TEST_F(StudioFailures, UndoOfAStepThatThrowsIsSaidAndLeavesTheDocumentAsItWas) {
    model::pushCommand(*document(), std::make_unique<ThrowingCommand>(
                                        *document(), part, QStringLiteral("New"), Throws::OnUndo));
    const QByteArray before = bytes();
    action("undoAction")->trigger();
    EXPECT_EQ(status(), QStringLiteral("Undo") + kInternal) << status().toStdString();
    EXPECT_EQ(bytes(), before);
    EXPECT_EQ(document()->partCount(), 1);
    EXPECT_EQ(name(), QStringLiteral("New"));
    EXPECT_TRUE(document()->isModified());
    expectStudioStillWorks();
}

TEST_F(StudioFailures, RedoOfAStepThatThrowsIsSaidAndLeavesNothingToRedo) {
    model::pushCommand(*document(),
                       std::make_unique<ThrowingCommand>(*document(), part, QStringLiteral("New"),
                                                         Throws::OnLaterRedo));
    action("undoAction")->trigger();
    ASSERT_EQ(name(), QStringLiteral("Body"));
    const QByteArray before = bytes();
    action("redoAction")->trigger();
    EXPECT_EQ(status(), QStringLiteral("Redo") + kInternal) << status().toStdString();
    EXPECT_EQ(bytes(), before);
    EXPECT_EQ(name(), QStringLiteral("Body"));
    EXPECT_FALSE(document()->undoStack()->canRedo());
    EXPECT_FALSE(action("redoAction")->isEnabled());
    expectStudioStillWorks();
}

TEST_F(StudioFailures, HistoryClickOnAStepThatThrowsStopsBeforeIt) {
    const int start = document()->undoStack()->index();
    model::pushCommand(*document(), std::make_unique<model::RenamePartCommand>(
                                        *document(), part, QStringLiteral("Leg")));
    model::pushCommand(*document(),
                       std::make_unique<ThrowingCommand>(*document(), part, QStringLiteral("New"),
                                                         Throws::OnLaterRedo));
    model::moveToUndoIndex(*document(), start);
    ASSERT_EQ(name(), QStringLiteral("Body"));
    auto* history = window->findChild<QUndoView*>();
    ASSERT_NE(history, nullptr);
    for (auto* dock : window->findChildren<QDockWidget*>())
        if (dock->objectName() == QStringLiteral("historyDock"))
            dock->show();
    QTest::qWait(20);
    // Row r is the stack's index r: the row of the step that throws.
    const QRect row = history->visualRect(history->model()->index(start + 2, 0));
    ASSERT_FALSE(row.isEmpty());
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {}, row.center());
    EXPECT_EQ(status(), QStringLiteral("History") + kInternal) << status().toStdString();
    // The step before it is done; the one that threw and after it are gone.
    EXPECT_EQ(document()->undoStack()->index(), start + 1);
    EXPECT_EQ(document()->undoStack()->count(), start + 1);
    EXPECT_EQ(name(), QStringLiteral("Leg"));
    EXPECT_EQ(document()->partCount(), 1);
    // A click on a row that works still moves there.
    const QRect first = history->visualRect(history->model()->index(start, 0));
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {}, first.center());
    EXPECT_EQ(document()->undoStack()->index(), start);
    EXPECT_EQ(name(), QStringLiteral("Body"));
    expectStudioStillWorks();
}

TEST_F(StudioFailures, ToolWhoseStepThrowsIsSaidAndPutsItsDragBack) {
    BrokenTool tool;
    viewport()->setTool(&tool);
    const QByteArray before = bytes();
    const int count = document()->undoStack()->count();
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, viewport()->rect().center());
    EXPECT_EQ(status(), QStringLiteral("Broken") + kInternal) << status().toStdString();
    EXPECT_EQ(bytes(), before);
    EXPECT_EQ(document()->undoStack()->count(), count);
    EXPECT_EQ(tool.cancels, 1);
    viewport()->setTool(nullptr);
    expectStudioStillWorks();
}

TEST_F(StudioFailures, JobWhoseStepThrowsReportsAnInternalErrorAndChangesNothing) {
    const QByteArray before = bytes();
    const auto apply = [this] {
        model::pushCommand(
            *document(), std::make_unique<ThrowingCommand>(*document(), part, QStringLiteral("New"),
                                                           Throws::OnRedo));
    };
    // In the background: the step applied on the GUI thread when the job ends.
    QString reason;
    ASSERT_TRUE(window->jobs()->run(
        QStringLiteral("Failing"), [apply]() -> widgets::JobRunner::Apply { return apply; },
        [&](const QString& why) { reason = why; }));
    test::waitForJobs();
    EXPECT_EQ(reason, QStringLiteral("Internal error: %1").arg(kBrokenOnPurpose));
    EXPECT_EQ(bytes(), before);
    // All at once, without a runner.
    reason.clear();
    widgets::JobRunner::runOn(
        nullptr, QStringLiteral("Failing"),
        [apply]() -> widgets::JobRunner::Apply { return apply; },
        [&](const QString& why) { reason = why; });
    EXPECT_EQ(reason, QStringLiteral("Internal error: %1").arg(kBrokenOnPurpose));
    EXPECT_EQ(bytes(), before);
    expectStudioStillWorks();
}

// runUserAction itself: what each kind of exception becomes.
TEST(UserAction, AnErrorKeepsItsOwnMessage) {
    const Error error(MessageId::DocumentNoSuchPart, 7);
    QString reported;
    EXPECT_FALSE(widgets::runUserAction(
        QStringLiteral("&Delete Part"), [&](const QString& text) { reported = text; },
        [&] { throw error; }));
    EXPECT_EQ(reported, model::errorText(error));
}

TEST(UserAction, AProgrammingErrorIsAnInternalErrorOfTheAction) {
    QString reported;
    EXPECT_FALSE(widgets::runUserAction(
        QStringLiteral("&Delete Part"), [&](const QString& text) { reported = text; },
        [] { throw std::logic_error("index out of range"); }));
    EXPECT_EQ(reported, QStringLiteral("Delete Part: internal error (index out of range)"));
    // Without an action name (the caller's message says what failed).
    widgets::runUserAction(
        {}, [&](const QString& text) { reported = text; },
        [] { throw std::logic_error("index out of range"); });
    EXPECT_EQ(reported, QStringLiteral("Internal error: index out of range"));
}

TEST(UserAction, OutOfMemoryAndUnknownExceptionsAreSaidToo) {
    QString reported;
    widgets::runUserAction(
        QStringLiteral("Cut"), [&](const QString& text) { reported = text; },
        [] { throw std::bad_alloc(); });
    EXPECT_EQ(reported, QStringLiteral("Cut: out of memory"));
    widgets::runUserAction(
        QStringLiteral("Cut"), [&](const QString& text) { reported = text; }, [] { throw 42; });
    EXPECT_EQ(reported, QStringLiteral("Cut: internal error (an exception of unknown type)"));
}

TEST(UserAction, ADoneActionReportsNothing) {
    bool reported = false;
    bool done = false;
    EXPECT_TRUE(widgets::runUserAction(
        QStringLiteral("Cut"), [&](const QString&) { reported = true; }, [&] { done = true; }));
    EXPECT_TRUE(done);
    EXPECT_FALSE(reported);
}

}  // namespace
}  // namespace rigmesh
