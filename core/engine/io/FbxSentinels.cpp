#include "io/FbxSentinels.h"

#include <assimp/version.h>

#include <cstring>
#include <iterator>

#include "base/Error.h"

namespace rigmesh {
namespace {

constexpr char kMagic[] = "Kaydara FBX Binary  ";  // then '\0', 0x1a, 0x00
constexpr std::size_t kHeaderSize = 27;            // magic, 2 bytes, uint32 version

struct Record {
    std::vector<std::uint8_t> body;  // property count .. properties (no end offset)
    std::vector<Record> children;
    std::string name;
    bool noProperties = false;
    bool nested = false;  // had a nested list (possibly only a null record)

    // The FBX SDK's rule (as Blender's encode_bin.py writes it): a nested
    // list, hence a null record, for a node with children, a node without
    // properties, and always for AnimationStack and AnimationLayer (Assimp's
    // reader drops the animation otherwise: "expected compound scope").
    bool needsNullRecord() const {
        return nested || !children.empty() || noProperties || name == "AnimationStack" ||
               name == "AnimationLayer";
    }
};

class Parser {
  public:
    Parser(const std::vector<std::uint8_t>& bytes, bool wide) : bytes_(bytes), wide_(wide) {}

    std::uint64_t field(std::size_t at) const {
        const std::size_t size = wide_ ? 8 : 4;
        if (at + size > bytes_.size())
            fail("a record runs past the end of the file");
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < size; ++i)
            value |= std::uint64_t(bytes_[at + i]) << (8 * i);
        return value;
    }
    std::size_t fieldSize() const { return wide_ ? 8 : 4; }
    std::size_t nullSize() const { return 3 * fieldSize() + 1; }

    bool isNull(std::size_t at) const {
        if (at + nullSize() > bytes_.size())
            return false;
        for (std::size_t i = 0; i < nullSize(); ++i)
            if (bytes_[at + i] != 0)
                return false;
        return true;
    }

    // Whether a plausible record starts at `at` and ends by `limit`.
    bool isRecord(std::size_t at, std::size_t limit) const {
        const std::size_t header = 3 * fieldSize() + 1;
        if (at + header > limit)
            return false;
        const std::uint64_t end = field(at);
        const std::uint64_t propertiesLength = field(at + 2 * fieldSize());
        const std::size_t nameLength = bytes_[at + 3 * fieldSize()];
        return end > at && end <= limit && at + header + nameLength + propertiesLength <= end;
    }

    Record read(std::size_t at) const {
        const std::size_t end = field(at);
        const std::size_t fs = fieldSize();
        const std::size_t nameLength = bytes_[at + 3 * fs];
        const std::size_t bodyEnd = at + 3 * fs + 1 + nameLength + field(at + 2 * fs);
        Record record;
        record.name.assign(
            bytes_.begin() + static_cast<std::ptrdiff_t>(at + 3 * fs + 1),
            bytes_.begin() + static_cast<std::ptrdiff_t>(at + 3 * fs + 1 + nameLength));
        record.noProperties = field(at + fs) == 0;
        record.body.assign(bytes_.begin() + static_cast<std::ptrdiff_t>(at + fs),
                           bytes_.begin() + static_cast<std::ptrdiff_t>(bodyEnd));
        std::size_t cursor = bodyEnd;
        record.nested = cursor < end;
        while (cursor < end) {
            if (isNull(cursor) && cursor + nullSize() == end)
                break;  // the sentinel is already there
            if (!isRecord(cursor, end))
                fail("a nested record is out of range");
            record.children.push_back(read(cursor));
            cursor = field(cursor);
        }
        return record;
    }

    [[noreturn]] static void fail(const std::string& why) {
        throw Error("cannot repair the FBX file: " + why);
    }

  private:
    const std::vector<std::uint8_t>& bytes_;
    bool wide_;
};

class Writer {
  public:
    explicit Writer(bool wide) : wide_(wide) {}
    std::vector<std::uint8_t> out;

    void put(std::uint64_t value) {
        for (std::size_t i = 0; i < (wide_ ? 8u : 4u); ++i)
            out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    }
    void patch(std::size_t at, std::uint64_t value) {
        for (std::size_t i = 0; i < (wide_ ? 8u : 4u); ++i)
            out[at + i] = static_cast<std::uint8_t>(value >> (8 * i));
    }
    void putNull() { out.insert(out.end(), 3 * (wide_ ? 8u : 4u) + 1, 0); }

    void write(const Record& record) {
        const std::size_t start = out.size();
        put(0);
        out.insert(out.end(), record.body.begin(), record.body.end());
        if (record.needsNullRecord()) {
            for (const Record& child : record.children)
                write(child);
            putNull();
        }
        patch(start, out.size());
    }

  private:
    bool wide_;
};

}  // namespace

bool assimpNeedsFbxSentinelFix() {
    return aiGetVersionMajor() < 5 || (aiGetVersionMajor() == 5 && aiGetVersionMinor() < 3);
}

std::vector<std::uint8_t> addFbxSentinels(const std::vector<std::uint8_t>& file) {
    if (file.size() < kHeaderSize || std::memcmp(file.data(), kMagic, sizeof kMagic - 1) != 0)
        Parser::fail("not a binary FBX file");
    std::uint32_t version = 0;
    for (int i = 0; i < 4; ++i)
        version |= std::uint32_t(file[23 + i]) << (8 * i);
    const bool wide = version >= 7500;
    const Parser parser(file, wide);

    std::vector<Record> top;
    std::size_t cursor = kHeaderSize;
    while (cursor < file.size()) {
        if (parser.isNull(cursor)) {
            cursor += parser.nullSize();
            break;
        }
        if (!parser.isRecord(cursor, file.size()))
            break;  // the footer
        top.push_back(parser.read(cursor));
        cursor = parser.field(cursor);
    }
    if (top.empty())
        Parser::fail("no node records");
    Writer writer(wide);
    writer.out.assign(file.begin(), file.begin() + kHeaderSize);
    for (const Record& record : top)
        writer.write(record);
    writer.putNull();
    writer.out.insert(writer.out.end(), file.begin() + static_cast<std::ptrdiff_t>(cursor),
                      file.end());
    return std::move(writer.out);
}

}  // namespace rigmesh
