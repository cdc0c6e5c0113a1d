// What our COLLADA import reads of the extras Blender 3.x writes: the action
// name hidden in the channel ids of its animation container
// (io/ColladaActionNames.h) and the `connect` flag it writes only for
// connected bones (io/BoneTipHints.h). The texts are cut down from Blender
// 3.4.1's export of a Rigify meta-rig (tests/external/make_rigify_rigs.py).
#include <gtest/gtest.h>

#include <string>

#include "io/BoneTipHints.h"
#include "io/ColladaActionNames.h"

namespace rigmesh {
namespace {

std::string collada(const std::string& body) {
    return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">)" +
           body + "</COLLADA>";
}

std::string channel(const std::string& id, const std::string& target) {
    return "<animation id=\"" + id + "\" name=\"metarig\"><channel source=\"#" + id +
           "-sampler\" target=\"" + target + "/transform\"/></animation>";
}

TEST(ColladaActionNames, ReadsBlendersActionFromTheChannelIdsOfItsContainer) {
    const std::string dae =
        collada("<library_animations><animation id=\"action_container-metarig\" name=\"metarig\">" +
                channel("metarig_Walk_spine_pose_matrix", "metarig_spine") +
                channel("metarig_Walk_spine_001_pose_matrix", "metarig_spine_001") +
                channel("metarig_Walk_f_index_01_L_pose_matrix", "metarig_f_index_01_L") +
                "</animation></library_animations>");
    const auto names = readColladaActionNames(dae);
    ASSERT_TRUE(names.contains("metarig"));
    EXPECT_EQ(names.at("metarig"), "Walk");
    EXPECT_EQ(names.at("action_container-metarig"), "Walk");
    EXPECT_EQ(names.at("metarig_metarig"), "Walk");  // as Assimp names the combined animation
}

TEST(ColladaActionNames, KeepsAnActionNameThatHasUnderscores) {
    const std::string dae = collada(
        "<library_animations><animation id=\"action_container-rig\" name=\"rig\">" +
        channel("rig_Run_Fast_hip_pose_matrix", "rig_hip") + "</animation></library_animations>");
    // Only the container's name, the channel ids and their targets count (the
    // channels' own name attribute is "metarig" here and plays no part).
    const auto names = readColladaActionNames(dae);
    ASSERT_TRUE(names.contains("rig"));
    EXPECT_EQ(names.at("rig"), "Run_Fast");
}

TEST(ColladaActionNames, NamesNothingWhenTheChannelsDisagreeOrDoNotFollowBlender) {
    const std::string disagree =
        collada("<library_animations><animation id=\"c\" name=\"metarig\">" +
                channel("metarig_Walk_spine_pose_matrix", "metarig_spine") +
                channel("metarig_Run_spine_001_pose_matrix", "metarig_spine_001") +
                "</animation></library_animations>");
    EXPECT_TRUE(readColladaActionNames(disagree).empty());
    const std::string other =
        collada("<library_animations><animation id=\"Armature_Action\" name=\"Action\">" +
                channel("Bone_location_X", "Bone") + "</animation></library_animations>");
    EXPECT_TRUE(readColladaActionNames(other).empty());
    EXPECT_TRUE(readColladaActionNames("not xml <").empty());
}

TEST(ColladaConnections, AJointWithBlendersExtraButNoConnectIsDisconnected) {
    const std::string dae = collada(R"(<library_visual_scenes><visual_scene id="Scene">
<node id="metarig_spine" name="spine" type="JOINT">
  <node id="metarig_spine_001" name="spine.001" type="JOINT">
    <extra><technique profile="blender"><connect sid="connect" type="bool">1</connect><layer sid="layer" type="string">3</layer></technique></extra>
  </node>
  <node id="metarig_spine_004" name="spine.004" type="JOINT">
    <extra><technique profile="blender"><layer sid="layer" type="string">3</layer></technique></extra>
  </node>
  <node id="metarig_tail" name="tail" type="JOINT"/>
</node></visual_scene></library_visual_scenes>)");
    const auto connected = readColladaBoneConnections(dae);
    ASSERT_TRUE(connected.contains("spine.001"));
    EXPECT_TRUE(connected.at("spine.001"));
    ASSERT_TRUE(connected.contains("spine.004"));
    EXPECT_FALSE(connected.at("spine.004"));
    EXPECT_FALSE(connected.contains("tail"));  // no extra: the importer decides by geometry
}

}  // namespace
}  // namespace rigmesh
