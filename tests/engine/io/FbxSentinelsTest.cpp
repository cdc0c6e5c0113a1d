#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "IoTestSupport.h"
#include "base/Error.h"
#include "io/FbxSentinels.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"

namespace rigmesh {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Node {
    std::string name;
    Bytes properties;  // already encoded
    int propertyCount = 0;
    std::vector<Node> children;
};

void put(Bytes& out, std::uint64_t value, bool wide) {
    for (int i = 0; i < (wide ? 8 : 4); ++i)
        out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

// Writes a record as an FBX writer would, with or without the null records.
void write(Bytes& out, const Node& node, bool wide, bool sentinels) {
    const std::size_t start = out.size();
    put(out, 0, wide);
    put(out, static_cast<std::uint64_t>(node.propertyCount), wide);
    put(out, node.properties.size(), wide);
    out.push_back(static_cast<std::uint8_t>(node.name.size()));
    out.insert(out.end(), node.name.begin(), node.name.end());
    out.insert(out.end(), node.properties.begin(), node.properties.end());
    for (const Node& child : node.children)
        write(out, child, wide, sentinels);
    // The FBX SDK's rule (FbxSentinels.h).
    if (sentinels &&
        (!node.children.empty() || node.propertyCount == 0 || node.name == "AnimationLayer"))
        out.insert(out.end(), wide ? 25 : 13, 0);
    Bytes end;
    put(end, out.size(), wide);
    std::copy(end.begin(), end.end(), out.begin() + static_cast<std::ptrdiff_t>(start));
}

const Bytes kFooter = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                       0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};

Bytes file(std::uint32_t version, bool sentinels) {
    Bytes out(27, 0);
    std::memcpy(out.data(), "Kaydara FBX Binary  ", 20);
    out[21] = 0x1a;
    for (int i = 0; i < 4; ++i)
        out[23 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(version >> (8 * i));
    const bool wide = version >= 7500;
    Node leaf{"Leaf", {'I', 42, 0, 0, 0}, 1, {}};
    Node inner{"Inner", {'S', 2, 0, 0, 0, 'h', 'i'}, 1, {leaf, leaf}};
    Node layer{"AnimationLayer", {'I', 7, 0, 0, 0}, 1, {}};
    Node top{"Objects", {}, 0, {inner, Node{"Empty", {}, 0, {}}, layer}};
    write(out, Node{"Header", {'I', 1, 0, 0, 0}, 1, {}}, wide, sentinels);
    write(out, top, wide, sentinels);
    if (sentinels)
        out.insert(out.end(), wide ? 25 : 13, 0);
    out.insert(out.end(), kFooter.begin(), kFooter.end());
    return out;
}

// A strict reader: every nested list and the top level must end with a null
// record (as Blender's and Assimp's readers demand). Returns the names.
class StrictReader {
  public:
    StrictReader(const Bytes& bytes) : bytes_(bytes) {
        std::uint32_t version = 0;
        std::memcpy(&version, bytes.data() + 23, 4);
        wide_ = version >= 7500;
    }
    std::uint64_t field(std::size_t at) const {
        std::uint64_t value = 0;
        for (int i = 0; i < (wide_ ? 8 : 4); ++i)
            value |= std::uint64_t(bytes_.at(at + static_cast<std::size_t>(i))) << (8 * i);
        return value;
    }
    std::size_t fs() const { return wide_ ? 8 : 4; }
    std::size_t nullSize() const { return 3 * fs() + 1; }
    // Reads records from `at` up to and including the null record.
    std::size_t list(std::size_t at, std::string& names) const {
        while (true) {
            const std::uint64_t end = field(at);
            if (end == 0) {
                for (std::size_t i = 0; i < nullSize(); ++i)
                    EXPECT_EQ(bytes_.at(at + i), 0) << "null record at " << at;
                return at + nullSize();
            }
            const std::size_t nameLength = bytes_.at(at + 3 * fs());
            names += std::string(
                bytes_.begin() + static_cast<std::ptrdiff_t>(at + 3 * fs() + 1),
                bytes_.begin() + static_cast<std::ptrdiff_t>(at + 3 * fs() + 1 + nameLength));
            const std::size_t body = at + 3 * fs() + 1 + nameLength + field(at + 2 * fs());
            if (body < end) {
                names += "{";
                EXPECT_EQ(list(body, names), end) << "nested list of record at " << at;
                names += "}";
            }
            names += ";";
            at = end;
        }
    }
    std::string names(bool syntheticFooter = true) const {
        std::string out;
        const std::size_t end = list(27, out);
        if (syntheticFooter) {
            EXPECT_EQ(Bytes(bytes_.begin() + static_cast<std::ptrdiff_t>(end), bytes_.end()),
                      kFooter);
        }
        return out;
    }

  private:
    const Bytes& bytes_;
    bool wide_ = true;
};

TEST(FbxSentinels, AddsTheNullRecordsTo64BitFiles) {
    const Bytes fixed = addFbxSentinels(file(7500, false));
    EXPECT_EQ(fixed, file(7500, true));
    EXPECT_EQ(StrictReader(fixed).names(),
              "Header;Objects{Inner{Leaf;Leaf;};Empty{};AnimationLayer{};};");
}

TEST(FbxSentinels, AddsTheNullRecordsTo32BitFiles) {
    const Bytes fixed = addFbxSentinels(file(7400, false));
    EXPECT_EQ(fixed, file(7400, true));
    EXPECT_EQ(StrictReader(fixed).names(),
              "Header;Objects{Inner{Leaf;Leaf;};Empty{};AnimationLayer{};};");
}

TEST(FbxSentinels, LeavesACorrectFileUnchanged) {
    EXPECT_EQ(addFbxSentinels(file(7500, true)), file(7500, true));
    EXPECT_EQ(addFbxSentinels(file(7400, true)), file(7400, true));
}

TEST(FbxSentinels, RejectsWhatIsNotABinaryFbx) {
    const std::string text = "; FBX 7.5.0 project file";
    EXPECT_THROW(addFbxSentinels(Bytes(text.begin(), text.end())), Error);
    Bytes broken = file(7500, false);
    broken[27] = 0xff;  // the first end offset points far past the end
    broken[28] = 0xff;
    EXPECT_THROW(addFbxSentinels(broken), Error);
}

TEST(FbxSentinels, TheLinkedAssimpNeedsThePass) {
    // Debian 12 ships Assimp 5.2.5; 5.3 writes the sentinels itself.
    EXPECT_TRUE(assimpNeedsFbxSentinelFix());
}

TEST(FbxSentinels, ARealExportHasEveryNullRecordAndReadsBack) {
    const Part& part = iotest::sharedPart("tube");
    const Clip clip = poseDemoClip(part);
    const auto path = iotest::scratchFolder() / "tube.fbx";
    ExportPart item;
    item.part = &part;
    exportScene({item}, &clip, path.string());
    std::ifstream in(path, std::ios::binary);
    const Bytes bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string names = StrictReader(bytes).names(false);
    EXPECT_NE(names.find("Objects{"), std::string::npos);
    EXPECT_NE(names.find("Connections{"), std::string::npos);
    EXPECT_EQ(addFbxSentinels(bytes), bytes);  // already complete
    EXPECT_FALSE(importScene(path.string()).parts.empty());
}

}  // namespace
}  // namespace rigmesh
