// Table 10's benchmark: the joint selection, the normalising height, the error definitions
// (checked on solvers whose errors are known), hinge identification and the ik-eval command.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>

#include "models/bvh.h"
#include "tests/support/key_values.h"
#include "tests/support/temp_dir.h"
#include "tracker/unzueta/ik_eval.h"

namespace simcap {
namespace {

const std::string kWalk = SIMCAP_MOCAP_DIR "/cmu_131_01_start_walk_stop.bvh";

// Replays a motion: solves frame i with the motion's pose i, turned about the vertical through
// the root by `yaw`.
class Replay final : public IkSolver {
 public:
  Replay(const SikBody& body, const Motion& motion, double yaw)
      : body_(body), motion_(motion), yaw_(yaw) {}
  std::string_view name() const override { return "replay"; }
  const SikBody& body() const override { return body_; }
  const Pose& solve(const SikTargets&) override {
    pose_ = motion_.frames[frame_++];
    pose_.rotations[0] = Eigen::AngleAxisd(yaw_, Eigen::Vector3d::UnitY()) * pose_.rotations[0];
    return pose_;
  }
  void reset() override { frame_ = 0; }

 private:
  const SikBody& body_;
  const Motion& motion_;
  double yaw_;
  size_t frame_ = 0;
  Pose pose_;
};

class IkEvalTest : public ::testing::Test {
 protected:
  IkClip clip = load_ik_clip(kWalk, false, 120);
};

TEST_F(IkEvalTest, ScoresTheThesisTwentyTwoJoints) {
  std::set<std::string> names;
  for (int j : table10_joints(clip.body)) names.insert(clip.body.skeleton()[j].name);
  const std::set<std::string> expected = {"humanoid_root",
                                          "LHipJoint",
                                          "l_hip",
                                          "l_knee",
                                          "l_talocrural",
                                          "r_hip",
                                          "r_knee",
                                          "r_talocrural",
                                          "vl5",
                                          "vl1",
                                          "vt6",
                                          "vc7",
                                          "vc4",
                                          "skullbase",
                                          "l_sternoclavicular",
                                          "l_shoulder",
                                          "l_elbow",
                                          "l_radiocarpal",
                                          "r_sternoclavicular",
                                          "r_shoulder",
                                          "r_elbow",
                                          "r_radiocarpal"};
  EXPECT_EQ(names, expected);
}

TEST_F(IkEvalTest, HeightIsCalfThighPelvisTorsoAndNeck) {
  // From the file's own offsets: calf and thigh bones, the hips' drop below the root, the
  // lowerback-to-lowerneck and lowerneck-to-head chains.
  const BvhClip bvh = read_bvh(kWalk);
  auto offset = [&](const char* name) { return bvh.joints[bvh.find(name)].offset; };
  const double legs = 0.5 * (offset("LeftKnee").norm() + offset("LeftAnkle").norm() +
                             offset("RightKnee").norm() + offset("RightAnkle").norm());
  const double pelvis = -0.5 * (offset("LeftHip").y() + offset("RightHip").y());
  const double torso =
      (offset("lowerback") + offset("Chest") + offset("Chest2") + offset("lowerneck")).norm();
  const double neck = (offset("Neck") + offset("Head")).norm();
  EXPECT_NEAR(table10_height(clip.body), legs + pelvis + torso + neck, 1e-9);
}

TEST_F(IkEvalTest, ErrorsFollowTheThesisDefinitions) {
  const std::vector<int> joints = table10_joints(clip.body);
  const double height = table10_height(clip.body);
  Replay exact(clip.body, clip.motion, 0.0);
  const IkEvalResult zero = evaluate_ik(exact, clip.motion, joints, height);
  EXPECT_EQ(zero.position_error, 0.0);
  EXPECT_EQ(zero.orientation_error, 0.0);
  ASSERT_EQ(zero.frame_ms.size(), clip.motion.frames.size());

  // The whole body turned by 0.2 rad about the root: only the root's orientation is off, by 0.2;
  // every joint moves by the chord of its distance from the vertical through the root.
  const double yaw = 0.2;
  Replay turned(clip.body, clip.motion, yaw);
  const IkEvalResult r = evaluate_ik(turned, clip.motion, joints, height);
  const double n = static_cast<double>(joints.size());
  EXPECT_NEAR(r.orientation_error, yaw / n, 1e-12);
  double sum_squares = 0.0;
  std::vector<Eigen::Quaterniond> rot;
  std::vector<Eigen::Vector3d> pos;
  for (const Pose& pose : clip.motion.frames) {
    clip.body.forward(pose, rot, pos);
    double sum = 0.0;
    for (int j : joints) {
      Eigen::Vector3d d = pos[j] - pos[0];
      d.y() = 0.0;
      sum += 2.0 * std::sin(yaw / 2) * d.norm();
    }
    sum_squares += std::pow(sum / (height * n), 2);
  }
  EXPECT_NEAR(r.position_error, std::sqrt(sum_squares / clip.motion.frames.size()), 1e-12);
}

TEST_F(IkEvalTest, IdentifiedHingesMakeTheClipsElbowsAndKneesPureHinges) {
  const SikHingeAxes axes = hinge_axes_from_motion(clip.body, clip.motion);
  const SikBody body(clip.body.skeleton(), axes);
  for (int side : {kLeft, kRight}) {
    for (const SikLimb* limb : {&body.arm(side), &body.leg(side)}) {
      for (const Pose& pose : clip.motion.frames) {
        const Eigen::AngleAxisd turn(pose.rotations[limb->b]);
        if (turn.angle() < 0.2) continue;
        EXPECT_NEAR(std::abs(turn.axis().dot(limb->hinge_axis)), 1.0, 1e-6);
      }
    }
  }
  // CMU's elbow turns about an axis 30 degrees off the mediolateral one.
  EXPECT_NEAR(std::abs(body.arm(kLeft).hinge_axis.x()), std::cos(std::numbers::pi / 6), 1e-3);
}

TEST(IkEvalCommand, WritesTheTablesAndTheSummaryLine) {
  testing::TempDir tmp;
  std::string out;
  const std::string dir = (tmp / "sik").string();
  ASSERT_EQ(testing::run_simcap("ik-eval " + kWalk + " --method sik --frames 90 -o " + dir, &out),
            0)
      << out;
  const auto fields = testing::key_values(testing::last_line(out));
  ASSERT_EQ(fields.size(), 3u) << out;
  for (const char* key : {"pos_err", "orient_err", "ms_per_frame"})
    ASSERT_TRUE(fields.contains(key)) << key << " missing from: " << out;
  std::ifstream json(dir + "/summary.json");
  const nlohmann::json summary = nlohmann::json::parse(json);
  EXPECT_NEAR(summary["position_error"].get<double>(), std::stod(fields.at("pos_err")), 1e-4);
  EXPECT_EQ(summary["frames"].get<int>(), 90);
  EXPECT_EQ(summary["joints"].size(), 22u);
  std::ifstream frames(dir + "/frame_errors.csv");
  int lines = 0;
  for (std::string line; std::getline(frames, line);) ++lines;
  EXPECT_EQ(lines, 91);
  EXPECT_TRUE(std::filesystem::exists(dir + "/joint_errors.csv"));
}

TEST(IkEvalCommand, AllPutsEverySolverBesideTheThesisColumns) {
  testing::TempDir tmp;
  std::string out;
  const std::string dir = (tmp / "all").string();
  ASSERT_EQ(testing::run_simcap("ik-eval " + kWalk + " --method all --frames 30 -o " + dir, &out),
            0)
      << out;
  const auto fields = testing::key_values(testing::last_line(out));
  ASSERT_TRUE(fields.contains("solvers")) << out;
  EXPECT_EQ(fields.at("solvers"), std::to_string(ik_solver_names().size()));
  std::ifstream table(dir + "/table10.csv");
  std::string line;
  std::getline(table, line);
  EXPECT_EQ(line.rfind("method,position_error,orientation_error,ms_per_frame", 0), 0u) << line;
  std::vector<std::string> methods;
  while (std::getline(table, line)) methods.push_back(line.substr(0, line.find(',')));
  EXPECT_EQ(methods, (std::vector<std::string>{"kma", "ccd", "pinv", "dls", "dls-svd", "sdls",
                                               "pik", "sik", "tgbsik"}));
  for (const std::string& m : methods) {
    std::ifstream json(dir + "/" + m + "/summary.json");
    ASSERT_TRUE(json) << m;
    const nlohmann::json summary = nlohmann::json::parse(json);
    EXPECT_EQ(summary["method"], m);
    EXPECT_EQ(summary["frames"].get<int>(), 30);
    EXPECT_GT(summary["position_error"].get<double>(), 0.0) << m;
  }
}

TEST(IkEvalCommand, RejectsABadClipWithoutWritingOutput) {
  testing::TempDir tmp;
  {
    std::ofstream bad(tmp / "bad.bvh");
    bad << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n}\n";
  }
  std::string out;
  EXPECT_EQ(testing::run_simcap(
                "ik-eval " + (tmp / "bad.bvh").string() + " -o " + (tmp / "out").string(), &out),
            1);
  EXPECT_NE(out.find("bad.bvh"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(tmp / "out" / "summary.json"));
  EXPECT_NE(
      testing::run_simcap("ik-eval " + kWalk + " --method jacobian -o " + (tmp / "out").string()),
      0);
}

TEST(IkBench, TimesTheThreeSolvers) {
  std::string out;
  ASSERT_EQ(testing::run_simcap("bench ik --repeat 1", &out), 0) << out;
  const std::string last = testing::last_line(out);
  EXPECT_EQ(last.rfind("ms_per_frame ", 0), 0u) << out;
  const auto fields = testing::key_values(last);
  for (const char* key : {"sik", "ccd", "dls"}) {
    ASSERT_TRUE(fields.contains(key)) << key << " missing from: " << out;
    EXPECT_GT(std::stod(fields.at(key)), 0.0) << out;
  }
}

}  // namespace
}  // namespace simcap
