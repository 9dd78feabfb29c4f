// `simcap track --method sik`'s back-end: sizes the humanoid from the truth, follows the truth's
// end-effectors, is reproducible for a seed, names what a bad dataset lacks, and (multiview)
// starts without a camera that does not see the person yet.
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tests/support/temp_dir.h"
#include "tracker/common/dataset.h"
#include "tracker/common/png_decoder.h"
#include "tracker/unzueta/ik_eval.h"
#include "tracker/unzueta/initial_regions.h"
#include "tracker/unzueta/sik_track_job.h"
#include "tracker/unzueta/unzueta_job.h"

namespace simcap {
namespace {

// gt/joints3d.csv of a humanoid of `height` walking for `seconds`, every non-site joint; with
// `shrug` each clavicle turned up by that many radians in every frame, with `curl` vl1 flexed
// forward by that many.
JointTrack write_truth(const std::filesystem::path& dataset, double height, double seconds,
                       double shrug = 0.0, double curl = 0.0) {
  BodyParameters body;
  body.height = height;
  const Skeleton skeleton = build_humanoid(body);
  ProceduralSpec walk;
  walk.duration_s = seconds;
  const Motion motion = generate_procedural(walk, skeleton, 60.0);
  JointTrack truth;
  std::vector<int> joints;
  for (int j = 0; j < skeleton.size(); ++j) {
    if (skeleton[j].is_site) continue;
    joints.push_back(j);
    truth.joints.push_back(skeleton[j].name);
  }
  for (size_t f = 0; f < motion.frames.size(); ++f) {
    Pose pose = motion.frames[f];
    for (const char* clavicle : {"l_sternoclavicular", "r_sternoclavicular"}) {
      const double up = clavicle[0] == 'l' ? shrug : -shrug;  // about +Z lifts the left
      pose.rotations[skeleton.require(clavicle)] =
          Eigen::Quaterniond(Eigen::AngleAxisd(up, Eigen::Vector3d::UnitZ())) *
          pose.rotations[skeleton.require(clavicle)];
    }
    Eigen::Quaterniond& vl1 = pose.rotations[skeleton.require("vl1")];
    vl1 = Eigen::Quaterniond(Eigen::AngleAxisd(curl, Eigen::Vector3d::UnitX())) * vl1;
    const auto p = joint_positions(skeleton, pose);
    std::vector<Eigen::Vector3d> row;
    for (int j : joints) row.push_back(p[j]);
    truth.add_frame(static_cast<int>(f), std::move(row));
  }
  write_joint_track(dataset / "gt" / "joints3d.csv", truth);
  return truth;
}

TEST(SikTrackJob, SizesTheHumanoidFromTheTruth) {
  testing::TempDir tmp;
  const JointTrack truth = write_truth(tmp.path(), 1.62, 0.5);
  const Skeleton sized = sik_humanoid_for_track(truth);
  const Skeleton fitted = sik_humanoid_with_truth_trunk(truth);
  BodyParameters body;
  body.height = 1.62;
  const Skeleton expected = build_humanoid(body);
  ASSERT_EQ(fitted.size(), expected.size());
  for (int j = 0; j < fitted.size(); ++j) {
    EXPECT_LT((sized[j].center - expected[j].center).norm(), 1e-6) << sized[j].name;
    // The walk's sway moves the medians of vc7 and the shoulders in the trunk by half a mm.
    EXPECT_LT((fitted[j].center - expected[j].center).norm(), 1e-3) << fitted[j].name;
  }
}

// A body whose clavicles are always turned up (as CMU clips retarget) has its shoulders where
// SIK's neutral clavicles never put them; the fit moves them there, the rest stays sized.
TEST(SikTrackJob, PlacesTheShouldersWhereTheTruthCarriesThem) {
  testing::TempDir tmp;
  const double shrug = 0.45;  // ~26 degrees
  const JointTrack truth = write_truth(tmp.path(), 1.75, 0.5, shrug);
  const Skeleton fitted = sik_humanoid_with_truth_trunk(truth);
  BodyParameters body;
  body.height = 1.75;
  const Skeleton plain = build_humanoid(body);
  Pose shrugged = Pose::neutral(plain);
  shrugged.rotations[plain.require("l_sternoclavicular")] =
      Eigen::AngleAxisd(shrug, Eigen::Vector3d::UnitZ());
  shrugged.rotations[plain.require("r_sternoclavicular")] =
      Eigen::AngleAxisd(-shrug, Eigen::Vector3d::UnitZ());
  const auto expected = joint_positions(plain, shrugged);
  for (const char* name : {"l_shoulder", "r_shoulder", "vc7", "l_knee"}) {
    const int j = plain.require(name);
    EXPECT_LT((fitted[j].center - expected[j]).norm(), 2e-3) << name;
  }
  EXPECT_GT(
      (plain[plain.require("l_shoulder")].center - expected[plain.require("l_shoulder")]).norm(),
      0.05);

  SikTrackOptions options;
  options.quiet = true;
  track_dataset_sik(tmp.path(), tmp / "track", options);
  const JointTrack track = read_joint_track(tmp / "track" / "joints3d.csv");
  double shoulder = 0.0;
  for (size_t f = 0; f < track.frames.size(); ++f) {
    for (const char* name : {"l_shoulder", "r_shoulder"}) {
      shoulder += std::abs(track.positions[f][track.joint_index(name)].y() -
                           truth.positions[f][truth.joint_index(name)].y());
    }
  }
  // Heights: the neutral clavicles would leave them ~7 cm low (where the heading SIK estimates
  // for the walk's turns moves them across).
  EXPECT_LT(shoulder / (2 * track.frames.size()), 0.03);
}

// vc7 in the trunk frame: origin humanoid_root, Y toward skullbase, X across the hips.
Eigen::Vector3d vc7_in_trunk(const std::vector<Eigen::Vector3d>& p, const Skeleton& skeleton) {
  const Eigen::Vector3d root = p[skeleton.require("humanoid_root")];
  const Eigen::Vector3d y = (p[skeleton.require("skullbase")] - root).normalized();
  Eigen::Vector3d x = p[skeleton.require("l_hip")] - p[skeleton.require("r_hip")];
  x = (x - x.dot(y) * y).normalized();
  const Eigen::Vector3d d = p[skeleton.require("vc7")] - root;
  return {d.dot(x), d.dot(y), d.dot(x.cross(y))};
}

// A thorax the motion always curls forward has vc7 ahead of SIK's neutral spine; the fit puts it
// where the truth carries it relative to the pelvis and head, and keeps skullbase.
TEST(SikTrackJob, CurlsTheSpineAsTheTruthCarriesIt) {
  testing::TempDir tmp;
  const double curl = 0.5;
  const JointTrack truth = write_truth(tmp.path(), 1.75, 0.5, 0.0, curl);
  const Skeleton fitted = sik_humanoid_with_truth_trunk(truth);
  BodyParameters body;
  body.height = 1.75;
  const Skeleton plain = build_humanoid(body);
  Pose curled = Pose::neutral(plain);
  curled.rotations[plain.require("vl1")] = Eigen::AngleAxisd(curl, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d expected = vc7_in_trunk(joint_positions(plain, curled), plain);
  std::vector<Eigen::Vector3d> centre;
  for (const Joint& j : fitted.joints()) centre.push_back(j.center);
  EXPECT_LT((vc7_in_trunk(centre, fitted) - expected).norm(), 2e-3);
  std::vector<Eigen::Vector3d> neutral;
  for (const Joint& j : plain.joints()) neutral.push_back(j.center);
  EXPECT_GT((vc7_in_trunk(neutral, plain) - expected).norm(), 0.015);
  const int skullbase = plain.require("skullbase");
  EXPECT_LT((fitted[skullbase].center - plain[skullbase].center).norm(), 1e-3);
}

TEST(SikTrackJob, FollowsTheEndEffectorsAndIsReproducible) {
  testing::TempDir tmp;
  const JointTrack truth = write_truth(tmp.path(), 1.75, 2.0);
  SikTrackOptions options;
  options.quiet = true;
  track_dataset_sik(tmp.path(), tmp / "clean", options);
  const JointTrack track = read_joint_track(tmp / "clean" / "joints3d.csv");
  ASSERT_EQ(track.frames, truth.frames);
  EXPECT_EQ(track.joints, he15_joints());
  double wrist = 0.0, all = 0.0;
  int n = 0;
  for (size_t f = 0; f < track.frames.size(); ++f) {
    for (size_t k = 0; k < track.joints.size(); ++k) {
      const double e =
          (track.positions[f][k] - truth.positions[f][truth.joint_index(track.joints[k])]).norm();
      all += e;
      if (track.joints[k] == "l_radiocarpal" || track.joints[k] == "r_radiocarpal") wrist += e;
    }
    ++n;
  }
  EXPECT_LT(wrist / (2 * n), 0.005);  // the wrists are targets
  EXPECT_LT(all / (15 * n), 0.05);    // the rest is SIK's reconstruction
  EXPECT_TRUE(std::filesystem::exists(tmp / "clean" / "diagnostics" / "sik_humanoid.csv"));

  options.noise_sigma_m = 0.02;
  track_dataset_sik(tmp.path(), tmp / "a", options);
  track_dataset_sik(tmp.path(), tmp / "b", options);
  options.seed = 2;
  track_dataset_sik(tmp.path(), tmp / "c", options);
  const std::string a = read_text(tmp / "a" / "joints3d.csv");
  EXPECT_EQ(a, read_text(tmp / "b" / "joints3d.csv"));
  EXPECT_NE(a, read_text(tmp / "c" / "joints3d.csv"));
  EXPECT_NE(a, read_text(tmp / "clean" / "joints3d.csv"));
}

// `track --method sik` solves with SIK's own defaults (those of ik-eval), and a walk forward
// gains from them: the travel cue turns the pelvis toward its path.
TEST(SikTrackJob, SolvesWithSiksDefaultsAndTheThesisOnRequest) {
  const SikTrackOptions defaults;
  const IkSolverSettings ik_eval;
  EXPECT_EQ(defaults.solver.spine_bend, ik_eval.spine_bend);
  EXPECT_EQ(defaults.solver.pelvis_weights.travel, ik_eval.pelvis_weights.travel);
  EXPECT_GT(defaults.solver.pelvis_weights.travel, 0.0);
  EXPECT_EQ(defaults.solver.spine_bend, SikSpineBend::lean);

  testing::TempDir tmp;
  const JointTrack truth = write_truth(tmp.path(), 1.75, 3.0);
  auto mean_error = [&](bool thesis) {
    SikTrackOptions options;
    options.quiet = true;
    if (thesis) {
      options.solver.pelvis_weights.travel = 0.0;
      options.solver.spine_bend = SikSpineBend::thesis;
    }
    const std::filesystem::path out = tmp / (thesis ? "thesis" : "defaults");
    track_dataset_sik(tmp.path(), out, options);
    const JointTrack track = read_joint_track(out / "joints3d.csv");
    double sum = 0.0;
    for (size_t f = 0; f < track.frames.size(); ++f) {
      for (size_t k = 0; k < track.joints.size(); ++k) {
        sum +=
            (track.positions[f][k] - truth.positions[f][truth.joint_index(track.joints[k])]).norm();
      }
    }
    return sum / (track.frames.size() * track.joints.size());
  };
  // 29.2 -> 14.4 mm: the limbs alone mistake the stride's swing for a turn of the pelvis.
  EXPECT_LT(mean_error(false), 0.7 * mean_error(true));
}

TEST(SikTrackJob, MiddleTargetsBringElbowsAndKneesToTheTruth) {
  testing::TempDir tmp;
  const JointTrack truth = write_truth(tmp.path(), 1.75, 1.0);
  auto middle_error = [&](bool middle_targets) {
    SikTrackOptions options;
    options.quiet = true;
    options.middle_targets = middle_targets;
    const std::filesystem::path out = tmp / (middle_targets ? "middle" : "ends");
    track_dataset_sik(tmp.path(), out, options);
    const JointTrack track = read_joint_track(out / "joints3d.csv");
    double sum = 0.0;
    int n = 0;
    for (size_t f = 0; f < track.frames.size(); ++f) {
      for (const char* joint : {"l_elbow", "r_elbow", "l_knee", "r_knee"}) {
        sum += (track.positions[f][track.joint_index(joint)] -
                truth.positions[f][truth.joint_index(joint)])
                   .norm();
        ++n;
      }
    }
    return sum / n;
  };
  // 5.4 -> 3.2 cm: the knees come to 1.5-2.3 cm; the elbows hang from SIK's own shoulders, which
  // the targets do not move (4.6 cm).
  EXPECT_LT(middle_error(true), 0.7 * middle_error(false));

  // Asked for, the middle joints are required.
  JointTrack no_elbow = truth;
  no_elbow.joints[truth.joint_index("l_elbow")] = "l_elbow_renamed";
  write_joint_track(tmp / "gt" / "joints3d.csv", no_elbow);
  SikTrackOptions options;
  options.middle_targets = true;
  options.quiet = true;
  try {
    track_dataset_sik(tmp.path(), tmp / "missing", options);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'l_elbow'"), std::string::npos) << e.what();
  }
  // Tracked effectors have no elbows or knees.
  options.effectors = EffectorSource::depth;
  EXPECT_THROW(track_sik(tmp.path(), tmp / "depth", options), Error);
  EXPECT_FALSE(std::filesystem::exists(tmp / "depth" / "joints3d.csv"));
}

TEST(SikTrackJob, NamesAMissingEndEffector) {
  testing::TempDir tmp;
  JointTrack truth;
  truth.joints = {"humanoid_root", "skullbase", "l_radiocarpal", "r_radiocarpal", "l_talocrural"};
  truth.add_frame(0, std::vector<Eigen::Vector3d>(5, Eigen::Vector3d::Zero()));
  write_joint_track(tmp / "gt" / "joints3d.csv", truth);
  try {
    track_dataset_sik(tmp.path(), tmp / "out", {});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("r_talocrural"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("joints3d.csv"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(tmp / "out" / "joints3d.csv"));
}

// Multiview starts in the cameras that see the person; fewer than two is refused, naming the
// frame, the cameras and what --init needed there.
TEST(SikTrackJob, MultiviewNeedsTwoCamerasThatSeeThePerson) {
  testing::TempDir dir;
  const std::string data = (dir / "tiny").string();
  std::string log;
  // 4x3 images: the person covers fewer labelled pixels than a part needs.
  ASSERT_EQ(
      testing::run_simcap(std::string("render ") + SIMCAP_SOURCE_DIR + "/scenes/studio4.yaml -o " +
                              data + " --frames 1 -q --set rig.resolution=[4,3]",
                          &log),
      0)
      << log;
  EXPECT_EQ(testing::run_simcap("track " + data + " -o " + (dir / "t").string() +
                                    " --method sik --effectors multiview -q",
                                &log),
            1);
  EXPECT_NE(log.find("frame 0: --effectors multiview needs the person in at least two cameras to "
                     "start, none could (cam00: CFOF: no body part could start in this camera; "
                     "cam01: "),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("(--init gt: the part labels show none of the parts there; is the person in "
                     "its view?)"),
            std::string::npos)
      << log;
  EXPECT_FALSE(std::filesystem::exists(dir / "t"));
}

// occluders: a pillar hides the person from cam01 on the first frame. Multiview starts in the
// other three cameras and brings cam01's parts in (reseed, borrowed colours) soon after they
// show; one camera alone (--effectors mono) that sees nobody is refused.
TEST(SikTrackJob, ACameraThatSeesNobodyAtTheStartJoinsLater) {
  testing::TempDir dir;
  const std::filesystem::path data = dir / "occluders";
  const int frames = 45;
  std::string log;
  ASSERT_EQ(testing::run_simcap(std::string("render ") + SIMCAP_SOURCE_DIR +
                                    "/scenes/occluders.yaml -o " + data.string() + " --frames " +
                                    std::to_string(frames) + " -q --set rig.resolution=[320,240]",
                                &log),
            0)
      << log;
  const tracker::Dataset ds(data);
  const int cam01 = 1;
  ASSERT_EQ(ds.cameras()[cam01].name, "cam01");
  // The first frame where cam01's part labels show a part, as the job's --init gt reads them.
  int shows = -1;
  for (int f = 0; f < frames && shows < 0; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "%06d.png", f);
    cv::Mat labels = tracker::decode_png(data / "cam01" / "parts" / name, cv::IMREAD_UNCHANGED);
    labels.setTo(0, ds.mask(cam01, f) == 0);
    const auto regions = tracker::labelled_part_regions(labels, data / "parts.json");
    for (const auto& roi : regions.roi) {
      if (roi) shows = f;
    }
  }
  ASSERT_GT(shows, 0) << "cam01 should see nobody on frame 0 and somebody later";

  SikTrackOptions options;
  options.effectors = EffectorSource::multiview;
  options.init = tracker::InitMethod::gt;
  options.quiet = true;
  int joined = -1, solved = 0;
  tracker::run_unzueta(data, options,
                       [&](const tracker::UnzuetaFrame& f, const std::vector<int>& cameras,
                           const std::vector<tracker::CameraTracker>& trackers) {
                         ++solved;
                         ASSERT_EQ(cameras[cam01], cam01);
                         for (tracker::Effector e : tracker::kEffectors) {
                           if (e == tracker::Effector::pelvis) continue;
                           const bool tracking =
                               trackers[cam01].state(e) == tracker::CfofState::tracking;
                           if (f.frame == 0) {
                             EXPECT_FALSE(tracking);
                           }
                           if (tracking && joined < 0) joined = f.frame;
                         }
                       });
  EXPECT_EQ(solved, frames);
  ASSERT_GE(joined, shows) << "cam01 tracked no part, or one before the person showed";
  // A part's first pixels, behind the pillar's edge, hold less of its colour than a restart
  // needs (restart_color_fraction): it joins a few frames later (shows 31, joins 34).
  EXPECT_LE(joined, shows + 10) << "the person shows in cam01 on frame " << shows;

  EXPECT_EQ(testing::run_simcap("track " + data.string() + " -o " + (dir / "mono").string() +
                                    " --method sik --effectors mono --camera 1 -q",
                                &log),
            1);
  EXPECT_NE(log.find("frame 0, cam01: CFOF: no body part could start in this camera"),
            std::string::npos)
      << log;
}

}  // namespace
}  // namespace simcap
