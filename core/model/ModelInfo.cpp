#include "model/ModelInfo.h"

#include <QtGlobal>

namespace rigmesh::model {

QString buildInfo() {
    return QStringLiteral("RigMesh Studio %1 (Qt %2)")
        .arg(QStringLiteral(RIGMESH_VERSION), QString::fromLatin1(qVersion()));
}

}  // namespace rigmesh::model
