#include "ImportCommand.h"

#include <QFile>
#include <QSaveFile>
#include <QString>
#include <cstdio>

#include "CommandLine.h"
#include "base/Error.h"
#include "io/SceneImport.h"
#include "model/DocumentFile.h"
#include "model/ImportReader.h"

namespace rigmesh::cli {

int runImport(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o"}, {});
    if (line.positional().size() != 1)
        throw Error("import needs exactly one file to read");
    const std::optional<std::string> out = line.value("-o");
    if (!out)
        throw Error("import needs -o PARTS.rigmesh (the document to write)");
    const QString path = QString::fromStdString(line.positional()[0]);

    ImportedScene scene = importScene(path.toStdString());
    const std::string message = scene.message;
    model::DocumentContents contents;
    contents.parts = model::partNodesFromScene(std::move(scene), path);
    for (model::PartNode& node : contents.parts) {
        const std::vector<std::string> problems = node.part->validate();
        if (!problems.empty())
            throw Error(MessageId::ImportPartUnusable, path.toStdString(), node.name.toStdString(),
                        problems.front());
        node.id = contents.nextPartId++;
    }

    const QByteArray bytes = model::DocumentFile::toBytes(contents);
    const QString target = QString::fromStdString(*out);
    if (target.startsWith(QStringLiteral("/dev/fd/"))) {
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
