// Each face's mirror image (mesh/MeshMirror.h) on a sketch surface, whose
// faces list the images in order, and on the same surface with its faces
// shuffled, where the images are searched for: the same faces as a search
// of every face finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>

#include "SketchToSurfaceTestSupport.h"
#include "mesh/MeshMirror.h"
#include "pipeline/SketchToSurface.h"

namespace rigmesh {
namespace {

// Per face, the first face (by index) on its corners' images, from a table
// of every face by its sorted corners.
std::vector<int> imagesByEveryFace(const TriMesh& mesh, const std::vector<int>& mirror) {
    const auto sorted = [](std::array<int, 3> corners) {
        std::sort(corners.begin(), corners.end());
        return corners;
    };
    std::map<std::array<int, 3>, int> faceOn;
    for (int j = 0; j < mesh.faceCount(); ++j)
        faceOn.emplace(sorted(mesh.faces[j]), j);  // keeps the first
    std::vector<int> image;
    for (const auto& [a, b, c] : mesh.faces) {
        const auto found = faceOn.find(sorted({mirror[a], mirror[b], mirror[c]}));
        image.push_back(found == faceOn.end() ? -1 : found->second);
    }
    return image;
}

TEST(MeshMirror, EveryFacesImageIsTheFaceOnItsCornersImagesInOrderOrShuffled) {
    const SketchSurface surface = sketchToSurface(testsupport::polarOutline(40, [](double t) {
                                      return 2.0 + 0.5 * std::cos(3 * t);
                                  })).surface;
    const auto images = mirrorFaceImages(surface.mesh, surface.mirror);
    ASSERT_TRUE(images.has_value());
    EXPECT_EQ(*images, imagesByEveryFace(surface.mesh, surface.mirror));
    for (std::size_t i = 0; i < images->size(); ++i)
        EXPECT_EQ((*images)[(*images)[i]], static_cast<int>(i));

    TriMesh shuffled = surface.mesh;
    std::mt19937 random(11);
    std::shuffle(shuffled.faces.begin(), shuffled.faces.end(), random);
    const auto shuffledImages = mirrorFaceImages(shuffled, surface.mirror);
    ASSERT_TRUE(shuffledImages.has_value());
    EXPECT_EQ(*shuffledImages, imagesByEveryFace(shuffled, surface.mirror));
}

TEST(MeshMirror, AMeshWithoutAFacesImageOrAFaceTwiceOrAVertexOffItsImageHasNone) {
    const SketchSurface surface =
        sketchToSurface(testsupport::polarOutline(32, [](double) { return 1.0; })).surface;
    ASSERT_TRUE(mirrorFaceImages(surface.mesh, surface.mirror).has_value());
    TriMesh missing = surface.mesh;
    missing.faces.pop_back();
    EXPECT_FALSE(mirrorFaceImages(missing, surface.mirror).has_value());
    TriMesh moved = surface.mesh;
    int above = 0;
    while (surface.mirror[above] == above)
        ++above;
    moved.vertices[above].x() += 1e-12;
    EXPECT_FALSE(mirrorFaceImages(moved, surface.mirror).has_value());
    TriMesh twice = surface.mesh;  // a face listed twice is no face's image
    twice.faces.push_back(twice.faces.front());
    EXPECT_FALSE(mirrorFaceImages(twice, surface.mirror).has_value());
    TriMesh outOfRange = surface.mesh;
    outOfRange.faces.front()[0] = outOfRange.vertexCount();
    EXPECT_FALSE(mirrorFaceImages(outOfRange, surface.mirror).has_value());
}

}  // namespace
}  // namespace rigmesh
