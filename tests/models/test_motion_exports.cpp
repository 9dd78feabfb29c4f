// Motions out: rotations fitted to a track's joint positions point its bones where the track
// does; the BVH and X3D (HAnimMotion) files written from them read back to the same motion, and
// malformed HAnimMotions are refused with file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "models/bvh.h"
#include "models/bvh_export.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "models/pose.h"
#include "models/pose_from_joints.h"
#include "models/x3d_export.h"
#include "models/x3d_humanoid.h"
#include "tests/support/error_of.h"

namespace simcap {
namespace {

using testing::error_of;

// The retargeted CMU walk at 30 fps on the humanoid, its first 90 frames.
Motion cmu_walk(const Skeleton& s) {
  MotionSource source;
  source.bvh = SIMCAP_SOURCE_DIR "/models/assets/cmu_131_01_start_walk_stop.bvh";
  Motion m = load_motion(source, s, 30.0);
  m.frames.resize(90);
  return m;
}

JointTrack he15_track(const Skeleton& s, const Motion& m) {
  JointTrack t;
  t.joints = he15_joints();
  for (size_t f = 0; f < m.frames.size(); ++f) {
    const auto p = joint_positions(s, m.frames[f]);
    std::vector<Eigen::Vector3d> row;
    for (const std::string& name : t.joints) row.push_back(p[s.require(name)]);
    t.add_frame(static_cast<int>(f), row);
  }
  return t;
}

const std::pair<const char*, const char*> kBones[] = {
    {"l_shoulder", "l_elbow"},    {"l_elbow", "l_radiocarpal"}, {"r_shoulder", "r_elbow"},
    {"r_elbow", "r_radiocarpal"}, {"l_hip", "l_knee"},          {"l_knee", "l_talocrural"},
    {"r_hip", "r_knee"},          {"r_knee", "r_talocrural"},   {"vc7", "skullbase"}};

double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(MotionFromTrack, BonesPointWhereTheTracksDo) {
  const Skeleton s = build_humanoid({.height = 1.68, .proportions = {}});
  const Motion walk = cmu_walk(s);
  const JointTrack track = he15_track(s, walk);
  const Skeleton fitted = humanoid_for_track(track);
  EXPECT_NEAR(fitted[fitted.require("skull_tip")].center.y(), 1.68, 1e-9);  // its height back
  const TrackMotion m = motion_from_track(track, fitted, 30.0);
  ASSERT_EQ(m.motion.frames.size(), walk.frames.size());
  EXPECT_EQ(m.held, 0);
  for (size_t f = 0; f < walk.frames.size(); ++f) {
    const auto p = joint_positions(fitted, m.motion.frames[f]);
    const auto q = joint_positions(s, walk.frames[f]);
    auto at = [](const Skeleton& k, const std::vector<Eigen::Vector3d>& x, const char* n) {
      return x[k.require(n)];
    };
    EXPECT_LT((at(fitted, p, "humanoid_root") - at(s, q, "humanoid_root")).norm(), 1e-12);
    for (const auto& [a, b] : kBones) {
      EXPECT_LT(angle(at(fitted, p, b) - at(fitted, p, a), at(s, q, b) - at(s, q, a)), 1e-6)
          << a << "-" << b << " frame " << f;
    }
    // Elbows and knees are hinges about their +X.
    for (const char* hinge : {"l_elbow", "r_knee"}) {
      const Eigen::AngleAxisd aa(m.motion.frames[f].rotations[fitted.require(hinge)]);
      if (std::abs(aa.angle()) > 1e-6) {
        EXPECT_GT(std::abs(aa.axis().x()), 1 - 1e-9) << hinge << " frame " << f;
      }
    }
  }
}

// The track's own body: the head and arm joints land on the track, shoulders too (the clavicles
// follow a shrug; before they did, the walk's raised shoulders and arms came out 7-9 cm low).
// The hips are left out: the pelvis turns with the spine line, so a bent lower back moves them.
TEST(MotionFromTrack, ArmsLandOnTheTrackOfTheSameBody) {
  const Skeleton s = build_humanoid();
  const JointTrack track = he15_track(s, cmu_walk(s));
  const TrackMotion m = motion_from_track(track, s, 30.0);
  for (const char* name : {"vc7", "skullbase", "l_shoulder", "r_shoulder", "l_elbow", "r_elbow",
                           "l_radiocarpal", "r_radiocarpal"}) {
    const int j = track.joint_index(name);
    double worst = 0;
    for (size_t f = 0; f < track.frames.size(); ++f) {
      const auto p = joint_positions(s, m.motion.frames[f]);
      worst = std::max(worst, (p[s.require(name)] - track.positions[f][j]).norm());
    }
    EXPECT_LT(worst, 0.01) << name;
  }
}

TEST(MotionFromTrack, FramesWithoutAllJointsHoldThePreviousPose) {
  const Skeleton s = build_humanoid();
  JointTrack t = he15_track(s, cmu_walk(s));
  t.positions[5][t.joint_index("l_knee")] = Eigen::Vector3d::Constant(NAN);
  t.frames.erase(t.frames.begin() + 7);  // frame 7 absent
  t.positions.erase(t.positions.begin() + 7);
  const TrackMotion m = motion_from_track(t, s, 30.0);
  EXPECT_EQ(m.motion.frames.size(), 90u);
  EXPECT_EQ(m.held, 2);
  EXPECT_EQ(m.motion.frames[5].root_position, m.motion.frames[4].root_position);
  EXPECT_EQ(m.motion.frames[7].root_position, m.motion.frames[6].root_position);
}

// The same joint positions (by joint name) in every frame.
void expect_same_motion(const Skeleton& s, const Motion& a, const Skeleton& t, const Motion& b,
                        double tol) {
  ASSERT_EQ(a.frames.size(), b.frames.size());
  EXPECT_NEAR(a.fps, b.fps, 1e-9);
  for (size_t f = 0; f < a.frames.size(); ++f) {
    const auto p = joint_positions(s, a.frames[f]);
    const auto q = joint_positions(t, b.frames[f]);
    for (int j = 0; j < s.size(); ++j) {
      EXPECT_LT((p[j] - q[t.require(s[j].name)]).norm(), tol) << s[j].name << " frame " << f;
    }
  }
}

TEST(MotionExports, BvhOfAFittedMotionReadsBack) {
  const Skeleton s = build_humanoid();
  const Motion m = motion_from_track(he15_track(s, cmu_walk(s)), s, 30.0).motion;
  const BvhClip clip = parse_bvh(format_bvh(s, m), "fit.bvh", {.metres_per_unit = 1.0});
  ASSERT_EQ(clip.frame_count(), 90);
  for (int f = 0; f < clip.frame_count(); f += 17) {
    const auto p = bvh_joint_positions(clip, f);
    const auto q = joint_positions(s, m.frames[f]);
    for (int j = 0; j < s.size(); ++j) {
      if (s[j].is_site) continue;  // BVH names end sites after their parent
      EXPECT_LT((p[clip.find(s[j].name)] - q[j]).norm(), 1e-5) << s[j].name;
    }
  }
}

TEST(MotionExports, X3dHumanoidAndHAnimMotionReadBack) {
  const Skeleton s = build_humanoid();
  const BodyMesh mesh = build_body_mesh(s);
  const Motion m = motion_from_track(he15_track(s, cmu_walk(s)), s, 30.0).motion;
  const std::array<Eigen::Vector3f, kMaterialRegionCount> colors{};
  const std::string text = format_x3d_humanoid("walker", s, mesh, colors, &m);
  const Body back = parse_x3d_humanoid(text, "walker.x3d");
  ASSERT_EQ(back.skeleton.size(), s.size());
  for (int j = 0; j < s.size(); ++j) {
    const Joint& b = back.skeleton[back.skeleton.require(s[j].name)];
    EXPECT_EQ(b.center, s[j].center);  // shortest round-trip text
    EXPECT_EQ(b.is_site, s[j].is_site);
    if (j > 0) {
      EXPECT_EQ(back.skeleton[b.parent].name, s[s[j].parent].name);
    }
  }
  EXPECT_EQ(back.mesh.triangles.size(), mesh.triangles.size());
  expect_same_motion(s, m, back.skeleton, parse_x3d_motion(text, "walker.x3d", back.skeleton),
                     1e-9);
}

TEST(MotionExports, MalformedHAnimMotionsNameTheirLine) {
  const Skeleton s = build_humanoid();
  const std::string head = "<X3D>\n<Scene>\n";
  auto motion = [&](const std::string& attributes) {
    return error_of([&] {
      parse_x3d_motion(head + "<HAnimMotion " + attributes + "/>\n</Scene></X3D>", "m.x3d", s);
    });
  };
  EXPECT_EQ(error_of([&] { parse_x3d_motion("<X3D/>", "m.x3d", s); }),
            "m.x3d:1: expected an HAnimMotion, found none");
  EXPECT_EQ(
      motion(
          R"(joints="humanoid_root l_wing" channels="3 Xrotation Yrotation Zrotation 1 Xrotation" values="0 0 0 0")"),
      "m.x3d:3: HAnimMotion joints: 'l_wing' is not a joint of the humanoid");
  EXPECT_EQ(
      motion(
          R"(joints="humanoid_root l_knee" channels="3 Xrotation Yrotation Zrotation" values="0 0 0")"),
      "m.x3d:3: HAnimMotion: expected channels for the 2 joints, got 1");
  EXPECT_EQ(motion(R"(joints="l_knee" channels="2 Xrotation" values="0")"),
            "m.x3d:3: HAnimMotion channels: expected 2 channel names, got 1");
  EXPECT_EQ(motion(R"(joints="l_knee" channels="1 Wrotation" values="0")"),
            "m.x3d:3: HAnimMotion channels: expected Xposition, Yposition, Zposition, Xrotation, "
            "Yrotation or Zrotation, got 'Wrotation'");
  EXPECT_EQ(motion(R"(joints="l_knee" channels="2 Xrotation Yrotation" values="1 2 3")"),
            "m.x3d:3: HAnimMotion values: expected a whole number of frames of 2 values, got 3");
  EXPECT_EQ(motion(R"(joints="l_knee" channels="1 Xrotation" values="1 x")"),
            "m.x3d:3: HAnimMotion: values: expected a number, got 'x'");
  EXPECT_EQ(motion(R"(joints="l_knee" channels="1 Xrotation" values="1" frameDuration="0")"),
            "m.x3d:3: HAnimMotion frameDuration: expected seconds > 0");
  // A bent knee, a tenth of a second a frame by default.
  const Motion ok = parse_x3d_motion(
      head +
          R"(<HAnimMotion joints="l_knee" channels="1 Xrotation" values="30 60"/></Scene></X3D>)",
      "m.x3d", s);
  ASSERT_EQ(ok.frames.size(), 2u);
  EXPECT_NEAR(ok.fps, 10.0, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(ok.frames[1].rotations[s.require("l_knee")]).angle(),
              60 * M_PI / 180, 1e-12);
}

}  // namespace
}  // namespace simcap
