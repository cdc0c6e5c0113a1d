// `rigmesh import FILE -o PARTS.rigmesh` run by hand holds itself to the
// limits the studio's import child gets (model/ImportReader.h): a file that
// would make the reader allocate gigabytes ends at once with our message
// naming the limit, not a library's "std::bad_alloc", and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "CliRunner.h"
#include "base/ChildProcess.h"

namespace rigmesh::test {
namespace {

TEST(CliImportByHand, AFileThatWouldNeedGigabytesIsRefusedAtTheMemoryLimit) {
    if (!addressSpaceLimitsSupported())
        GTEST_SKIP() << "address-space limits do not work in this build (sanitizers)";
    // A binary PLY that declares two billion vertices and holds none: Assimp
    // 5.2.5 reserves room for all of them before it reads one.
    const std::filesystem::path file = scratch("two_billion_vertices.ply");
    std::ofstream(file) << "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
                           "property float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::filesystem::path out = scratch("two_billion_vertices.rigmesh");
    const CliResult result = runCli("import " + quoted(file) + " -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("two_billion_vertices.ply"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("GiB"), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find("bad_alloc"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rigmesh::test
