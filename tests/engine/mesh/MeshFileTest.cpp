#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "FullDisk.h"
#include "base/Error.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/MeshWriter.h"
#include "mesh/PlyReader.h"

namespace rigmesh {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class MeshFile : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("rigmesh_test_mesh_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    static std::string contents(const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream out;
        out << in.rdbuf();
        return out.str();
    }
    static void store(const std::string& file, const std::string& bytes) {
        std::ofstream(file, std::ios::binary) << bytes;
    }

    fs::path dir_;
};

// Coordinates that only survive a round trip if every bit is kept.
TriMesh awkwardMesh() {
    TriMesh mesh = makeIcosphere(1, 1.0 / 3.0);
    mesh.vertices[0] = Vec3(0.1, -1e-300, 1e300);
    mesh.vertices[1] =
        Vec3(std::numeric_limits<double>::denorm_min(), -0.0, std::numeric_limits<double>::max());
    mesh.vertices[2] = Vec3(1.0 / 7.0, -2.0 / 3.0, std::nextafter(1.0, 2.0));
    return mesh;
}

void expectBitExact(const TriMesh& expected, const TriMesh& actual) {
    ASSERT_EQ(actual.vertexCount(), expected.vertexCount());
    EXPECT_EQ(actual.faces, expected.faces);
    for (int i = 0; i < expected.vertexCount(); ++i)
        EXPECT_EQ(
            std::memcmp(actual.vertices[i].data(), expected.vertices[i].data(), 3 * sizeof(double)),
            0)
            << "vertex " << i << " differs";
}

TEST_F(MeshFile, ObjRoundTripIsExact) {
    const TriMesh mesh = awkwardMesh();
    writeMesh(mesh, path("a.obj"));
    expectBitExact(mesh, readMesh(path("a.obj")));
}

TEST_F(MeshFile, OffRoundTripIsExact) {
    const TriMesh mesh = awkwardMesh();
    writeMesh(mesh, path("a.off"));
    expectBitExact(mesh, readMesh(path("a.off")));
}

TEST_F(MeshFile, BinaryPlyRoundTripIsBitExact) {
    const TriMesh mesh = awkwardMesh();
    writeMesh(mesh, path("a.ply"));
    const TriMesh read = readMesh(path("a.ply"));
    expectBitExact(mesh, read);
    // Writing what was read reproduces the file byte for byte.
    writeMesh(read, path("b.ply"));
    EXPECT_EQ(contents(path("a.ply")), contents(path("b.ply")));
    EXPECT_NE(contents(path("a.ply")).find("format binary_little_endian 1.0"), std::string::npos);
}

TEST_F(MeshFile, ExtensionIsCaseInsensitive) {
    writeMesh(makeIcosphere(0, 1.0), path("upper.OBJ"));
    EXPECT_EQ(readMesh(path("upper.OBJ")).faceCount(), 20);
}

TEST_F(MeshFile, PlyStoresVertexColours) {
    const TriMesh mesh = makeIcosphere(0, 1.0);
    MeshWriteOptions options;
    for (int i = 0; i < mesh.vertexCount(); ++i)
        options.vertexColors.push_back(
            {static_cast<std::uint8_t>(i * 20), static_cast<std::uint8_t>(255 - i), 7});
    writeMesh(mesh, path("c.ply"), options);
    EXPECT_NE(contents(path("c.ply")).find("property uchar red"), std::string::npos);

    std::vector<VertexColor> colors;
    expectBitExact(mesh, readMesh(path("c.ply"), &colors));
    EXPECT_EQ(colors, options.vertexColors);
}

TEST_F(MeshFile, PlyWithoutColoursReadsNoColours) {
    writeMesh(makeIcosphere(0, 1.0), path("plain.ply"));
    std::vector<VertexColor> colors = {{1, 2, 3}};
    readMesh(path("plain.ply"), &colors);
    EXPECT_TRUE(colors.empty());
}

TEST_F(MeshFile, ColourCountMismatchThrows) {
    MeshWriteOptions options;
    options.vertexColors = {{1, 2, 3}};
    EXPECT_THROW(writeMesh(makeIcosphere(0, 1.0), path("c.ply"), options), std::logic_error);
}

TEST_F(MeshFile, UnknownExtensionThrowsNamingSupportedOnes) {
    try {
        writeMesh(makeIcosphere(0, 1.0), path("mesh.stl"));
        FAIL() << "expected an Error";
    } catch (const Error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(".obj"), std::string::npos) << message;
        EXPECT_NE(message.find(".off"), std::string::npos) << message;
        EXPECT_NE(message.find(".ply"), std::string::npos) << message;
    }
    EXPECT_FALSE(fs::exists(path("mesh.stl")));
}

TEST_F(MeshFile, WritingIntoMissingDirectoryThrowsAndLeavesNoTempFile) {
    const std::string target = path("missing/sub/mesh.obj");
    try {
        writeMesh(makeIcosphere(0, 1.0), target);
        FAIL() << "expected an Error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos)
            << error.what();
    }
    EXPECT_FALSE(fs::exists(target));
    EXPECT_FALSE(fs::exists(target + ".tmp"));
}

TEST_F(MeshFile, FailedRenameRemovesTempFileAndKeepsTarget) {
    // A directory where the file should go makes the final rename fail.
    fs::create_directories(path("taken.obj/inside"));
    EXPECT_THROW(writeMesh(makeIcosphere(0, 1.0), path("taken.obj")), Error);
    EXPECT_TRUE(fs::is_directory(path("taken.obj/inside")));
    EXPECT_FALSE(fs::exists(path("taken.obj.tmp")));
}

TEST_F(MeshFile, OverwritingReplacesTheFileAndLeavesNoTempFile) {
    writeMesh(makeIcosphere(0, 1.0), path("m.off"));
    writeMesh(makeIcosphere(1, 1.0), path("m.off"));
    EXPECT_EQ(readMesh(path("m.off")).faceCount(), 80);
    EXPECT_FALSE(fs::exists(path("m.off.tmp")));
}

TEST_F(MeshFile, ObjFacesWithSlashesAndPolygonsAreFanTriangulated) {
    store(path("q.obj"),
          "# quad and pentagon\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 2 0\nvt 0 0\n"
          "vn 0 0 1\ng part\nf 1/1/1 2/1/1 3/1/1 4/1/1\nf 1//1 2//1 3//1\nf -5 -4 -3 -1 -2\n");
    const TriMesh mesh = readMesh(path("q.obj"));
    EXPECT_EQ(mesh.vertexCount(), 5);
    const std::vector<std::array<int, 3>> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2},
                                                      {0, 1, 2}, {0, 2, 4}, {0, 4, 3}};
    EXPECT_EQ(mesh.faces, expected);
}

TEST_F(MeshFile, AsciiPlyWithQuadIsRead) {
    store(path("q.ply"),
          "ply\r\nformat ascii 1.0\r\ncomment hand written\r\nelement vertex 4\r\n"
          "property float x\r\nproperty float y\r\nproperty float z\r\nelement face 1\r\n"
          "property list uchar uint vertex_index\r\nend_header\r\n"
          "0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n4 0 1 2 3\r\n");
    const TriMesh mesh = readMesh(path("q.ply"));
    EXPECT_EQ(mesh.vertexCount(), 4);
    const std::vector<std::array<int, 3>> expected = {{0, 1, 2}, {0, 2, 3}};
    EXPECT_EQ(mesh.faces, expected);
}

// The message of the Error readMesh throws, or "" if it did not throw.
std::string readError(const std::string& file) {
    try {
        readMesh(file);
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST_F(MeshFile, TruncatedBinaryPlyThrowsAtEveryCut) {
    writeMesh(makeIcosphere(0, 1.0), path("full.ply"));
    const std::string bytes = contents(path("full.ply"));
    // Parse in memory: one file per cut would make this test slow.
    for (std::size_t length = 0; length < bytes.size(); ++length)
        EXPECT_THROW(readPly(std::string_view(bytes).substr(0, length), "full.ply", nullptr), Error)
            << "cut at " << length;

    store(path("cut.ply"), bytes.substr(0, bytes.size() / 2));
    const std::string message = readError(path("cut.ply"));
    EXPECT_NE(message.find("cut.ply"), std::string::npos) << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST_F(MeshFile, TruncatedTextFilesNeverCrash) {
    constexpr std::size_t kCutStride = 11;  // a spread of cuts through numbers and line ends
    for (const std::string name : {"full.obj", "full.off"}) {
        writeMesh(makeIcosphere(0, 1.0), path(name));
        const std::string bytes = contents(path(name));
        const std::string cut = "cut" + name.substr(4);
        for (std::size_t length = 0; length < bytes.size(); length += kCutStride) {
            store(path(cut), bytes.substr(0, length));
            // A cut inside the last number can still be a valid file; either is fine.
            try {
                readMesh(path(cut));
            } catch (const Error&) {
            }
        }
    }
}

TEST_F(MeshFile, TruncatedOffSaysItEndsEarly) {
    writeMesh(makeIcosphere(0, 1.0), path("full.off"));
    const std::string bytes = contents(path("full.off"));
    // Cut at a line end so that what remains is well formed, only short.
    store(path("cut.off"), bytes.substr(0, bytes.find('\n', bytes.size() / 2) + 1));
    const std::string message = readError(path("cut.off"));
    EXPECT_NE(message.find("ends early"), std::string::npos) << message;
}

TEST_F(MeshFile, CorruptObjNamesTheLine) {
    store(path("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 abc 0\nf 1 2 3\n");
    const std::string message = readError(path("bad.obj"));
    EXPECT_NE(message.find("line 3"), std::string::npos) << message;
    EXPECT_NE(message.find("abc"), std::string::npos) << message;
}

TEST_F(MeshFile, ObjFaceReferringToMissingVertexThrows) {
    store(path("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    EXPECT_NE(readError(path("bad.obj")), "");
}

TEST_F(MeshFile, PlyWithHugeDeclaredCountThrowsInsteadOfAllocating) {
    store(path("huge.ply"),
          "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
          "property double x\nproperty double y\nproperty double z\nend_header\n");
    EXPECT_NE(readError(path("huge.ply")).find("truncated"), std::string::npos);
}

TEST_F(MeshFile, GarbageIsRejectedForEveryFormat) {
    const std::string garbage("\x7f\x00\xff garbage \n\n\x01", 14);
    for (const std::string name : {"g.obj", "g.off", "g.ply"}) {
        store(path(name), garbage);
        if (name != "g.obj")  // OBJ ignores lines it does not know, yielding an empty mesh
            EXPECT_NE(readError(path(name)), "") << name;
        else
            EXPECT_EQ(readMesh(path(name)).faceCount(), 0);
    }
}

TEST_F(MeshFile, MissingFileThrows) {
    EXPECT_NE(readError(path("nothing.obj")).find("does not exist"), std::string::npos);
}

// On a full disk, OBJ once exited 0 and replaced the file with a
// truncated one.
TEST_F(MeshFile, AFullDiskIsAnErrorAndLeavesThePreviousFileAndNoTemporaryFile) {
    const TriMesh big = makeIcosphere(4, 1.0);
    for (const std::string name : {"full.obj", "full.off", "full.ply"}) {
        writeMesh(makeIcosphere(1, 1.0), path(name));
        const std::string previous = contents(path(name));
        EXPECT_EQ(fulldisk::runOnFullDisk(2048, [&] { writeMesh(big, path(name)); }),
                  fulldisk::FullDiskOutcome::RefusedWithError)
            << name;
        EXPECT_EQ(contents(path(name)), previous) << name;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);
}

TEST_F(MeshFile, WritingKeepsPermissionsAndRefusesReadOnlyFiles) {
    const TriMesh mesh = makeIcosphere(1, 1.0);
    writeMesh(mesh, path("kept.obj"));
    fs::permissions(path("kept.obj"), fs::perms::owner_read | fs::perms::owner_write);
    writeMesh(mesh, path("kept.obj"));
    EXPECT_EQ(fs::status(path("kept.obj")).permissions(),
              fs::perms::owner_read | fs::perms::owner_write);
    fs::permissions(path("kept.obj"), fs::perms::owner_read);
    EXPECT_THROW(writeMesh(mesh, path("kept.obj")), Error);
}

TEST_F(MeshFile, NonFiniteCoordinatesAreRefused) {
    TriMesh mesh = makeIcosphere(1, 1.0);
    mesh.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(writeMesh(mesh, path("nan.obj")), Error);
    EXPECT_FALSE(fs::exists(path("nan.obj")));
}

}  // namespace
}  // namespace rigmesh
