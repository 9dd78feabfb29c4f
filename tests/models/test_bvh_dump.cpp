// Acceptance: `simcap motion dump` of the CMU walk agrees with forward kinematics written
// independently here (its own reading of the text, 4x4 matrices from explicit sines and
// cosines) to 1e-6 m on every joint and frame.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

struct RefJoint {
  std::string name;
  int parent;
  Eigen::Vector3d offset;
  std::vector<std::string> channels;
};

// Recursive reading of one JOINT/ROOT body from a whitespace token stream.
void read_joint(std::istream& in, std::vector<RefJoint>& joints, int parent, std::string name) {
  const int self = static_cast<int>(joints.size());
  joints.push_back({name, parent, Eigen::Vector3d::Zero(), {}});
  std::string word;
  in >> word;  // "{"
  while (in >> word && word != "}") {
    if (word == "OFFSET") {
      in >> joints[self].offset.x() >> joints[self].offset.y() >> joints[self].offset.z();
    } else if (word == "CHANNELS") {
      int n;
      in >> n;
      joints[self].channels.resize(n);
      for (auto& c : joints[self].channels) in >> c;
    } else if (word == "JOINT") {
      in >> word;
      read_joint(in, joints, self, word);
    } else if (word == "End") {
      in >> word >> word >> word;  // "Site" "{" "OFFSET"
      Eigen::Vector3d o;
      in >> o.x() >> o.y() >> o.z() >> word;  // ... "}"
      joints.push_back({joints[self].name + "_End", self, o, {}});
    }
  }
}

Eigen::Matrix4d channel_matrix(const std::string& channel, double v) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  const int axis = channel[0] - 'X';
  if (channel.substr(1) == "position") {
    m(axis, 3) = v;
    return m;
  }
  const double r = v * std::numbers::pi / 180, c = std::cos(r), s = std::sin(r);
  if (axis == 0) {
    m.block<3, 3>(0, 0) << 1, 0, 0, 0, c, -s, 0, s, c;
  } else if (axis == 1) {
    m.block<3, 3>(0, 0) << c, 0, s, 0, 1, 0, -s, 0, c;
  } else {
    m.block<3, 3>(0, 0) << c, -s, 0, s, c, 0, 0, 0, 1;
  }
  return m;
}

TEST(BvhDump, CmuWalkMatchesIndependentForwardKinematics) {
  const std::string bvh = std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_01_start_walk_stop.bvh";
  testing::TempDir dir;
  const auto csv = dir / "joints.csv";
  std::string output;
  ASSERT_EQ(testing::run_simcap("motion dump '" + bvh + "' -o '" + csv.string() + "'", &output), 0)
      << output;

  std::ifstream in(bvh);
  std::vector<RefJoint> joints;
  std::string word;
  in >> word >> word >> word;  // HIERARCHY ROOT <name>
  read_joint(in, joints, -1, word);
  int frames;
  double frame_time;
  in >> word >> word >> frames >> word >> word >> frame_time;  // MOTION Frames: N Frame Time: t
  ASSERT_EQ(frames, 994);
  const double unit = 0.0254 / 0.45;  // CMU: 1/0.45 inch

  // The dump: frame,joint,x,y,z.
  std::ifstream table(csv);
  std::string line;
  std::getline(table, line);
  ASSERT_EQ(line, "frame,joint,x,y,z");
  std::map<std::pair<int, std::string>, Eigen::Vector3d> dumped;
  while (std::getline(table, line)) {
    std::stringstream row(line);
    std::string frame, joint, x, y, z;
    std::getline(row, frame, ',');
    std::getline(row, joint, ',');
    std::getline(row, x, ',');
    std::getline(row, y, ',');
    std::getline(row, z, ',');
    dumped[{std::stoi(frame), joint}] = {std::stod(x), std::stod(y), std::stod(z)};
  }
  ASSERT_EQ(dumped.size(), joints.size() * 994);

  double worst = 0;
  std::vector<Eigen::Matrix4d> world(joints.size());
  for (int f = 0; f < frames; ++f) {
    for (size_t j = 0; j < joints.size(); ++j) {
      Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
      local.block<3, 1>(0, 3) = joints[j].offset * unit;
      for (const auto& c : joints[j].channels) {
        double v;
        in >> v;
        local = local * channel_matrix(c, c.substr(1) == "position" ? v * unit : v);
      }
      world[j] = joints[j].parent < 0 ? local : Eigen::Matrix4d(world[joints[j].parent] * local);
      const auto it = dumped.find({f, joints[j].name});
      ASSERT_NE(it, dumped.end()) << joints[j].name << " frame " << f;
      worst = std::max(worst, (it->second - world[j].block<3, 1>(0, 3)).norm());
    }
  }
  ASSERT_TRUE(in) << "the reference reader ran out of values";
  EXPECT_LT(worst, 1e-6);
  EXPECT_TRUE(dumped.count({993, "LeftToe_End"}));
  EXPECT_TRUE(dumped.count({0, "LHipJoint"}));
}

}  // namespace
}  // namespace simcap
