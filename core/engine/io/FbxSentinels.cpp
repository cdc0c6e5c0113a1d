#include "io/FbxSentinels.h"

#include <assimp/version.h>

#include <algorithm>
#include <cstring>
#include <iterator>

#include "base/Error.h"
#include "io/FbxRecords.h"

namespace rigmesh {
namespace {

constexpr char kMagic[] = "Kaydara FBX Binary  ";  // then '\0', 0x1a, 0x00
constexpr std::size_t kHeaderSize = 27;            // magic, 2 bytes, uint32 version

class Parser {
  public:
    Parser(const std::vector<std::uint8_t>& bytes, bool wide) : bytes_(bytes), wide_(wide) {}

    std::uint64_t field(std::size_t at) const {
        const std::size_t size = wide_ ? 8 : 4;
        if (at + size > bytes_.size())
            fail(MessageId::FbxRepairRecordPastEnd);
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

    FbxRecord read(std::size_t at) const {
        const std::size_t end = field(at);
        const std::size_t fs = fieldSize();
        const std::size_t nameLength = bytes_[at + 3 * fs];
        const std::size_t bodyEnd = at + 3 * fs + 1 + nameLength + field(at + 2 * fs);
        FbxRecord record;
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
                fail(MessageId::FbxRepairNestedOutOfRange);
            record.children.push_back(read(cursor));
            cursor = field(cursor);
        }
        return record;
    }

    [[noreturn]] static void fail(MessageId why) { throw Error(why); }

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

    void write(const FbxRecord& record) {
        const std::size_t start = out.size();
        put(0);
        out.insert(out.end(), record.body.begin(), record.body.end());
        if (record.needsNullRecord()) {
            for (const FbxRecord& child : record.children)
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

FbxFile parseFbx(const std::vector<std::uint8_t>& file) {
    if (file.size() < kHeaderSize || std::memcmp(file.data(), kMagic, sizeof kMagic - 1) != 0)
        Parser::fail(MessageId::FbxRepairNotBinary);
    std::uint32_t version = 0;
    for (int i = 0; i < 4; ++i)
        version |= std::uint32_t(file[23 + i]) << (8 * i);
    const bool wide = version >= 7500;
    const Parser parser(file, wide);

    std::vector<FbxRecord> top;
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
        Parser::fail(MessageId::FbxRepairNoRecords);
    return {wide, std::move(top), cursor};
}

std::vector<std::uint8_t> writeFbx(const std::vector<std::uint8_t>& file, const FbxFile& fbx) {
    Writer writer(fbx.wide);
    // Room for the file and the null records it may lack: one allocation,
    // not a copy at each doubling of a file of many megabytes.
    writer.out.reserve(file.size() + file.size() / 4 + 4096);
    writer.out.assign(file.begin(), file.begin() + kHeaderSize);
    for (const FbxRecord& record : fbx.top)
        writer.write(record);
    writer.putNull();
    writer.out.insert(writer.out.end(), file.begin() + static_cast<std::ptrdiff_t>(fbx.footer),
                      file.end());
    return std::move(writer.out);
}

std::vector<FbxProperty> fbxProperties(const FbxRecord& record, bool wide) {
    const std::size_t fs = wide ? 8 : 4;
    const std::vector<std::uint8_t>& body = record.body;
    if (body.size() < 2 * fs + 1)
        return {};
    std::uint64_t count = 0;
    for (std::size_t i = 0; i < fs; ++i)
        count |= std::uint64_t(body[i]) << (8 * i);
    std::size_t at = 2 * fs + 1 + record.name.size();
    auto u32 = [&](std::size_t from) {
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < 4; ++i)
            value |= std::uint32_t(body[from + i]) << (8 * i);
        return value;
    };
    std::vector<FbxProperty> out;
    for (std::uint64_t p = 0; p < count; ++p) {
        if (at >= body.size())
            return {};
        const char type = static_cast<char>(body[at]);
        const std::size_t data = at + 1;
        std::size_t size = 0;
        switch (type) {
            case 'C':
                size = 1;
                break;
            case 'Y':
                size = 2;
                break;
            case 'I':
            case 'F':
                size = 4;
                break;
            case 'D':
            case 'L':
                size = 8;
                break;
            case 'S':
            case 'R':
                if (data + 4 > body.size())
                    return {};
                size = 4 + std::size_t(u32(data));
                break;
            case 'f':
            case 'd':
            case 'l':
            case 'i':
            case 'b':
                if (data + 12 > body.size())
                    return {};
                size = 12 + std::size_t(u32(data + 8));
                break;
            default:
                return {};
        }
        if (data + size > body.size())
            return {};
        out.push_back({type, data});
        at = data + size;
    }
    return out;
}

namespace {

void putString(std::vector<std::uint8_t>& out, const std::string& text) {
    out.push_back('S');
    putFbxLittleEndian(out, text.size(), 4);
    out.insert(out.end(), text.begin(), text.end());
}

void putDouble(std::vector<std::uint8_t>& out, double value) {
    out.push_back('D');
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    putFbxLittleEndian(out, bits, 8);
}

// A Properties70 entry `P` of `count` properties already encoded.
FbxRecord propertyRecord(std::uint64_t count, const std::vector<std::uint8_t>& properties,
                         bool wide) {
    FbxRecord record;
    record.name = "P";
    putFbxLittleEndian(record.body, count, wide ? 8 : 4);
    putFbxLittleEndian(record.body, properties.size(), wide ? 8 : 4);
    record.body.push_back(1);
    record.body.push_back('P');
    record.body.insert(record.body.end(), properties.begin(), properties.end());
    return record;
}

// P: "name", "Vector", "", "A+U", x, y, z.
FbxRecord vectorProperty(const std::string& name, const Vec3& value, bool wide) {
    std::vector<std::uint8_t> properties;
    putString(properties, name);
    putString(properties, "Vector");
    putString(properties, "");
    putString(properties, "A+U");
    for (int k = 0; k < 3; ++k)
        putDouble(properties, value[k]);
    return propertyRecord(7, properties, wide);
}

// P: "name", "KString", "", "U", "value".
FbxRecord stringProperty(const std::string& name, const std::string& value, bool wide) {
    std::vector<std::uint8_t> properties;
    putString(properties, name);
    putString(properties, "KString");
    putString(properties, "");
    putString(properties, "U");
    putString(properties, value);
    return propertyRecord(5, properties, wide);
}

// A Model record's name: its second property, "<name>\0\1Model".
std::string modelName(const FbxRecord& model, bool wide) {
    const std::size_t fs = wide ? 8 : 4;
    std::size_t at = 2 * fs + 1 + model.name.size();
    if (at + 9 > model.body.size() || model.body[at] != 'L')
        return "";
    at += 9;
    if (at + 5 > model.body.size() || model.body[at] != 'S')
        return "";
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i)
        length |= std::uint32_t(model.body[at + 1 + static_cast<std::size_t>(i)]) << (8 * i);
    if (at + 5 + length > model.body.size())
        return "";
    const std::string full(model.body.begin() + static_cast<std::ptrdiff_t>(at + 5),
                           model.body.begin() + static_cast<std::ptrdiff_t>(at + 5 + length));
    return full.substr(0, full.find('\0'));
}

// make(value) appended to the Properties70 of each Model named in `values`.
template <typename Value, typename Make>
void addModelProperties(FbxFile& fbx, const std::map<std::string, Value>& values, Make make) {
    for (FbxRecord& objects : fbx.top) {
        if (objects.name != "Objects")
            continue;
        for (FbxRecord& model : objects.children) {
            if (model.name != "Model")
                continue;
            const auto value = values.find(modelName(model, fbx.wide));
            if (value == values.end())
                continue;
            auto table = std::find_if(model.children.begin(), model.children.end(),
                                      [](const FbxRecord& r) { return r.name == "Properties70"; });
            if (table == model.children.end()) {
                FbxRecord properties;
                properties.name = "Properties70";
                putFbxLittleEndian(properties.body, 0, fbx.wide ? 8 : 4);
                putFbxLittleEndian(properties.body, 0, fbx.wide ? 8 : 4);
                properties.body.push_back(12);
                properties.body.insert(properties.body.end(), properties.name.begin(),
                                       properties.name.end());
                properties.noProperties = true;
                model.children.insert(model.children.begin(), properties);
                model.nested = true;
                table = model.children.begin();
            }
            table->children.push_back(make(value->second, fbx.wide));
            table->nested = true;
        }
    }
}

}  // namespace

std::vector<std::uint8_t> addFbxSentinels(const std::vector<std::uint8_t>& file) {
    return writeFbx(file, parseFbx(file));
}

void addFbxModelVectors(FbxFile& fbx, const std::string& property,
                        const std::map<std::string, Vec3>& values) {
    addModelProperties(fbx, values, [&](const Vec3& value, bool wide) {
        return vectorProperty(property, value, wide);
    });
}

void addFbxModelStrings(FbxFile& fbx, const std::string& property,
                        const std::map<std::string, std::string>& values) {
    addModelProperties(fbx, values, [&](const std::string& value, bool wide) {
        return stringProperty(property, value, wide);
    });
}

}  // namespace rigmesh
