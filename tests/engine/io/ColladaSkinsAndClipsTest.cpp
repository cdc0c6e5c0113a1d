// COLLADA as game engines read it (io/ColladaSkinsAndClips.h): every skin
// names the root joints of its joints' trees as its <skeleton>s, and every
// animation is an <animation_clip> of its name spanning its keys.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "IoTestSupport.h"
#include "base/Error.h"
#include "io/ColladaSkinsAndClips.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"

namespace rigmesh {
namespace {

// Per <instance_controller url="#X">: X and the ids its <skeleton>s name.
std::vector<std::pair<std::string, std::vector<std::string>>> skeletons(const std::string& dae) {
    std::vector<std::pair<std::string, std::vector<std::string>>> out;
    const std::regex instance(
        R"re(<instance_controller url="#([^"]+)">([\s\S]*?)</instance_controller>)re");
    const std::regex skeleton(R"re(<skeleton>#([^<]+)</skeleton>)re");
    for (auto it = std::sregex_iterator(dae.begin(), dae.end(), instance);
         it != std::sregex_iterator(); ++it) {
        const std::string body = (*it)[2];
        std::vector<std::string> ids;
        for (auto s = std::sregex_iterator(body.begin(), body.end(), skeleton);
             s != std::sregex_iterator(); ++s)
            ids.push_back((*s)[1]);
        out.emplace_back((*it)[1], ids);
    }
    return out;
}

// The ids of the joint nodes with no joint above them.
std::set<std::string> rootJointIds(const std::string& dae) {
    std::set<std::string> roots;
    int depth = 0;
    std::vector<bool> jointAt;  // per open <node>: is it a joint
    const std::regex tag(R"re(<(/?)node\b([^>]*?)(/?)>)re");
    const std::regex id(R"re(\bid="([^"]+)")re"), joint(R"re(type="JOINT")re");
    for (auto it = std::sregex_iterator(dae.begin(), dae.end(), tag); it != std::sregex_iterator();
         ++it) {
        if ((*it)[1] == "/") {
            jointAt.pop_back(), --depth;
            continue;
        }
        const std::string attributes = (*it)[2];
        const bool isJoint = std::regex_search(attributes, joint);
        std::smatch match;
        if (isJoint && (jointAt.empty() || !jointAt.back()) &&
            std::regex_search(attributes, match, id))
            roots.insert(match[1]);
        if ((*it)[3] != "/")
            jointAt.push_back(isJoint), ++depth;
    }
    return roots;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

TEST(ColladaSkinsAndClips, EachSkinNamesTheRootJointsOfItsPartAsSkeletons) {
    const Part& biped = iotest::sharedPart("biped");
    const Part& tube = iotest::sharedPart("tube");
    std::vector<ExportPart> parts(2);
    parts[0].part = &biped;
    parts[0].name = "biped";
    parts[1].part = &tube;
    parts[1].name = "tube";
    parts[1].placement = Eigen::Translation3d(3.0, 0.0, 0.0);
    const auto path = iotest::scratchFolder() / "two.dae";
    exportScene(parts, nullptr, path.string());
    const std::string dae = readFile(path);

    const auto skins = skeletons(dae);
    ASSERT_EQ(skins.size(), 2u);
    const std::set<std::string> roots = rootJointIds(dae);
    std::set<std::string> named;
    for (const auto& [controller, ids] : skins) {
        const std::string part = controller.substr(0, controller.find('_'));
        ASSERT_FALSE(ids.empty()) << controller;
        for (const std::string& joint : ids) {
            EXPECT_TRUE(roots.contains(joint)) << joint << " is not a root joint";
            EXPECT_EQ(joint.rfind(part + "_bone", 0), 0u) << joint << " is not of " << part;
            named.insert(joint);
        }
    }
    // Every root joint is some skin's skeleton; the biped has 3 root bones.
    EXPECT_EQ(named, roots);
    EXPECT_EQ(skins[0].second.size(), 3u);
    EXPECT_EQ(dae.find("<skeleton>#Armature</skeleton>"), std::string::npos);
}

TEST(ColladaSkinsAndClips, EachAnimationIsAClipOfItsNameFromFirstToLastKey) {
    const Part& part = iotest::sharedPart("y_branch");
    Clip clip = poseDemoClip(part);
    clip.name = "wave";
    ExportPart item;
    item.part = &part;
    const auto path = iotest::scratchFolder() / "clip.dae";
    exportScene({item}, &clip, path.string());
    const std::string dae = readFile(path);
    const std::vector<double> keys = clip.keyTimes();
    std::smatch match;
    ASSERT_TRUE(std::regex_search(
        dae, match,
        std::regex(
            R"re(<animation_clip id="([^"]+)" name="wave" start="([^"]+)" end="([^"]+)">\s*<instance_animation url="#([^"]+)"/>)re")));
    EXPECT_DOUBLE_EQ(std::stod(match[2]), keys.front());
    EXPECT_NEAR(std::stod(match[3]), keys.back(), 1e-6);
    EXPECT_NE(dae.find("<animation id=\"" + match[4].str() + "\""), std::string::npos);
    EXPECT_NE(dae.find("<library_animation_clips>"), std::string::npos);
}

TEST(ColladaSkinsAndClips, AFileWithoutSkinsOrAnimationsIsUnchangedButForLayout) {
    const std::string plain =
        "<COLLADA><library_visual_scenes><visual_scene id=\"s\"><node id=\"n\" type=\"NODE\"/>"
        "</visual_scene></library_visual_scenes></COLLADA>";
    const std::string out = withColladaSkinRootsAndClips(plain);
    EXPECT_EQ(out.find("skeleton"), std::string::npos);
    EXPECT_EQ(out.find("animation_clip"), std::string::npos);
    EXPECT_NE(out.find("<node id=\"n\" type=\"NODE\"/>"), std::string::npos);
}

TEST(ColladaSkinsAndClips, TextThatIsNotXmlIsRefused) {
    EXPECT_THROW(withColladaSkinRootsAndClips("<COLLADA><unclosed>"), Error);
}

}  // namespace
}  // namespace rigmesh
