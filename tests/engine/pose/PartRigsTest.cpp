// The rigged parts the posing tests use have the structure they rely on.
#include "PoseTestSupport.h"

namespace rigmesh::posetest {
namespace {

TEST(PoseTestParts, SharedPartsAreValidTreesWithWeightsPerVertex) {
    for (const std::string name : {"tube", "y_branch", "biped"}) {
        const Part& part = sharedPart(name);
        EXPECT_TRUE(part.skeleton.validate().empty()) << name;
        EXPECT_EQ(part.weights.perVertex.size(), part.mesh.vertices.size()) << name;
        std::cout << name << ": " << part.skeleton.boneCount() << " bones, "
                  << part.mesh.vertexCount() << " vertices\n";
    }
}

}  // namespace
}  // namespace rigmesh::posetest
