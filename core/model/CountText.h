// A count in words, "1 bone" or "3 bones": the singular for exactly one.
// Qt's %n plural forms need a translation file even for English, which the
// studio does not have, so each count is two source strings (both
// translated; German and Spanish also say one and many).
#pragma once

#include <QString>

namespace rigmesh::model {

inline QString countText(long long n, const QString& one, const QString& many) {
    return n == 1 ? one : many.arg(n);
}

}  // namespace rigmesh::model
