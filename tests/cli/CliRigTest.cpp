// `rigmesh rig` end to end: a plain OBJ of one of our sketches
// comes out rigged in every format; a mesh that cannot be rigged is a
// one-line reason with exit code 1 and no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "CliRunner.h"

namespace fs = std::filesystem;
using rigmesh::test::quoted;
using rigmesh::test::runCli;
using rigmesh::test::scratch;

namespace {

// The star's surface as a plain OBJ, as another tool would write it.
const fs::path& starObj() {
    static const fs::path obj = [] {
        const fs::path path = scratch("rig_star.obj");
        const auto built = runCli("build '" + std::string(RIGMESH_SHARED_SKETCHES) +
                                  "/star.json' -o " + quoted(path));
        EXPECT_EQ(built.exitCode, 0) << built.err;
        return path;
    }();
    return obj;
}

TEST(CliRig, APlainObjIsRiggedAndWrittenInEveryRiggedFormat) {
    for (const std::string extension : {".rigmesh", ".glb", ".fbx", ".dae"}) {
        const fs::path out = scratch("rigged_star" + extension);
        const auto result = runCli("rig " + quoted(starObj()) + " -o " + quoted(out));
        ASSERT_EQ(result.exitCode, 0) << result.err;
        EXPECT_NE(result.out.find("rigged with"), std::string::npos) << result.out;
        ASSERT_TRUE(fs::exists(out)) << extension;
        if (extension == ".rigmesh")
            continue;
        // Read back as a user's import would be: rigged, nothing left to rig.
        const auto imported =
            runCli("import " + quoted(out) + " -o " + quoted(scratch("reimported.rigmesh")));
        ASSERT_EQ(imported.exitCode, 0) << imported.err;
        EXPECT_NE(imported.out.find("(0 unrigged)"), std::string::npos) << imported.out;
    }
}

TEST(CliRig, AFileWithNothingToRigIsRefused) {
    const fs::path rigged = scratch("already.glb");
    ASSERT_EQ(runCli("rig " + quoted(starObj()) + " -o " + quoted(rigged)).exitCode, 0);
    const fs::path out = scratch("again.glb");
    const auto result = runCli("rig " + quoted(rigged) + " -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.err.find("nothing to rig"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out));
}

// Separate pieces are rigged together on a closed proxy wrapped around them
// (autorig/ProxyWrap), and the summary says so.
TEST(CliRig, TwoSeparatePiecesAreRiggedOnAProxyThatTheSummaryNames) {
    const fs::path obj = scratch("two_pieces.obj");
    {
        std::ofstream file(obj);
        for (int piece = 0; piece < 2; ++piece) {
            const double x = piece * 3.0;
            file << "v " << x << " 0 0\nv " << x + 1 << " 0 0\nv " << x << " 1 0\nv " << x
                 << " 0 1\n";
        }
        for (int piece = 0; piece < 2; ++piece) {
            const int o = piece * 4;
            file << "f " << o + 1 << ' ' << o + 3 << ' ' << o + 2 << "\nf " << o + 1 << ' ' << o + 2
                 << ' ' << o + 4 << "\nf " << o + 1 << ' ' << o + 4 << ' ' << o + 3 << "\nf "
                 << o + 2 << ' ' << o + 3 << ' ' << o + 4 << "\n";
        }
    }
    const fs::path out = scratch("two_pieces.glb");
    const auto result = runCli("rig " + quoted(obj) + " -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 0) << result.err;
    const std::string said = result.out + result.err;
    EXPECT_NE(said.find("2 separate pieces"), std::string::npos) << said;
    EXPECT_NE(said.find("closed proxy"), std::string::npos) << said;
    EXPECT_TRUE(fs::exists(out));
}

TEST(CliRig, MisuseSaysHow) {
    EXPECT_EQ(runCli("rig").exitCode, 1);
    const auto noOutput = runCli("rig " + quoted(starObj()));
    EXPECT_EQ(noOutput.exitCode, 1);
    EXPECT_NE(noOutput.err.find("-o"), std::string::npos);
    const auto badFormat = runCli("rig " + quoted(starObj()) + " -o x.xyz");
    EXPECT_EQ(badFormat.exitCode, 1);
    EXPECT_NE(badFormat.err.find("unknown format"), std::string::npos);
}

}  // namespace
