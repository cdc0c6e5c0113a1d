#include "viewport/SceneRenderer.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <QFile>
#include <algorithm>
#include <array>

#include "merge/MergeParts.h"
#include "part/BoneWeights.h"

// The shaders are compiled into this static library: register them
// explicitly (Q_INIT_RESOURCE must be called outside any namespace).
static void registerShaderResources() {
    Q_INIT_RESOURCE(shaders);
}

namespace rigmesh::widgets {
namespace {

constexpr int kMaxBones = 128;  // matches the arrays in mesh.vert

QString shaderSource(const QString& name) {
    QFile file(QStringLiteral(":/shaders/") + name);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll());
}

// Area-weighted vertex normals of the rest mesh.
std::vector<Vec3> vertexNormals(const TriMesh& mesh) {
    std::vector<Vec3> normals(mesh.vertices.size(), Vec3::Zero());
    for (const auto& f : mesh.faces) {
        Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                     .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]);
        for (int v : f)
            normals[v] += n;
    }
    for (auto& n : normals)
        n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3(0, 0, 1);
    return normals;
}

}  // namespace

struct SceneRenderer::GpuMesh {
    std::shared_ptr<const Part> part;  // keeps the key's address valid
    QOpenGLVertexArrayObject vao;
    QOpenGLBuffer vertices{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
    // Per vertex: the L1 distance between its weights and a fresh global
    // computation (the GlobalDifference view), uploaded once it is ready.
    QOpenGLBuffer difference{QOpenGLBuffer::VertexBuffer};
    std::shared_ptr<const std::vector<float>> differenceUploaded;
    int indexCount = 0;
    bool usedThisFrame = false;
};

SceneRenderer::SceneRenderer() = default;
SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::initialize(QString* error) {
    registerShaderResources();
    initializeOpenGLFunctions();
    auto build = [&](QOpenGLShaderProgram& program, const char* vertex, const char* fragment) {
        return program.addShaderFromSourceCode(QOpenGLShader::Vertex, shaderSource(vertex)) &&
               program.addShaderFromSourceCode(QOpenGLShader::Fragment, shaderSource(fragment)) &&
               program.link();
    };
    if (!build(meshProgram_, "mesh.vert", "mesh.frag")) {
        if (error)
            *error = meshProgram_.log();
        return false;
    }
    if (!build(lineProgram_, "lines.vert", "lines.frag")) {
        if (error)
            *error = lineProgram_.log();
        return false;
    }
    lineVao_.create();
    linePositions_.create();
    lineColours_.create();
    initialized_ = true;
    return true;
}

SceneRenderer::GpuMesh& SceneRenderer::meshFor(const std::shared_ptr<const Part>& part) {
    auto& slot = meshes_[part.get()];
    if (slot)
        return *slot;
    slot = std::make_unique<GpuMesh>();
    GpuMesh& gpu = *slot;
    gpu.part = part;
    const TriMesh& mesh = part->mesh;
    const auto normals = vertexNormals(mesh);
    // Interleaved: position (3), normal (3), 4 bone indices, 4 weights, the
    // number of influences. The four largest influences are kept (largest
    // first) and renormalised for the GPU; the count is of all of them, so
    // the Influences view can flag vertices over four.
    // The shader's bone matrices are by position in skeleton.bones(); the
    // part's weights name bones by id.
    const BoneIndexTable positionOf(part->skeleton);
    std::vector<float> data;
    data.reserve(mesh.vertices.size() * 15);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        std::array<std::pair<int, double>, 4> top{};
        std::size_t influenceCount = 0;
        if (v < part->weights.perVertex.size()) {
            influenceCount = part->weights.perVertex[v].size();
            auto influences = part->weights.perVertex[v];
            std::sort(influences.begin(), influences.end(),
                      [](const auto& a, const auto& b) { return a.second > b.second; });
            for (std::size_t k = 0; k < 4 && k < influences.size(); ++k)
                top[k] = {std::max(positionOf[influences[k].first], 0), influences[k].second};
        }
        double sum = top[0].second + top[1].second + top[2].second + top[3].second;
        if (sum <= 0)
            top[0] = {0, sum = 1.0};
        for (int k = 0; k < 3; ++k)
            data.push_back(static_cast<float>(mesh.vertices[v][k]));
        for (int k = 0; k < 3; ++k)
            data.push_back(static_cast<float>(normals[v][k]));
        for (int k = 0; k < 4; ++k)
            data.push_back(static_cast<float>(std::min(top[k].first, kMaxBones - 1)));
        for (int k = 0; k < 4; ++k)
            data.push_back(static_cast<float>(top[k].second / sum));
        data.push_back(static_cast<float>(influenceCount));
    }
    std::vector<GLuint> indices;
    indices.reserve(mesh.faces.size() * 3);
    for (const auto& f : mesh.faces)
        for (int v : f)
            indices.push_back(static_cast<GLuint>(v));

    gpu.vao.create();
    gpu.vao.bind();
    gpu.vertices.create();
    gpu.vertices.bind();
    gpu.vertices.allocate(data.data(), static_cast<int>(data.size() * sizeof(float)));
    const int stride = 15 * sizeof(float);
    for (int attribute = 0; attribute < 5; ++attribute)
        glEnableVertexAttribArray(attribute);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(3 * sizeof(float)));
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(6 * sizeof(float)));
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(10 * sizeof(float)));
    glVertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(14 * sizeof(float)));
    gpu.indices.create();
    gpu.indices.bind();
    gpu.indices.allocate(indices.data(), static_cast<int>(indices.size() * sizeof(GLuint)));
    gpu.indexCount = static_cast<int>(indices.size());
    gpu.vao.release();
    return gpu;
}

void SceneRenderer::render(const RenderScene& scene, const OrbitCamera& camera,
                           const QSize& pixels) {
    glViewport(0, 0, pixels.width(), pixels.height());
    glClearColor(0.23f, 0.24f, 0.26f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!initialized_)
        return;
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_PROGRAM_POINT_SIZE);
    const QMatrix4x4 view = camera.viewMatrix();
    const QMatrix4x4 projection = camera.projectionMatrix(QSizeF(pixels));
    const QMatrix4x4 viewProjection = projection * view;

    if (scene.showGrid)
        drawGrid(scene, viewProjection);
    drawParts(scene.parts, scene, view, projection, QVector2D(pixels.width(), pixels.height()));
    if (!scene.ghosts.empty()) {
        // Ghosts blend over what is drawn, hiding nothing behind them. They
        // are pushed back in depth, so where a ghost lies on the part itself
        // (what did not move) the part wins instead of flickering with it.
        // The framebuffer's alpha stays 1: the widget is composited with it.
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glDepthMask(GL_FALSE);
        drawParts(scene.ghosts, scene, view, projection,
                  QVector2D(pixels.width(), pixels.height()));
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    if (!scene.inFront.empty()) {
        // In front of everything, see-through (Blender's In Front display):
        // a fresh depth buffer, so only these parts' own faces hide each
        // other, blended over what is drawn.
        glClear(GL_DEPTH_BUFFER_BIT);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        drawParts(scene.inFront, scene, view, projection,
                  QVector2D(pixels.width(), pixels.height()));
        glDisable(GL_BLEND);
    }
    // Overlays stay visible through the surface, like Blender's bone overlay.
    glDisable(GL_DEPTH_TEST);
    drawColoured(scene.lines, GL_LINES, viewProjection, 1.0f);
    drawColoured(scene.points, GL_POINTS, viewProjection, 9.0f);
    drawColoured(scene.stroke, GL_LINE_STRIP, viewProjection, 1.0f);
    glEnable(GL_DEPTH_TEST);

    // Free the buffers of parts no longer shown (undo replaced them).
    for (auto it = meshes_.begin(); it != meshes_.end();) {
        if (!it->second->usedThisFrame)
            it = meshes_.erase(it);
        else
            (it++)->second->usedThisFrame = false;
    }
}

void SceneRenderer::drawParts(const std::vector<RenderPart>& parts, const RenderScene& scene,
                              const QMatrix4x4& view, const QMatrix4x4& projection,
                              const QVector2D& pixels) {
    meshProgram_.bind();
    meshProgram_.setUniformValue("view", view);
    meshProgram_.setUniformValue("projection", projection);
    meshProgram_.setUniformValue("viewportPixels", pixels);
    meshProgram_.setUniformValue("outlinePixels", 0.0f);
    meshProgram_.setUniformValue("flatColour", 0);
    meshProgram_.setUniformValue("dualQuaternionSkinning", scene.dualQuaternionSkinning ? 1 : 0);
    meshProgram_.setUniformValue("weightView", static_cast<int>(scene.weightView));
    for (const RenderPart& item : parts) {
        GpuMesh& gpu = meshFor(item.part);
        meshProgram_.setUniformValue("opacity", item.opacity);
        gpu.usedThisFrame = true;
        if (scene.weightView == WeightView::GlobalDifference && item.globalDifference &&
            gpu.differenceUploaded != item.globalDifference) {
            const std::vector<float>& difference = *item.globalDifference;
            gpu.differenceUploaded = item.globalDifference;
            gpu.vao.bind();
            if (!gpu.difference.isCreated())
                gpu.difference.create();
            gpu.difference.bind();
            gpu.difference.allocate(difference.data(),
                                    static_cast<int>(difference.size() * sizeof(float)));
            glEnableVertexAttribArray(5);
            glVertexAttribPointer(5, 1, GL_FLOAT, GL_FALSE, sizeof(float), nullptr);
            gpu.vao.release();
        }
        const int bones = std::min<int>(static_cast<int>(item.boneReal.size()), kMaxBones);
        meshProgram_.setUniformValue("model", item.model);
        meshProgram_.setUniformValue("weightBone", item.weightBone);
        meshProgram_.setUniformValue("boneCount", bones);
        if (bones > 0) {
            meshProgram_.setUniformValueArray("boneReal", item.boneReal.data(), bones);
            meshProgram_.setUniformValueArray("boneDual", item.boneDual.data(), bones);
            meshProgram_.setUniformValueArray("boneRows", item.boneRows.data(), 3 * bones);
        }
        gpu.vao.bind();
        if (item.selected) {
            // The selection outline: back faces pushed out by a few pixels,
            // in Blender's selection orange, before the part itself.
            meshProgram_.setUniformValue("outlinePixels", 2.5f);
            meshProgram_.setUniformValue("flatColour", 1);
            meshProgram_.setUniformValue("baseColour", QVector3D(1.0f, 0.55f, 0.1f));
            glEnable(GL_CULL_FACE);
            glCullFace(GL_FRONT);
            glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
            glDisable(GL_CULL_FACE);
            meshProgram_.setUniformValue("outlinePixels", 0.0f);
            meshProgram_.setUniformValue("flatColour", 0);
        }
        meshProgram_.setUniformValue("baseColour", item.colour);
        meshProgram_.setUniformValue("highlight", item.selected ? 1.0f : 0.0f);
        glEnable(GL_POLYGON_OFFSET_FILL);
        const float offset = item.opacity < 1.0f ? 8.0f : 1.0f;  // ghosts further back
        glPolygonOffset(offset, offset);
        glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
        glDisable(GL_POLYGON_OFFSET_FILL);
        if (scene.wireframe) {
            meshProgram_.setUniformValue("baseColour", QVector3D(0.1f, 0.1f, 0.15f));
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        }
        gpu.vao.release();
    }
    meshProgram_.release();
}

void SceneRenderer::drawColoured(const ColouredVertices& vertices, GLenum mode,
                                 const QMatrix4x4& viewProjection, float pointSize) {
    if (vertices.positions.empty())
        return;
    lineProgram_.bind();
    lineProgram_.setUniformValue("viewProjection", viewProjection);
    lineProgram_.setUniformValue("pointSize", pointSize);
    lineProgram_.setUniformValue("roundPoints", mode == GL_POINTS ? 1 : 0);
    lineVao_.bind();
    linePositions_.bind();
    linePositions_.allocate(vertices.positions.data(),
                            static_cast<int>(vertices.positions.size() * sizeof(QVector3D)));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    lineColours_.bind();
    lineColours_.allocate(vertices.colours.data(),
                          static_cast<int>(vertices.colours.size() * sizeof(QVector3D)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glDrawArrays(mode, 0, static_cast<GLsizei>(vertices.positions.size()));
    lineVao_.release();
    lineProgram_.release();
}

void SceneRenderer::drawGrid(const RenderScene& scene, const QMatrix4x4& viewProjection) {
    ColouredVertices grid;
    // The plane's two axes (u, v) and the lines' colours: through the world
    // origin tinted like Blender's axes (x red, y green, z blue).
    const int n = std::clamp(scene.gridNormal, 0, 2);
    const int u = n == 0 ? 2 : 0;
    const int v = n == 1 ? 2 : 1;
    const QVector3D axisColours[] = {
        {0.55f, 0.25f, 0.25f}, {0.3f, 0.5f, 0.28f}, {0.25f, 0.35f, 0.6f}};
    const QVector3D plain(0.33f, 0.34f, 0.36f);
    const float spacing = scene.gridSpacing;
    const float extent = spacing * static_cast<float>(scene.gridLines);
    // On whole multiples of the spacing, around the centre.
    const float cu = spacing * std::round(scene.gridCentre[u] / spacing);
    const float cv = spacing * std::round(scene.gridCentre[v] / spacing);
    auto point = [&](float a, float b) {
        QVector3D p = scene.gridCentre;
        p[u] = a;
        p[v] = b;
        return p;
    };
    for (int i = -scene.gridLines; i <= scene.gridLines; ++i) {
        const float a = cu + spacing * static_cast<float>(i);
        const float b = cv + spacing * static_cast<float>(i);
        const bool originV = std::abs(b) < 0.5f * spacing;  // the u axis
        const bool originU = std::abs(a) < 0.5f * spacing;  // the v axis
        grid.add(point(cu - extent, b), originV ? axisColours[u] : plain);
        grid.add(point(cu + extent, b), originV ? axisColours[u] : plain);
        grid.add(point(a, cv - extent), originU ? axisColours[v] : plain);
        grid.add(point(a, cv + extent), originU ? axisColours[v] : plain);
    }
    drawColoured(grid, GL_LINES, viewProjection, 1.0f);
}

void SceneRenderer::release() {
    meshes_.clear();
    lineVao_.destroy();
    linePositions_.destroy();
    lineColours_.destroy();
    initialized_ = false;
}

}  // namespace rigmesh::widgets
