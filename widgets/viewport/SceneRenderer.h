// OpenGL 3.3 core drawing of a RenderScene: shaded, GPU-skinned part meshes
// with a headlight, an optional wireframe, the ground grid, the skeleton
// overlay and the stroke being sketched. Owns the GL buffers of each part,
// uploaded once per part value (parts are immutable).
#pragma once

#include <QOpenGLBuffer>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QVector2D>
#include <map>
#include <memory>

#include "viewport/OrbitCamera.h"
#include "viewport/RenderScene.h"

namespace rigmesh::widgets {

class SceneRenderer : protected QOpenGLFunctions_3_3_Core {
  public:
    SceneRenderer();
    ~SceneRenderer();
    // Needs a current GL 3.3 core context; returns false with a reason when
    // the shaders do not compile.
    bool initialize(QString* error);
    void render(const RenderScene& scene, const OrbitCamera& camera, const QSize& pixels);
    void release();  // with the context current, before it goes away

  private:
    struct GpuMesh;
    GpuMesh& meshFor(const std::shared_ptr<const Part>& part);
    void drawParts(const std::vector<RenderPart>& parts, const RenderScene& scene,
                   const QMatrix4x4& view, const QMatrix4x4& projection, const QVector2D& pixels);
    void drawColoured(const ColouredVertices& vertices, GLenum mode,
                      const QMatrix4x4& viewProjection, float pointSize);
    void drawGrid(const RenderScene& scene, const QMatrix4x4& viewProjection);

    QOpenGLShaderProgram meshProgram_;
    QOpenGLShaderProgram lineProgram_;
    std::map<const Part*, std::unique_ptr<GpuMesh>> meshes_;
    QOpenGLVertexArrayObject lineVao_;
    QOpenGLBuffer linePositions_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer lineColours_{QOpenGLBuffer::VertexBuffer};
    bool initialized_ = false;
};

}  // namespace rigmesh::widgets
