// BVH reading: channel orders, end sites, line endings, units, forward kinematics against
// transforms composed by hand, and bad input reported as file:line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "models/bvh.h"
#include "tests/support/error_of.h"

namespace simcap {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Root with position and rotation channels interleaved (legal, if unusual), a child with XYZ
// rotations and an end site.
const char* kMixed =
    "HIERARCHY\n"
    "ROOT Pelvis\n"
    "{\n"
    "  OFFSET 0.5 1.0 -0.25\n"
    "  CHANNELS 6 Zrotation Xposition Yrotation Yposition Xrotation Zposition\n"
    "  JOINT Thigh\n"
    "  {\n"
    "    OFFSET 0.1 -0.4 0.0\n"
    "    CHANNELS 3 Xrotation Yrotation Zrotation\n"
    "    End Site\n"
    "    {\n"
    "      OFFSET 0.0 -0.45 0.05\n"
    "    }\n"
    "  }\n"
    "}\n"
    "MOTION\n"
    "Frames: 2\n"
    "Frame Time: 0.04\n"
    "0 0 0 0 0 0 0 0 0\n"
    "30 0.2 -45 0.3 10 -0.1 20 -35 60\n";

Eigen::Matrix4d translation(double x, double y, double z) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 3) = x;
  m(1, 3) = y;
  m(2, 3) = z;
  return m;
}

Eigen::Matrix4d rotation(int axis, double degrees) {
  const double c = std::cos(degrees * kDeg), s = std::sin(degrees * kDeg);
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(a, a) = c;
  m(a, b) = -s;
  m(b, a) = s;
  m(b, b) = c;
  return m;
}

TEST(Bvh, ReadsJointsChannelsAndEndSites) {
  const BvhClip clip = parse_bvh(kMixed, "mixed.bvh", {.metres_per_unit = 1.0});
  ASSERT_EQ(clip.joints.size(), 3u);
  EXPECT_EQ(clip.joints[0].name, "Pelvis");
  EXPECT_EQ(clip.joints[1].name, "Thigh");
  EXPECT_EQ(clip.joints[2].name, "Thigh_End");
  EXPECT_TRUE(clip.joints[2].is_end_site);
  EXPECT_EQ(clip.joints[2].parent, 1);
  EXPECT_EQ(clip.channel_count, 9);
  EXPECT_EQ(clip.joints[1].first_channel, 6);
  EXPECT_EQ(clip.joints[0].channels[1], BvhChannel::x_position);
  EXPECT_EQ(bvh_channel_name(clip.joints[1].channels[0]), "Xrotation");
  EXPECT_EQ(clip.frame_count(), 2);
  EXPECT_DOUBLE_EQ(clip.frame_time, 0.04);
  EXPECT_DOUBLE_EQ(clip.fps(), 25.0);
  EXPECT_FALSE(clip.units_detected);
}

TEST(Bvh, ForwardKinematicsComposesChannelsInFileOrder) {
  const BvhClip clip = parse_bvh(kMixed, "mixed.bvh", {.metres_per_unit = 1.0});
  const Eigen::Matrix4d root = translation(0.5, 1.0, -0.25) * rotation(2, 30) *
                               translation(0.2, 0, 0) * rotation(1, -45) * translation(0, 0.3, 0) *
                               rotation(0, 10) * translation(0, 0, -0.1);
  const Eigen::Matrix4d thigh =
      root * translation(0.1, -0.4, 0) * rotation(0, 20) * rotation(1, -35) * rotation(2, 60);
  const Eigen::Vector4d tip = thigh * Eigen::Vector4d(0, -0.45, 0.05, 1);
  const auto p = bvh_joint_positions(clip, 1);
  EXPECT_LT((p[0] - root.block<3, 1>(0, 3)).norm(), 1e-12);
  EXPECT_LT((p[1] - thigh.block<3, 1>(0, 3)).norm(), 1e-12);
  EXPECT_LT((p[2] - tip.head<3>()).norm(), 1e-12);
  const auto world = bvh_forward_kinematics(clip, 1);
  EXPECT_LT((world[1].matrix() - thigh).norm(), 1e-12);

  // Rest pose: offsets only; frame 0 (all zero) is the same.
  const auto rest = bvh_joint_positions(clip, -1);
  EXPECT_LT((rest[2] - Eigen::Vector3d(0.6, 0.15, -0.2)).norm(), 1e-12);
  const auto zero = bvh_joint_positions(clip, 0);
  for (size_t j = 0; j < rest.size(); ++j) EXPECT_LT((rest[j] - zero[j]).norm(), 1e-12);
}

TEST(Bvh, CrlfAndLfGiveTheSameClip) {
  std::string crlf;
  for (const char* c = kMixed; *c; ++c) {
    if (*c == '\n') crlf += '\r';
    crlf += *c;
  }
  const BvhClip a = parse_bvh(kMixed, "lf.bvh");
  const BvhClip b = parse_bvh(crlf, "crlf.bvh");
  ASSERT_EQ(a.joints.size(), b.joints.size());
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.metres_per_unit, b.metres_per_unit);
  for (size_t j = 0; j < a.joints.size(); ++j) EXPECT_EQ(a.joints[j].name, b.joints[j].name);
}

TEST(Bvh, ConvertsUnitsAndDetectsThem) {
  // kMixed is 0.85 units tall: detected as metres.
  const BvhClip metres = parse_bvh(kMixed, "m.bvh");
  EXPECT_TRUE(metres.units_detected);
  EXPECT_DOUBLE_EQ(metres.metres_per_unit, 1.0);
  const BvhClip cm = parse_bvh(kMixed, "cm.bvh", {.metres_per_unit = 0.01});
  EXPECT_DOUBLE_EQ(cm.joints[1].offset.y(), -0.004);
  // Position channels are converted too, rotation channels are not.
  EXPECT_DOUBLE_EQ(cm.values[9 + 1], 0.002);
  EXPECT_DOUBLE_EQ(cm.values[9 + 0], 30.0);
  EXPECT_THROW(parse_bvh(kMixed, "x.bvh", {.metres_per_unit = -1}), Error);

  const BvhClip cmu = read_bvh(std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_01_start_walk_stop.bvh");
  EXPECT_TRUE(cmu.units_detected);
  EXPECT_DOUBLE_EQ(cmu.metres_per_unit, kCmuMetresPerUnit);
  EXPECT_EQ(cmu.frame_count(), 994);
  EXPECT_NEAR(cmu.fps(), 120.0, 0.01);
  // LeftKnee's OFFSET is "2.49329 -6.85026 0.00000" CMU units.
  const int knee = cmu.find("LeftKnee");
  ASSERT_GE(knee, 0);
  EXPECT_NEAR(cmu.joints[knee].offset.y(), -6.85026 * 0.0254 / 0.45, 1e-12);
  const BvhClip inches = read_bvh(std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_01_start_walk_stop.bvh",
                                  {.metres_per_unit = 0.0254});
  EXPECT_NEAR(inches.joints[knee].offset.y(), -6.85026 * 0.0254, 1e-12);
}

TEST(Bvh, ShippedWalkIsTheCmuClip) {
  const BvhClip shipped =
      read_bvh(std::string(SIMCAP_SOURCE_DIR) + "/models/assets/cmu_131_01_start_walk_stop.bvh");
  const BvhClip shared =
      read_bvh(std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_01_start_walk_stop.bvh");
  EXPECT_EQ(shipped.frame_count(), 994);
  EXPECT_EQ(shipped.values, shared.values);
}

// The message of the Error that parsing `text` throws.
std::string error_of(const std::string& text) {
  return testing::error_of([&] { parse_bvh(text, "bad.bvh"); });
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Bvh, BadInputNamesFileLineAndWhatWasExpected) {
  const std::string good = kMixed;
  // Truncated inside the hierarchy.
  EXPECT_NE(error_of(good.substr(0, good.find("End Site"))).find("bad.bvh:9: unexpected end"),
            std::string::npos)
      << error_of(good.substr(0, good.find("End Site")));
  // Truncated in the motion data: the last frame is missing.
  const std::string cut = good.substr(0, good.rfind("30 0.2"));
  EXPECT_NE(error_of(cut).find("expected 2 frames"), std::string::npos) << error_of(cut);
  // A frame with a value missing.
  const std::string short_frame = replace(good, "20 -35 60", "20 -35");
  EXPECT_NE(error_of(short_frame).find("bad.bvh:20: frame 1: expected 9 values"), std::string::npos)
      << error_of(short_frame);
  // CHANNELS announcing more names than given.
  const std::string few = replace(good, "CHANNELS 3 Xrotation", "CHANNELS 4 Xrotation");
  EXPECT_NE(error_of(few).find("bad.bvh:10: CHANNELS of 'Thigh': expected 4 channel names"),
            std::string::npos)
      << error_of(few);
  // Non-numeric values.
  const std::string word = replace(good, "30 0.2", "30 abc");
  EXPECT_NE(error_of(word).find("bad.bvh:20: frame 1, value 2: expected a number, got 'abc'"),
            std::string::npos)
      << error_of(word);
  const std::string offset = replace(good, "OFFSET 0.1 -0.4", "OFFSET 0.1 x");
  EXPECT_NE(error_of(offset).find("bad.bvh:8: OFFSET of 'Thigh': expected a number"),
            std::string::npos)
      << error_of(offset);
  // Unknown channel.
  const std::string channel = replace(good, "Yrotation Zrotation", "Wrotation Zrotation");
  EXPECT_NE(error_of(channel).find("bad.bvh:9: CHANNELS of 'Thigh'"), std::string::npos);
  EXPECT_NE(error_of(channel).find("got 'Wrotation'"), std::string::npos) << error_of(channel);
  // No MOTION section.
  const std::string no_motion = good.substr(0, good.find("MOTION"));
  EXPECT_NE(error_of(no_motion).find("bad.bvh:15: expected MOTION"), std::string::npos)
      << error_of(no_motion);
  // Frame count disagreeing with the data, both ways.
  const std::string more = replace(good, "Frames: 2", "Frames: 3");
  EXPECT_NE(error_of(more).find("bad.bvh:20: expected 3 frames ('Frames:' on line 17)"),
            std::string::npos)
      << error_of(more);
  const std::string fewer = replace(good, "Frames: 2", "Frames: 1");
  EXPECT_NE(error_of(fewer).find("bad.bvh:20: more frames than the 1"), std::string::npos)
      << error_of(fewer);
  // A declared frame count beyond the limit is refused before any frame is read.
  const std::string huge = replace(good, "Frames: 2", "Frames: 1000000000");
  EXPECT_NE(error_of(huge).find("bad.bvh:17: Frames: 1000000000 is more than simcap's largest "
                                "frame count, 1000000"),
            std::string::npos)
      << error_of(huge);
  EXPECT_NE(error_of(replace(good, "Frames: 2", "Frames: two")).find("expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of(replace(good, "Frame Time: 0.04", "Frame Time: 0")).find("positive"),
            std::string::npos);
  EXPECT_NE(error_of(replace(good, "}\nMOTION", "}\n}\nMOTION")).find("expected 'MOTION'"),
            std::string::npos);
  EXPECT_NE(error_of(replace(good, "HIERARCHY", "HIERARCHIE")).find("bad.bvh:1:"),
            std::string::npos);
  EXPECT_NE(error_of("").find("bad.bvh:1: unexpected end of the file"), std::string::npos);
  EXPECT_NE(error_of(replace(good, "0 0 0 0 0 0 0 0 0", "0 0 0 nan 0 0 0 0 0"))
                .find("expected a number, got 'nan'"),
            std::string::npos);
  EXPECT_THROW(read_bvh("/nonexistent/clip.bvh"), Error);
}

}  // namespace
}  // namespace simcap
