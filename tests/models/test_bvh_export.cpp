// BVH export: writing a simcap Skeleton + Motion and reading it back gives the same joint
// positions (to 1e-5 m), for a procedural walk on the humanoid and for a CMU clip's skeleton.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "models/bvh.h"
#include "models/bvh_export.h"
#include "models/bvh_skeleton.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "models/pose.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

// Largest distance between the joints of `a` and those of `b` that `match` pairs with them
// (-1: no partner, which fails).
template <typename Match>
double worst_distance(const Skeleton& a, const Motion& ma, const Skeleton& b, const Motion& mb,
                      Match match) {
  EXPECT_EQ(a.size(), b.size());
  EXPECT_EQ(ma.frames.size(), mb.frames.size());
  double worst = 0;
  for (size_t f = 0; f < ma.frames.size() && f < mb.frames.size(); ++f) {
    const auto pa = joint_positions(a, ma.frames[f]);
    const auto pb = joint_positions(b, mb.frames[f]);
    for (int j = 0; j < a.size(); ++j) {
      const int k = match(j);
      if (k < 0) {
        ADD_FAILURE() << "no partner for " << a[j].name;
        return INFINITY;
      }
      worst = std::max(worst, (pa[j] - pb[k]).norm());
    }
  }
  return worst;
}

TEST(BvhExport, ProceduralWalkRoundTrips) {
  const Skeleton s = build_humanoid({.height = 1.68, .proportions = {}});
  const Motion m = generate_procedural({.kind = "walk_path", .duration_s = 2.0}, s, 30.0);
  testing::TempDir dir;
  write_bvh(dir / "walk.bvh", s, m);
  const BvhClip clip = read_bvh(dir / "walk.bvh");
  EXPECT_DOUBLE_EQ(clip.metres_per_unit, 1.0);  // detected
  EXPECT_NEAR(clip.fps(), 30.0, 1e-6);
  const BvhSkeleton back = skeleton_from_bvh(clip);
  EXPECT_EQ(back.naming, "h-anim");
  // Joints come back in depth-first order, under their names (sites through the table).
  const auto by_name = [&](int j) { return back.skeleton.find(s[j].name); };
  EXPECT_LT(worst_distance(s, m, back.skeleton, back.motion, by_name), 1e-5);
}

TEST(BvhExport, CentimetresAreDetectedOnTheWayBack) {
  const Skeleton s = build_humanoid();
  const Motion m = generate_procedural({.kind = "arm_raise", .duration_s = 1.0}, s, 10.0);
  testing::TempDir dir;
  write_bvh(dir / "cm.bvh", s, m, {.metres_per_unit = 0.01});
  const BvhClip clip = read_bvh(dir / "cm.bvh");
  EXPECT_DOUBLE_EQ(clip.metres_per_unit, 0.01);
  const BvhSkeleton back = skeleton_from_bvh(clip);
  const auto by_name = [&](int j) { return back.skeleton.find(s[j].name); };
  EXPECT_LT(worst_distance(s, m, back.skeleton, back.motion, by_name), 1e-5);
}

TEST(BvhExport, CmuSkeletonRoundTrips) {
  const BvhClip clip = read_bvh(std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_03_start_hop_stop.bvh");
  const BvhSkeleton original = skeleton_from_bvh(clip);
  testing::TempDir dir;
  write_bvh(dir / "hop.bvh", original.skeleton, original.motion);
  const BvhSkeleton back = skeleton_from_bvh(read_bvh(dir / "hop.bvh"));
  // A BVH clip's joints are already in depth-first order, so indices match.
  const auto same_index = [](int j) { return j; };
  EXPECT_LT(
      worst_distance(original.skeleton, original.motion, back.skeleton, back.motion, same_index),
      1e-5);
  EXPECT_EQ(back.skeleton[back.skeleton.require("l_knee")].parent, back.skeleton.require("l_hip"));
}

TEST(BvhExport, LeafJointsGetAnEndSiteAndBadInputIsRefused) {
  Skeleton s;
  s.add({"humanoid_root", "sacrum", -1, {0, 1, 0}, false});
  s.add({"l_hip", "l_thigh", 0, {0.1, 0.9, 0}, false});
  Motion m;
  m.fps = 24;
  m.frames.push_back(Pose::neutral(s));
  const std::string text = format_bvh(s, m);
  EXPECT_NE(text.find("JOINT l_hip"), std::string::npos);
  EXPECT_NE(text.find("End Site"), std::string::npos);
  EXPECT_NE(text.find("Frame Time: 0.0416666667"), std::string::npos);
  const BvhClip clip = parse_bvh(text, "leaf.bvh", {.metres_per_unit = 1.0});
  EXPECT_EQ(clip.joints.size(), 3u);

  EXPECT_THROW(format_bvh(s, Motion{}), Error);
  Motion wrong = m;
  wrong.frames[0].rotations.pop_back();
  EXPECT_THROW(format_bvh(s, wrong), Error);
  testing::TempDir dir;
  EXPECT_THROW(write_bvh(dir / "none.bvh", s, Motion{}), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "none.bvh"));
}

}  // namespace
}  // namespace simcap
