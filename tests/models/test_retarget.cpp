// Retargeting BVH clips onto the simcap humanoid: bones point where the clip's bones point
// (whatever the rest poses), the root follows the clip scaled by leg length, feet meet the floor,
// and the report says what was not mapped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "models/bvh.h"
#include "models/humanoid.h"
#include "models/pose.h"
#include "models/retarget.h"

namespace simcap {
namespace {

const std::string kWalk = std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_01_start_walk_stop.bvh";

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// For each pair (target joint, its child) whose BVH joints are named here: the angle between
// the target bone and the clip's bone, worst over frames.
double worst_bone_angle(const BvhClip& clip, const Skeleton& target, const Motion& motion,
                        const std::vector<std::pair<std::string, std::string>>& bones,
                        const std::vector<std::pair<std::string, std::string>>& bvh_names) {
  double worst = 0;
  for (int f = 0; f < clip.frame_count(); f += 7) {
    const auto t = joint_positions(target, motion.frames[f]);
    const auto s = bvh_joint_positions(clip, f);
    for (size_t b = 0; b < bones.size(); ++b) {
      const Eigen::Vector3d tb =
          t[target.require(bones[b].second)] - t[target.require(bones[b].first)];
      const Eigen::Vector3d sb =
          s[clip.find(bvh_names[b].second)] - s[clip.find(bvh_names[b].first)];
      worst = std::max(worst, angle(tb, sb));
    }
  }
  return worst;
}

TEST(Retarget, CmuWalkBonesFollowTheClip) {
  const BvhClip clip = read_bvh(kWalk);
  const Skeleton target = build_humanoid({.height = 1.62, .proportions = {}});
  const Retargeted r = retarget_bvh(clip, target);
  ASSERT_EQ(r.motion.frames.size(), 994u);
  EXPECT_DOUBLE_EQ(r.motion.fps, clip.fps());
  const double worst = worst_bone_angle(clip, target, r.motion,
                                        {{"l_hip", "l_knee"},
                                         {"l_knee", "l_talocrural"},
                                         {"r_talocrural", "r_metatarsophalangeal_2"},
                                         {"l_shoulder", "l_elbow"},
                                         {"r_elbow", "r_radiocarpal"},
                                         {"r_sternoclavicular", "r_shoulder"},
                                         {"vc4", "skullbase"}},
                                        {{"LeftHip", "LeftKnee"},
                                         {"LeftKnee", "LeftAnkle"},
                                         {"RightAnkle", "RightToe"},
                                         {"LeftShoulder", "LeftElbow"},
                                         {"RightElbow", "RightWrist"},
                                         {"RightCollar", "RightShoulder"},
                                         {"Neck", "Head"}});
  EXPECT_LT(worst, 1e-6);
  // Segment lengths are the target's own.
  const auto p = joint_positions(target, r.motion.frames[600]);
  const int hip = target.require("l_hip"), knee = target.require("l_knee");
  EXPECT_NEAR((p[knee] - p[hip]).norm(), (target[knee].center - target[hip].center).norm(), 1e-9);
}

TEST(Retarget, RootFollowsTheClipScaledByLegLength) {
  const BvhClip clip = read_bvh(kWalk);
  const Skeleton target = build_humanoid({.height = 1.9, .proportions = {}});
  const Retargeted r = retarget_bvh(clip, target);
  const auto leg = [](const std::vector<Eigen::Vector3d>& p, int h, int k, int a) {
    return (p[k] - p[h]).norm() + (p[a] - p[k]).norm();
  };
  const auto rest = bvh_joint_positions(clip, -1);
  std::vector<Eigen::Vector3d> centres;
  for (const auto& j : target.joints()) centres.push_back(j.center);
  const double scale =
      (leg(centres, target.require("l_hip"), target.require("l_knee"),
           target.require("l_talocrural")) +
       leg(centres, target.require("r_hip"), target.require("r_knee"),
           target.require("r_talocrural"))) /
      (leg(rest, clip.find("LeftHip"), clip.find("LeftKnee"), clip.find("LeftAnkle")) +
       leg(rest, clip.find("RightHip"), clip.find("RightKnee"), clip.find("RightAnkle")));
  EXPECT_NEAR(r.report.root_scale, scale, 1e-12);
  for (int f = 0; f < clip.frame_count(); f += 11) {
    const auto s = bvh_joint_positions(clip, f);
    const auto t = joint_positions(target, r.motion.frames[f]);
    const Eigen::Vector3d source_mid = 0.5 * (s[clip.find("LeftHip")] + s[clip.find("RightHip")]);
    const Eigen::Vector3d target_mid =
        0.5 * (t[target.require("l_hip")] + t[target.require("r_hip")]);
    EXPECT_NEAR(target_mid.x(), scale * source_mid.x(), 1e-9);
    EXPECT_NEAR(target_mid.z(), scale * source_mid.z(), 1e-9);
  }
}

TEST(Retarget, FeetMeetTheFloorAndTheReportSaysWhatWasLeftOut) {
  const BvhClip clip = read_bvh(kWalk);
  const Skeleton target = build_humanoid();
  const Retargeted r = retarget_bvh(clip, target);
  const RetargetReport& report = r.report;
  EXPECT_EQ(report.naming, "cmu-asf");
  EXPECT_TRUE(contains(report.folded, "LHipJoint"));
  EXPECT_TRUE(contains(report.unmapped, "LThumb"));
  EXPECT_FALSE(contains(report.unmapped, "LeftHip"));
  EXPECT_TRUE(contains(report.target_unmapped, "vt1"));
  EXPECT_NE(report.summary().find("LThumb"), std::string::npos);
  // A foot is down in every frame of this clip, and it is on the floor, not in or above it.
  const FootStats& feet = report.target_feet;
  EXPECT_EQ(feet.frames, 994);
  EXPECT_GT(feet.lowest_min, -1e-9);
  EXPECT_LT(feet.lowest_mean, 0.002);
  // Retargeting does not make the feet slide more than they do in the clip.
  EXPECT_LT(feet.slide_median, 1.5 * report.source_feet.slide_median);
  EXPECT_LT(feet.drift_mean, 1.5 * report.source_feet.drift_mean);
  // Without floor placement the feet float or sink by centimetres.
  const Retargeted raw = retarget_bvh(clip, target, {.place_on_floor = false});
  EXPECT_GT(std::abs(raw.report.target_feet.lowest_mean), 0.01);
}

// A Mixamo-named clip in centimetres whose rest pose is a T-pose (arms along X).
std::string tpose_clip() {
  struct J {
    const char* name;
    int parent;
    double x, y, z;
  };
  // In depth-first order, as BVH lists them; Mixamo ends chains with "_End" joints.
  const std::vector<J> joints = {{"Hips", -1, 0, 0, 0},          {"Spine", 0, 0, 10, 0},
                                 {"Spine1", 1, 0, 12, 0},        {"Spine2", 2, 0, 12, 0},
                                 {"Neck", 3, 0, 15, 0},          {"Head", 4, 0, 10, 0},
                                 {"HeadTop_End", 5, 0, 18, 0},   {"LeftShoulder", 3, 6, 10, 0},
                                 {"LeftArm", 7, 12, 0, 0},       {"LeftForeArm", 8, 28, 0, 0},
                                 {"LeftHand", 9, 25, 0, 0},      {"RightShoulder", 3, -6, 10, 0},
                                 {"RightArm", 11, -12, 0, 0},    {"RightForeArm", 12, -28, 0, 0},
                                 {"RightHand", 13, -25, 0, 0},   {"LeftUpLeg", 0, 9, -5, 0},
                                 {"LeftLeg", 15, 0, -42, 0},     {"LeftFoot", 16, 0, -42, 0},
                                 {"LeftToeBase", 17, 0, -8, 12}, {"LeftToe_End", 18, 0, 0, 6},
                                 {"RightUpLeg", 0, -9, -5, 0},   {"RightLeg", 20, 0, -42, 0},
                                 {"RightFoot", 21, 0, -42, 0},   {"RightToeBase", 22, 0, -8, 12},
                                 {"RightToe_End", 23, 0, 0, 6}};
  std::string text = "HIERARCHY\n";
  std::vector<int> open;
  const auto close_to = [&](int parent) {
    while (!open.empty() && open.back() != parent) {
      text += "}\n";
      open.pop_back();
    }
  };
  for (size_t j = 0; j < joints.size(); ++j) {
    close_to(joints[j].parent);
    text += std::string(j == 0 ? "ROOT " : "JOINT ") + "mixamorig:" + joints[j].name + "\n{\n";
    text += "OFFSET " + std::to_string(joints[j].x) + " " + std::to_string(joints[j].y) + " " +
            std::to_string(joints[j].z) + "\n";
    text += j == 0 ? "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                   : "CHANNELS 3 Zrotation Xrotation Yrotation\n";
    const bool leaf = std::none_of(joints.begin(), joints.end(),
                                   [&](const J& k) { return k.parent == static_cast<int>(j); });
    if (leaf) text += "End Site\n{\nOFFSET 0 0 6\n}\n";
    open.push_back(static_cast<int>(j));
  }
  close_to(-1);
  text += "MOTION\nFrames: 2\nFrame Time: 0.0333333\n";
  for (int f = 0; f < 2; ++f) {
    text += "0 97 0 0 0 0";
    for (size_t j = 1; j < joints.size(); ++j) {
      // Frame 1: the left arm hangs down (-90 degrees about Z from the T-pose).
      text +=
          std::string(f == 1 && std::string(joints[j].name) == "LeftArm" ? " -90" : " 0") + " 0 0";
    }
    text += "\n";
  }
  return text;
}

TEST(Retarget, TPoseClipDrivesArmsThatHangInTheNeutralPose) {
  const BvhClip clip = parse_bvh(tpose_clip(), "tpose.bvh");
  EXPECT_DOUBLE_EQ(clip.metres_per_unit, 0.01);
  const Skeleton target = build_humanoid();
  const Retargeted r = retarget_bvh(clip, target);
  EXPECT_EQ(r.report.naming, "mixamo");
  EXPECT_TRUE(contains(r.report.target_unmapped, "vl5"));
  const int shoulder = target.require("l_shoulder"), elbow = target.require("l_elbow");
  const int wrist = target.require("l_radiocarpal"), tip = target.require("l_hand_tip");
  const auto t0 = joint_positions(target, r.motion.frames[0]);
  EXPECT_LT(angle(t0[elbow] - t0[shoulder], Eigen::Vector3d::UnitX()), 1e-6);
  EXPECT_LT(angle(t0[wrist] - t0[elbow], Eigen::Vector3d::UnitX()), 1e-6);
  // The clip names no fingertip: the hand continues the forearm.
  EXPECT_LT(angle(t0[tip] - t0[wrist], t0[wrist] - t0[elbow]), 0.1);
  const auto t1 = joint_positions(target, r.motion.frames[1]);
  EXPECT_LT(angle(t1[elbow] - t1[shoulder], -Eigen::Vector3d::UnitY()), 1e-6);
  EXPECT_LT(angle(t1[wrist] - t1[elbow], -Eigen::Vector3d::UnitY()), 1e-6);
  EXPECT_LT(angle(t1[target.require("r_elbow")] - t1[target.require("r_shoulder")],
                  -Eigen::Vector3d::UnitX()),
            1e-6);
  EXPECT_GT(r.report.target_feet.lowest_min, -1e-9);
}

TEST(Retarget, AClipWithoutLegsIsRefused) {
  std::string text = tpose_clip();
  for (const char* side : {"LeftUpLeg", "RightUpLeg"}) {
    text.replace(text.find(side), std::string(side).size(), "Tail");
    text.replace(text.find("Tail"), 4, side[0] == 'L' ? "TailA" : "TailB");
  }
  const BvhClip clip = parse_bvh(text, "legless.bvh");
  try {
    retarget_bvh(clip, build_humanoid());
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(
        std::string(e.what()).find("legless.bvh: cannot retarget: no BVH joint maps to 'l_hip'"),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace simcap
