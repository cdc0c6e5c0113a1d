#include "model/ImportReader.h"

#include <QCoreApplication>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <algorithm>
#include <csignal>
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

// The child's own words when it failed cleanly (`rigmesh: <message>`), or
// what its end says about the file.
std::string failureMessage(const QString& path, const ChildOutcome& outcome,
                           const ImportLimits& limits) {
    const std::string file = fileLabel(path);
    switch (outcome.end) {
        case ChildOutcome::End::FailedToStart:
            return "cannot import " + file + ": " + outcome.standardError;
        case ChildOutcome::End::TimedOut:
            return "cannot import " + file + ": reading it took longer than " +
                   std::to_string(static_cast<long long>(limits.seconds)) +
                   " s, so it was stopped (the file is probably broken)";
        case ChildOutcome::End::Signalled:
            return "cannot import " + file + ": the importer crashed on it (" +
                   strsignal(outcome.signal) + "); the file is probably broken";
        case ChildOutcome::End::Exited:
            break;
    }
    std::string message = lastLineStartingWith(outcome.standardError, "rigmesh: ");
    if (message.find("std::bad_alloc") != std::string::npos ||
        message.find("out of memory") != std::string::npos)
        return "cannot import " + file + ": reading it needed more than " +
               gibibytes(limits.addressSpaceBytes) + " of memory, so it was stopped";
    if (message.empty())
        message = "the importer failed on " + file + " (exit status " +
                  std::to_string(outcome.exitCode) + ")";
    return message;
}

}  // namespace

ImportLimits importLimitsFor(std::uint64_t fileBytes) {
    constexpr std::uint64_t kMiB = 1u << 20;
    constexpr std::uint64_t kGiB = 1u << 30;
    ImportLimits limits;
    limits.seconds = std::min(600.0, 60.0 + static_cast<double>(fileBytes / kMiB));
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
        throw Error(QCoreApplication::translate("rigmesh::model::ImportReader",
                                                "cannot import %1: no such file")
                        .arg(path)
                        .toStdString());
    if (!info.isFile())
        throw Error(QCoreApplication::translate("rigmesh::model::ImportReader",
                                                "cannot import %1: not a file")
                        .arg(path)
                        .toStdString());
    return readImportedParts(path, importLimitsFor(static_cast<std::uint64_t>(info.size())));
}

std::vector<PartNode> readImportedParts(const QString& path, const ImportLimits& limits) {
    const QString program = importWorkerProgram();
    if (program.isEmpty())
        throw Error(QCoreApplication::translate(
                        "rigmesh::model::ImportReader",
                        "cannot import %1: the program that reads imports (rigmesh) is not "
                        "installed")
                        .arg(QString::fromStdString(fileLabel(path)))
                        .toStdString());
    QTemporaryDir folder;  // removed with everything in it on every path out
    if (!folder.isValid())
        throw Error("cannot import " + fileLabel(path) + ": no temporary folder (" +
                    folder.errorString().toStdString() + ")");
    const QString parts = folder.filePath(QStringLiteral("parts.rigmesh"));

    ChildLimits childLimits;
    childLimits.seconds = limits.seconds;
    childLimits.addressSpaceBytes = static_cast<std::size_t>(limits.addressSpaceBytes);
    const ChildOutcome outcome = runChildProcess(
        program.toStdString(),
        // Local 8-bit file names, so a name that is not UTF-8 still reaches the child.
        {"import", QFile::encodeName(QFileInfo(path).absoluteFilePath()).toStdString(), "-o",
         QFile::encodeName(parts).toStdString()},
        childLimits);
    if (outcome.end != ChildOutcome::End::Exited || outcome.exitCode != 0)
        throw Error(failureMessage(path, outcome, limits));

    DocumentContents contents;
    try {
        contents = DocumentFile::read(parts);
    } catch (const Error& error) {
        throw Error("cannot import " + fileLabel(path) + ": the importer returned bad data (" +
                    error.what() + ")");
    }
    // Whatever came back is checked again: numbers finite, indices in range,
    // weights a partition of unity.
    for (PartNode& node : contents.parts) {
        const std::vector<std::string> problems = node.part->validate();
        if (!problems.empty())
            throw Error("cannot import " + fileLabel(path) + ": part \"" + node.name.toStdString() +
                        "\" is not usable: " + problems.front());
        node.id = kNoPart;
    }
    return std::move(contents.parts);
}

}  // namespace rigmesh::model
