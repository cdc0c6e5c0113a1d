// A seeded mutation fuzzer over File > Import (issue 9 item 6): our own
// exports of a rigged part in every format Assimp reads for us are mutated
// (bit flips, overwritten bytes, truncation, repeated and removed chunks,
// extreme numbers in text) and imported through the child process. Every
// input must give valid parts or an Error with a message, within the time
// limit plus a margin: never another exception, a crash of the caller or a
// hang. Runs RIGMESH_FUZZ_SECONDS seconds per format (default 3; the seed is
// RIGMESH_FUZZ_SEED, default 1). A failing input is saved next to the test
// binary as import-fuzz-failure.<ext> to become a regression test.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <chrono>
#include <cstdlib>
#include <map>
#include <random>

#include "ModelTestSupport.h"
#include "base/Error.h"
#include "mesh/MeshWriter.h"
#include "model/DocumentExport.h"
#include "model/ImportReader.h"

namespace rigmesh::model {
namespace {

using test::addPart;
using test::sharedStroke;

double fuzzSeconds() {
    const char* value = std::getenv("RIGMESH_FUZZ_SECONDS");
    return value ? std::atof(value) : 3.0;
}

unsigned fuzzSeed() {
    const char* value = std::getenv("RIGMESH_FUZZ_SEED");
    return value ? static_cast<unsigned>(std::strtoul(value, nullptr, 10)) : 1u;
}

// One random edit of `bytes`.
void mutate(QByteArray& bytes, std::mt19937& random) {
    if (bytes.isEmpty()) {
        bytes.append(char(random()));
        return;
    }
    auto at = [&](qsizetype size) {
        return static_cast<qsizetype>(random() % static_cast<unsigned>(size));
    };
    static const char* extremes[] = {"1e308", "-1e308",     "nan",        "inf", "1e999",
                                     "-0",    "4294967295", "2147483648", "-1",  "99999999999"};
    switch (random() % 8) {
        case 0:  // flip a bit
            bytes[at(bytes.size())] ^= char(1 << (random() % 8));
            break;
        case 1:  // overwrite a byte with an edge value
            bytes[at(bytes.size())] = "\x00\xff\x7f\x80\x01"[random() % 5];
            break;
        case 2:  // truncate
            bytes.truncate(at(bytes.size()));
            break;
        case 3: {  // repeat a chunk
            const qsizetype from = at(bytes.size());
            const qsizetype length = std::min<qsizetype>(bytes.size() - from, 1 + random() % 256);
            bytes.insert(at(bytes.size()), bytes.mid(from, length));
            break;
        }
        case 4: {  // remove a chunk
            const qsizetype from = at(bytes.size());
            bytes.remove(from, std::min<qsizetype>(bytes.size() - from, 1 + random() % 64));
            break;
        }
        case 5: {  // a 32-bit edge value (counts, offsets, lengths in binary formats)
            const qsizetype from = at(bytes.size());
            const quint32 values[] = {0u, 0xffffffffu, 0x7fffffffu, 0x80000000u, 0x10000u};
            const quint32 value = values[random() % 5];
            for (int k = 0; k < 4 && from + k < bytes.size(); ++k)
                bytes[from + k] = char((value >> (8 * k)) & 0xff);
            break;
        }
        default: {  // an extreme number where a digit was (text formats)
            qsizetype from = at(bytes.size());
            while (from < bytes.size() && !(bytes[from] >= '0' && bytes[from] <= '9'))
                ++from;
            if (from < bytes.size())
                bytes.replace(from, 1, extremes[random() % std::size(extremes)]);
            break;
        }
    }
}

class ImportFuzz : public testing::TestWithParam<const char*> {};

TEST_P(ImportFuzz, EveryMutatedFileGivesValidPartsOrAMessage) {
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    const std::string extension = GetParam();
    const QString seedPath = folder.filePath(QString::fromStdString("seed." + extension));
    Document source;
    addPart(source, sharedStroke("y_branch"));
    if (extension == "ply" || extension == "off")
        writeMesh(source.parts().front().part->mesh, seedPath.toStdString());
    else
        exportDocument(source, seedPath.toStdString());
    QFile seedFile(seedPath);
    ASSERT_TRUE(seedFile.open(QIODevice::ReadOnly));
    const QByteArray seed = seedFile.readAll();
    ASSERT_FALSE(seed.isEmpty());

    ImportLimits limits;
    limits.seconds = 10.0;
    limits.addressSpaceBytes = std::uint64_t{2} << 30;
    std::mt19937 random(fuzzSeed());
    const auto end =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(fuzzSeconds());
    const QString input = folder.filePath(QString::fromStdString("input." + extension));
    int runs = 0, refused = 0;
    std::map<std::string, int> reasons;  // printed with RIGMESH_FUZZ_VERBOSE
    while (std::chrono::steady_clock::now() < end) {
        QByteArray bytes = seed;
        for (unsigned edits = 1 + random() % 4; edits > 0; --edits)
            mutate(bytes, random);
        QFile out(input);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write(bytes);
        out.close();
        ++runs;
        const auto start = std::chrono::steady_clock::now();
        std::string failure;
        try {
            for (const PartNode& node : readImportedParts(input, limits))
                if (!node.part->validate().empty())
                    failure = "an invalid part came back";
        } catch (const Error& error) {
            ++refused;
            const std::string what = error.what();
            // RIGMESH_FUZZ_KEEP=DIR keeps the inputs whose crash or hang was contained.
            if (const char* keep = std::getenv("RIGMESH_FUZZ_KEEP");
                keep && (what.find("crashed") != std::string::npos ||
                         what.find("longer than") != std::string::npos ||
                         what.find("memory") != std::string::npos))
                QFile::copy(input, QDir(QString::fromLocal8Bit(keep))
                                       .filePath(QStringLiteral("contained-%1.%2")
                                                     .arg(runs)
                                                     .arg(QString::fromStdString(extension))));
            ++reasons[what.find("crashed") != std::string::npos       ? "crash contained"
                      : what.find("longer than") != std::string::npos ? "hang contained"
                      : what.find("memory") != std::string::npos      ? "memory limit"
                                                                      : "refused by a reader"];
            if (std::string(error.what()).empty())
                failure = "an Error without a message";
        } catch (const std::exception& error) {
            failure = std::string("an exception other than rigmesh::Error: ") + error.what();
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (seconds > limits.seconds + 5.0)
            failure = "took " + std::to_string(seconds) + " s";
        if (!failure.empty()) {
            const QString kept = QDir::current().filePath(
                QString::fromStdString("import-fuzz-failure." + extension));
            QFile::remove(kept);
            QFile::copy(input, kept);
            FAIL() << failure << " (input saved as " << kept.toStdString() << ")";
        }
    }
    std::printf("import fuzz .%s: %d inputs, %d refused with a message\n", extension.c_str(), runs,
                refused);
    if (std::getenv("RIGMESH_FUZZ_VERBOSE"))
        for (const auto& [reason, count] : reasons)
            std::printf("  %s: %d\n", reason.c_str(), count);
    EXPECT_GT(runs, 0);
}

INSTANTIATE_TEST_SUITE_P(Formats, ImportFuzz,
                         testing::Values("glb", "gltf", "fbx", "dae", "obj", "ply", "off"),
                         [](const testing::TestParamInfo<const char*>& param) {
                             return std::string(param.param);
                         });

}  // namespace
}  // namespace rigmesh::model
