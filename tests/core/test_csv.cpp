// The joints table: round trip, and bad rows reported with file:line and column.
#include <gtest/gtest.h>

#include "core/atomic_file.h"
#include "core/joint_track.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::TempDir;

TEST(JointTrack, RoundTrips) {
  TempDir dir;
  JointTrack t;
  t.joints = {"humanoid_root", "l_knee"};
  t.add_frame(0, {{0.1, 0.9, 0.2}, {0.1, 0.5, 0.25}});
  t.add_frame(1, {{0.2, 0.9, 0.2}, {0.2, 0.5, 0.25}});
  write_joint_track(dir / "j.csv", t);
  const JointTrack back = read_joint_track(dir / "j.csv");
  EXPECT_EQ(back.joints, t.joints);
  EXPECT_EQ(back.frames, t.frames);
  EXPECT_TRUE(back.positions[1][1].isApprox(t.positions[1][1]));
  EXPECT_EQ(read_text(dir / "j.csv").substr(0, 18), "frame,joint,x,y,z\n");
}

std::string error_reading(const std::string& text) {
  TempDir dir;
  write_text_atomic(dir / "j.csv", text);
  return testing::error_of([&] { read_joint_track(dir / "j.csv"); });
}

TEST(JointTrack, BadInputNamesLineAndColumn) {
  EXPECT_NE(error_reading("frame,joint,x,y\n").find("j.csv:1: header"), std::string::npos);
  EXPECT_NE(error_reading("").find("empty"), std::string::npos);
  EXPECT_NE(
      error_reading("frame,joint,x,y,z\n0,a,1,2,3\n0,b,1,2\n").find("j.csv:3: expected 5 columns"),
      std::string::npos);
  EXPECT_NE(error_reading("frame,joint,x,y,z\r\n0,a,1,zz,3\r\n")
                .find("j.csv:2: column 'y': expected a number, got 'zz'"),
            std::string::npos);
  EXPECT_NE(
      error_reading("frame,joint,x,y,z\n0.5,a,1,2,3\n").find("column 'frame': expected an integer"),
      std::string::npos);
  EXPECT_NE(error_reading("frame,joint,x,y,z\n0,a,1,2,3\n0,a,1,2,3\n").find("repeated"),
            std::string::npos);
}

}  // namespace
}  // namespace simcap
