#include "model/ImportReader.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "base/ChildProcess.h"
#include "base/Error.h"
#include "model/DocumentFile.h"
#include "model/PartClips.h"

namespace rigmesh::model {
namespace {

QString& programOverride() {
    static QString program;
    return program;
}

std::string fileLabel(const QString& path) {
    return QFileInfo(path).fileName().toStdString();
}

std::string gibibytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1u << 30));
    return text;
}

// Sanitizer builds run several times slower; their limits are as much longer.
double sanitizerSlowdown() {
    return addressSpaceLimitsSupported() ? 1.0 : 8.0;
}

// The child's own words when it failed cleanly (`rigmesh: <message>`), or
// what its end says about the file.
Error failure(const QString& path, const ChildOutcome& outcome, const ImportLimits& limits) {
    const std::string file = fileLabel(path);
    switch (outcome.end) {
        case ChildOutcome::End::FailedToStart:
            return Error(MessageId::ImportReaderNotStarted, file, outcome.standardError);
        case ChildOutcome::End::TimedOut:
            return Error(MessageId::ImportTimedOut, file,
                         static_cast<long long>(std::ceil(limits.seconds)));
        case ChildOutcome::End::Signalled:
            return Error(MessageId::ImportReaderCrashed, file, strsignal(outcome.signal));
        case ChildOutcome::End::Exited:
            break;
    }
    const std::string message = lastLineStartingWith(outcome.standardError, "rigmesh: ");
    if (message.find("std::bad_alloc") != std::string::npos ||
        message.find("out of memory") != std::string::npos)
        return Error(MessageId::ImportOutOfMemory, file, gibibytes(limits.addressSpaceBytes));
    if (message.empty())
        return Error(MessageId::ImportReaderFailed, file, outcome.exitCode);
    return Error(message);
}

}  // namespace

ImportLimits importLimitsFor(std::uint64_t fileBytes) {
    constexpr std::uint64_t kMiB = 1u << 20;
    constexpr std::uint64_t kGiB = 1u << 30;
    ImportLimits limits;
    // Measured with `rigmesh import` on a machine busy with other builds
    // (load 17 on 2 cores): pond.0.ply (2.1 MiB) 0.9 s, 2CylinderEngine.glb
    // (1.8 MiB) 0.8 s, a 700 x 700 grid OBJ (27.6 MiB) 19.4 s; the limits
    // (15 s, 14 s, 143 s) leave seven times that or more.
    const double mebibytes = static_cast<double>(fileBytes) / static_cast<double>(kMiB);
    limits.seconds = std::min(600.0, sanitizerSlowdown() * (5.0 + 5.0 * mebibytes));
    const std::uint64_t scaled = fileBytes > 6 * kGiB / 64 ? 6 * kGiB : 64 * fileBytes;
    limits.addressSpaceBytes = std::min<std::uint64_t>(8 * kGiB, 2 * kGiB + scaled);
    return limits;
}

std::vector<PartNode> partNodesFromScene(ImportedScene scene, const QString& path) {
    std::vector<PartNode> nodes;
    for (std::size_t i = 0; i < scene.parts.size(); ++i) {
        PartNode node;
        node.part = std::make_shared<const Part>(std::move(scene.parts[i].part));
        node.name = QString::fromStdString(node.part->name);
        // Assimp names some roots itself ("<OFFRoot>", "<PLYRoot>"): not a user's name.
        if (node.name.isEmpty() || (node.name.startsWith(u'<') && node.name.endsWith(u'>')))
            node.name = QFileInfo(path).completeBaseName();
        node.pose = restPoseOf(node);
        // Every animation a named clip: the file's first one active.
        std::set<std::string> names;
        std::vector<Clip> others;
        for (Clip& clip : scene.parts[i].clips) {
            // An unnamed clip stays unnamed ("Action") unless that is taken.
            const std::string name = usableClipName(clip.name, names);
            clip.name = clip.name.empty() && name == kDefaultClipName ? std::string() : name;
            names.insert(name);
            if (names.size() == 1)
                node.clip = std::move(clip);
            else
                others.push_back(std::move(clip));
        }
        node.otherClips = sortedByName(std::move(others));
        nodes.push_back(std::move(node));
    }
    return nodes;
}

QString importWorkerProgram() {
    if (!programOverride().isEmpty())
        return programOverride();
    const QByteArray fromEnvironment = qgetenv("RIGMESH_IMPORT_WORKER");
    if (!fromEnvironment.isEmpty())
        return QString::fromLocal8Bit(fromEnvironment);
    // Beside the running executable (the build tree, or /usr/bin when installed).
    const QFileInfo self(QStringLiteral("/proc/self/exe"));
    const QFileInfo sibling(QDir(QFileInfo(self.canonicalFilePath()).absolutePath()),
                            QStringLiteral("rigmesh"));
    if (sibling.isFile() && sibling.isExecutable())
        return sibling.absoluteFilePath();
    return QStandardPaths::findExecutable(QStringLiteral("rigmesh"));
}

void setImportWorkerProgram(const QString& program) {
    programOverride() = program;
}

std::vector<PartNode> readImportedParts(const QString& path) {
    const QFileInfo info(path);
    if (!info.exists())
        throw Error(MessageId::ImportNoSuchFile, path.toStdString());
    if (!info.isFile())
        throw Error(MessageId::ImportNotAFile, path.toStdString());
    return readImportedParts(path, importLimitsFor(static_cast<std::uint64_t>(info.size())));
}

std::vector<PartNode> readImportedParts(const QString& path, const ImportLimits& limits) {
    const QString program = importWorkerProgram();
    if (program.isEmpty())
        throw Error(MessageId::ImportReaderMissing, fileLabel(path));

    ChildLimits childLimits;
    childLimits.seconds = limits.seconds;
    childLimits.addressSpaceBytes = static_cast<std::size_t>(limits.addressSpaceBytes);
    // The parts come back through the child's descriptor 3, a temporary file
    // without a name: nothing to clean up, whichever of the two ends first.
    // They cannot outgrow the child's memory.
    childLimits.maxResultBytes = limits.addressSpaceBytes > 0
                                     ? static_cast<std::size_t>(limits.addressSpaceBytes)
                                     : std::size_t{8} << 30;
    const ChildOutcome outcome = runChildProcess(
        program.toStdString(),
        // Local 8-bit file names, so a name that is not UTF-8 still reaches the child.
        {"import", QFile::encodeName(QFileInfo(path).absoluteFilePath()).toStdString(), "-o",
         "/dev/fd/3"},
        childLimits);
    if (outcome.end != ChildOutcome::End::Exited || outcome.exitCode != 0)
        throw failure(path, outcome, limits);
    if (outcome.resultTooLarge)
        throw Error(MessageId::ImportOutOfMemory, fileLabel(path),
                    gibibytes(limits.addressSpaceBytes));

    DocumentContents contents;
    try {
        contents = DocumentFile::fromBytes(
            QByteArray(outcome.result.data(), static_cast<qsizetype>(outcome.result.size())));
    } catch (const Error& error) {
        throw Error(MessageId::ImportBadData, fileLabel(path), error.what());
    }
    // Whatever came back is checked again: numbers finite, indices in range,
    // weights a partition of unity.
    for (PartNode& node : contents.parts) {
        const std::vector<Message> problems = node.part->validate();
        if (!problems.empty())
            throw Error(MessageId::ImportPartUnusable, fileLabel(path), node.name.toStdString(),
                        problems.front());
        node.id = kNoPart;
    }
    return std::move(contents.parts);
}

}  // namespace rigmesh::model
