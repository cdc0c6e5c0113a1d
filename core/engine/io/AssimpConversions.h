// Eigen <-> Assimp value conversions shared by export and import. Internal to
// io/ and included only from .cpp files (it includes Assimp).
#pragma once

#include <assimp/matrix4x4.h>
#include <assimp/quaternion.h>
#include <assimp/vector3.h>

#include <Eigen/Geometry>

#include "base/Types.h"

namespace rigmesh {

inline aiVector3D toAi(const Vec3& v) {
    return {static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z())};
}
inline aiQuaternion toAi(const Eigen::Quaterniond& q) {
    return {static_cast<ai_real>(q.w()), static_cast<ai_real>(q.x()), static_cast<ai_real>(q.y()),
            static_cast<ai_real>(q.z())};
}
inline Vec3 fromAi(const aiVector3D& v) {
    return {v.x, v.y, v.z};
}
inline Eigen::Quaterniond fromAi(const aiQuaternion& q) {
    return {q.w, q.x, q.y, q.z};
}

inline aiMatrix4x4 translationMatrix(const Vec3& t) {
    aiMatrix4x4 m;
    aiMatrix4x4::Translation(toAi(t), m);
    return m;
}

inline aiMatrix4x4 toAi(const Eigen::Affine3d& a) {
    aiMatrix4x4 m;
    for (unsigned r = 0; r < 4; ++r)
        for (unsigned c = 0; c < 4; ++c)
            m[r][c] = static_cast<ai_real>(a.matrix()(r, c));
    return m;
}

// A rigid transform: rotate, then translate.
inline aiMatrix4x4 rigidMatrix(const Vec3& translation, const Eigen::Quaterniond& rotation) {
    Eigen::Affine3d a = Eigen::Affine3d::Identity();
    a.translate(translation);
    a.rotate(rotation);
    return toAi(a);
}

inline Eigen::Affine3d fromAi(const aiMatrix4x4& m) {
    Eigen::Matrix4d out;
    for (unsigned r = 0; r < 4; ++r)
        for (unsigned c = 0; c < 4; ++c)
            out(r, c) = m[r][c];
    return Eigen::Affine3d(out);
}

}  // namespace rigmesh
