// skeleton_from_bvh: a simcap Skeleton + Motion that reproduces the clip's own joint positions,
// with H-Anim names where the name table maps them.
#include <gtest/gtest.h>

#include "models/bvh.h"
#include "models/bvh_names.h"
#include "models/bvh_skeleton.h"
#include "models/pose.h"

namespace simcap {
namespace {

const std::string kWalk = std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_01_start_walk_stop.bvh";

TEST(BvhSkeleton, ReproducesTheClipsJointPositions) {
  const BvhClip clip = read_bvh(kWalk);
  const BvhSkeleton b = skeleton_from_bvh(clip);
  ASSERT_EQ(b.skeleton.size(), static_cast<int>(clip.joints.size()));
  ASSERT_EQ(b.motion.frames.size(), 994u);
  EXPECT_DOUBLE_EQ(b.motion.fps, clip.fps());
  double worst = 0;
  for (int f = 0; f < clip.frame_count(); ++f) {
    const auto mine = joint_positions(b.skeleton, b.motion.frames[f]);
    const auto truth = bvh_joint_positions(clip, f);
    for (size_t j = 0; j < truth.size(); ++j) worst = std::max(worst, (mine[j] - truth[j]).norm());
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_TRUE(b.dropped_translations.empty());
  // The neutral pose is the clip's rest pose.
  const auto rest = bvh_joint_positions(clip, -1);
  for (int j = 0; j < b.skeleton.size(); ++j) {
    EXPECT_LT((b.skeleton[j].center - rest[j]).norm(), 1e-12);
  }
}

TEST(BvhSkeleton, RenamesMappedJointsAndKeepsTheRest) {
  const BvhClip clip = read_bvh(kWalk);
  const BvhSkeleton b = skeleton_from_bvh(clip);
  EXPECT_EQ(b.naming, "cmu-asf");
  const Skeleton& s = b.skeleton;
  const int hip = s.require("l_hip");
  EXPECT_EQ(b.source_names[hip], "LeftHip");
  EXPECT_EQ(s[hip].segment, "l_thigh");
  EXPECT_EQ(s[s.require("r_elbow")].segment, "r_forearm");
  EXPECT_EQ(b.source_names[s.require("r_radiocarpal")], "RightWrist");
  EXPECT_EQ(b.source_names[s.require("vc7")], "lowerneck");
  EXPECT_TRUE(s[s.require("l_toe_tip")].is_site);
  EXPECT_TRUE(s[s.require("skull_tip")].is_site);
  // The intermediate LHipJoint stays (positions stay exact) under its own name.
  const int pelvis_bone = s.require("LHipJoint");
  EXPECT_FALSE(b.is_hanim[pelvis_bone]);
  EXPECT_EQ(s[hip].parent, pelvis_bone);
  EXPECT_EQ(b.hanim_parent[hip], s.require("humanoid_root"));
  EXPECT_EQ(b.hanim_parent[s.require("l_knee")], hip);
  EXPECT_EQ(b.hanim_parent[0], -1);
  EXPECT_GE(s.find("LThumb"), 0);
  // Rotations are the clip's local rotations.
  const auto local = bvh_local_transform(clip, s.require("l_knee"), 500);
  EXPECT_LT(b.motion.frames[500].rotations[s.require("l_knee")].angularDistance(
                Eigen::Quaterniond(local.linear())),
            1e-12);
}

TEST(BvhNames, PicksTheTableThatKnowsMostNames) {
  const BvhNaming cmu = map_bvh_names({"Hips", "LHipJoint", "LeftUpLeg", "LeftLeg", "LeftFoot",
                                       "LowerBack", "Spine", "Spine1", "Neck", "Neck1", "Head",
                                       "LeftShoulder", "LeftArm", "LeftForeArm", "LeftHand"});
  EXPECT_EQ(cmu.convention, "cmu-3dsmax");
  EXPECT_EQ(cmu.hanim[11], "l_sternoclavicular");  // LeftShoulder is the clavicle here
  EXPECT_EQ(cmu.hanim[12], "l_shoulder");
  EXPECT_TRUE(cmu.intermediate[1]);
  const BvhNaming asf = map_bvh_names({"Hips", "LHipJoint", "LeftHip", "LeftKnee", "LeftAnkle",
                                       "LeftCollar", "LeftShoulder", "LeftElbow", "LeftWrist"});
  EXPECT_EQ(asf.convention, "cmu-asf");
  EXPECT_EQ(asf.hanim[6], "l_shoulder");  // ... and the shoulder joint here
  const BvhNaming mixamo =
      map_bvh_names({"mixamorig:Hips", "mixamorig:Spine", "mixamorig:Spine1", "mixamorig:Spine2",
                     "mixamorig:Neck", "mixamorig:Head", "mixamorig:HeadTop_End",
                     "mixamorig:RightArm", "mixamorig:RightUpLeg", "mixamorig:RightToe_End"});
  EXPECT_EQ(mixamo.convention, "mixamo");
  EXPECT_EQ(mixamo.hanim[7], "r_shoulder");
  EXPECT_EQ(mixamo.hanim[9], "r_toe_tip");
  const BvhNaming daz = map_bvh_names({"hip", "abdomen", "chest", "neck", "head", "lCollar",
                                       "lShldr", "lForeArm", "lHand", "rThigh", "rShin", "rFoot"});
  EXPECT_EQ(daz.convention, "daz");
  EXPECT_EQ(daz.hanim[6], "l_shoulder");
  EXPECT_EQ(daz.hanim[9], "r_hip");
  const BvhNaming hanim = map_bvh_names({"humanoid_root", "l_hip", "skullbase_End", "Tail"});
  EXPECT_EQ(hanim.convention, "h-anim");
  EXPECT_EQ(hanim.hanim[2], "skull_tip");
  EXPECT_EQ(hanim.hanim[3], "");  // not mapped, and not by its position in the list
  EXPECT_FALSE(hanim.intermediate[3]);
  EXPECT_EQ(bvh_naming_conventions().size(), 7u);
}

}  // namespace
}  // namespace simcap
