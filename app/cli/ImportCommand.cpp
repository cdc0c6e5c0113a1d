#include "ImportCommand.h"

#include <sys/resource.h>
#include <unistd.h>

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QString>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <new>

#include "CommandLine.h"
#include "base/ChildProcess.h"
#include "base/Error.h"
#include "io/SceneImport.h"
#include "model/DocumentFile.h"
#include "model/ImportReader.h"

namespace rigmesh::cli {
namespace {

// What the processor-time signal prints: filled before the limit is set,
// written by the handler with write(2), the one call it may make.
char timedOutLine[512];
std::size_t timedOutLength = 0;

void onProcessorLimit(int) {
    [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, timedOutLine, timedOutLength);
    _exit(1);
}

// Run by hand (`rigmesh import FILE -o PARTS.rigmesh`), this command holds
// itself to the limits model/ImportReader gives the child it starts, so a
// broken file ends in seconds with the same message instead of running for
// minutes (a mutated .dae took 3 min 23 s). As that child (`-o /dev/fd/3`)
// it keeps the limits its parent set: raising them is not its call.
void limitOwnImport(const QString& path) {
    const model::ImportLimits limits =
        model::importLimitsFor(static_cast<std::uint64_t>(QFileInfo(path).size()));
    const std::string file = QFileInfo(path).fileName().toStdString();
    const std::string line = "rigmesh: " +
                             std::string(Error(MessageId::ImportTimedOut, file,
                                               static_cast<long long>(std::ceil(limits.seconds)))
                                             .what()) +
                             "\n";
    timedOutLength = std::min(line.size(), sizeof timedOutLine);
    std::copy_n(line.data(), timedOutLength, timedOutLine);
    std::signal(SIGXCPU, onProcessorLimit);
    const auto seconds = static_cast<rlim_t>(std::ceil(limits.seconds));
    const rlimit processor{seconds, seconds + 1};
    setrlimit(RLIMIT_CPU, &processor);
    if (addressSpaceLimitsSupported() && limits.addressSpaceBytes > 0) {
        const rlimit space{limits.addressSpaceBytes, limits.addressSpaceBytes};
        setrlimit(RLIMIT_AS, &space);
    }
}

// The message model/ImportReader gives when its child runs out of memory.
Error outOfMemory(const QString& path) {
    const std::uint64_t bytes =
        model::importLimitsFor(static_cast<std::uint64_t>(QFileInfo(path).size()))
            .addressSpaceBytes;
    char gibibytes[32];
    std::snprintf(gibibytes, sizeof gibibytes, "%.1f GiB", static_cast<double>(bytes) / (1u << 30));
    return Error(MessageId::ImportOutOfMemory, QFileInfo(path).fileName().toStdString(),
                 std::string(gibibytes));
}

}  // namespace

int runImport(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o"}, {});
    if (line.positional().size() != 1)
        throw Error("import needs exactly one file to read");
    const std::optional<std::string> out = line.value("-o");
    if (!out)
        throw Error("import needs -o PARTS.rigmesh (the document to write)");
    const QString path = QString::fromStdString(line.positional()[0]);
    const bool asWorker = out->starts_with("/dev/fd/");
    if (!asWorker)
        limitOwnImport(path);

    ImportedScene scene;
    try {
        scene = importScene(path.toStdString());
    } catch (const std::bad_alloc&) {
        if (asWorker)
            throw;  // the parent names the limit it set
        throw outOfMemory(path);
    } catch (const Error& error) {
        // Assimp reports its own allocation failure as text.
        if (asWorker || std::string(error.what()).find("bad_alloc") == std::string::npos)
            throw;
        throw outOfMemory(path);
    }
    const std::string message = scene.message;
    model::DocumentContents contents;
    contents.parts = model::partNodesFromScene(std::move(scene), path);
    for (model::PartNode& node : contents.parts) {
        const std::vector<Message> problems = node.part->validate();
        if (!problems.empty())
            throw Error(MessageId::ImportPartUnusable, path.toStdString(), node.name.toStdString(),
                        problems.front());
        node.id = contents.nextPartId++;
    }

    const QByteArray bytes = model::DocumentFile::toBytes(contents);
    const QString target = QString::fromStdString(*out);
    if (asWorker) {
        // A descriptor the caller handed over (model/ImportReader: an unnamed
        // temporary file), written in place: there is no folder to stage in.
        QFile file(target);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
            file.write(bytes) != bytes.size() || !file.flush())
            throw Error(MessageId::CannotWriteFile, *out, file.errorString().toStdString());
    } else {
        QSaveFile file(target);
        if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
            throw Error(MessageId::CannotWriteFile, *out, file.errorString().toStdString());
    }

    int unrigged = 0;
    for (const model::PartNode& node : contents.parts)
        unrigged += node.part->skeleton.jointCount() == 0 ? 1 : 0;
    std::printf("%zu part%s (%d unrigged)\n", contents.parts.size(),
                contents.parts.size() == 1 ? "" : "s", unrigged);
    if (!message.empty())
        std::printf("%s\n", message.c_str());
    std::printf("wrote %s\n", out->c_str());
    return 0;
}

}  // namespace rigmesh::cli
