// Clip export is bounded by the keys, not by the clip's length in frames
// (issue 9: a key at 1e6 s, or 20,000 keys, never finished).
#include <gtest/gtest.h>

#include <algorithm>

#include "io/AssimpAnimationBuilder.h"
#include "pose/Clip.h"

namespace rigmesh {
namespace {

TEST(ClipExport, ASmoothClipSpanningMillionsOfFramesSamplesEachSegmentBoundedly) {
    Clip clip;
    clip.interpolation = Interpolation::Smooth;
    clip.setKey(0.0, Pose{});
    clip.setKey(Clip::kLongestKeyTime, Pose{});
    const std::vector<double> times = exportedKeyTimes(clip);
    EXPECT_EQ(times.size(), 2u + kMaxFramesPerSegment);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
    EXPECT_EQ(times.front(), 0.0);
    EXPECT_EQ(times.back(), Clip::kLongestKeyTime);
}

TEST(ClipExport, ShortSmoothSegmentsStillGetEveryFrame) {
    Clip clip(24.0);
    clip.interpolation = Interpolation::Smooth;
    clip.setKey(0.0, Pose{});
    clip.setKey(1.0, Pose{});
    const std::vector<double> times = exportedKeyTimes(clip);
    EXPECT_EQ(times.size(), 25u);  // frames 0..24
    EXPECT_NEAR(times[12], 0.5, 1e-12);
}

TEST(ClipExport, TwentyThousandKeysGiveAtMostBoundedSamplesPerKey) {
    Clip clip(24.0);
    clip.interpolation = Interpolation::Smooth;
    for (int k = 0; k < 20000; ++k)
        clip.setKey(k * 0.5, Pose{});
    const std::vector<double> times = exportedKeyTimes(clip);
    // Twelve frames per half-second segment: the key and eleven between.
    EXPECT_EQ(times.size(), 19999u * 12u + 1u);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
}

}  // namespace
}  // namespace rigmesh
