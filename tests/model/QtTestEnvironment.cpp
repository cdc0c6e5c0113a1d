// One QCoreApplication for the whole test run (QObject signals, timers and
// QAbstractItemModelTester need it), set up as a GoogleTest environment so
// GTest::gtest_main stays the entry point.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <memory>

#include "model/ImportReader.h"

namespace {

class QtEnvironment : public ::testing::Environment {
  public:
    void SetUp() override {
        if (!QCoreApplication::instance())
            app_ = std::make_unique<QCoreApplication>(argc_, argv_);
        // Imports are read by the built rigmesh in a child process.
        rigmesh::model::setImportWorkerProgram(QStringLiteral(RIGMESH_CLI));
    }
    void TearDown() override { app_.reset(); }

  private:
    int argc_ = 1;
    char name_[11] = "test_model";
    char* argv_[2] = {name_, nullptr};
    std::unique_ptr<QCoreApplication> app_;
};

[[maybe_unused]] ::testing::Environment* const qtEnvironment =
    ::testing::AddGlobalTestEnvironment(new QtEnvironment);

}  // namespace
