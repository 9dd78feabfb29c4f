// `simcap track --export bvh,x3d,bap`: every family's track leaves as BVH, X3D H-Anim and MPEG-4
// BAP files that simcap's own readers (and so Blender's BVH importer and X3D browsers) take back.
#include <gtest/gtest.h>

#include "core/joint_track.h"
#include "models/bvh.h"
#include "models/mpeg4_bap.h"
#include "models/x3d_humanoid.h"
#include "tests/support/temp_dir.h"
#include "tests/tracker/capsule_dataset.h"

namespace simcap::tracker {
namespace {

namespace fs = std::filesystem;
using testing::run_simcap;
using testing::TempDir;

TEST(TrackExport, EveryFamilyWritesBvhAndX3dThatReadBack) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "d");
  for (const char* method : {"moschini", "sik"}) {
    SCOPED_TRACE(method);
    const fs::path out = dir / method;
    std::string log;
    ASSERT_EQ(run_simcap("track " + (dir / "d").string() + " -o " + out.string() + " --method " +
                             method + " --export bvh,x3d --quiet",
                         &log),
              0)
        << log;
    const JointTrack track = read_joint_track(out / "joints3d.csv");
    const BvhClip clip = read_bvh(out / "motion.bvh", {.metres_per_unit = 1.0});
    EXPECT_EQ(clip.frame_count(), track.frames.back() - track.frames.front() + 1);
    const Body body = read_x3d_humanoid(out / "motion.x3d");
    const Motion motion = read_x3d_motion(out / "motion.x3d", body.skeleton);
    EXPECT_EQ(static_cast<int>(motion.frames.size()), clip.frame_count());
    // The root follows the track's humanoid_root in both files.
    const int root = track.joint_index("humanoid_root");
    for (size_t f = 0; f < track.frames.size(); ++f) {
      const int k = track.frames[f] - track.frames.front();
      EXPECT_LT((bvh_joint_positions(clip, k)[0] - track.positions[f][root]).norm(), 1e-6);
      EXPECT_LT((motion.frames[k].root_position - track.positions[f][root]).norm(), 1e-6);
    }
  }
}

TEST(TrackExport, BapFramesCarryTheTracksRootAndEveryFrame) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "d", {.frames = 4});
  const fs::path out = dir / "t";
  std::string log;
  ASSERT_EQ(run_simcap("track " + (dir / "d").string() + " -o " + out.string() +
                           " --method sik --export bap --quiet",
                       &log),
            0)
      << log;
  const JointTrack track = read_joint_track(out / "joints3d.csv");
  const BapFile bap = read_bap(out / "motion.bap");
  ASSERT_EQ(static_cast<int>(bap.frames.size()), track.frames.back() - track.frames.front() + 1);
  const int root = track.joint_index("humanoid_root");
  for (size_t f = 0; f < track.frames.size(); ++f) {
    const BapFrame& b = bap.frames[track.frames[f] - track.frames.front()];
    EXPECT_EQ(b.number, track.frames[f]);
    const Eigen::Vector3d p(b.values[bap_id("HumanoidRoot_tr_lateral") - 1],
                            b.values[bap_id("HumanoidRoot_tr_vertical") - 1],
                            b.values[bap_id("HumanoidRoot_tr_frontal") - 1]);
    EXPECT_LT((p - track.positions[f][root]).norm(), 1e-3);  // the file holds millimetres
    for (const char* name : {"l_shoulder_flexion", "r_elbow_flexion", "l_knee_flexion"}) {
      EXPECT_TRUE(b.mask[bap_id(name) - 1]) << name;
    }
  }
}

TEST(TrackExport, UnknownFormatIsRefusedWithoutOutput) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "d", {.frames = 2});
  std::string log;
  EXPECT_NE(run_simcap("track " + (dir / "d").string() + " -o " + (dir / "t").string() +
                           " --export bvh,fbx",
                       &log),
            0);
  EXPECT_NE(log.find("fbx"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
}

}  // namespace
}  // namespace simcap::tracker
