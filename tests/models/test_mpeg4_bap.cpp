// MPEG-4 BAP files: the ids of Gomez Jauregui's Table 2-2, a write/read round trip to the file's
// resolution, and bad files refused with their line.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "models/mpeg4_bap.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

TEST(Mpeg4Bap, IdsOfTheThesisTable) {
  // Gomez Jauregui 2011, Table 2-2.
  const std::pair<const char*, int> table[] = {
      {"vl5_torsion", 121},       {"vl5_roll", 120},           {"vl5_tilt", 122},
      {"skullbase_roll", 48},     {"skullbase_torsion", 49},   {"skullbase_tilt", 50},
      {"l_shoulder_flexion", 32}, {"l_shoulder_twisting", 36}, {"l_shoulder_abduct", 34},
      {"r_shoulder_flexion", 33}, {"r_shoulder_twisting", 37}, {"r_shoulder_abduct", 35},
      {"l_elbow_flexion", 38},    {"r_elbow_flexion", 39},     {"l_wrist_flexion", 42},
      {"l_wrist_twisting", 46},   {"l_wrist_pivot", 44},       {"r_wrist_flexion", 43},
      {"r_wrist_twisting", 47},   {"r_wrist_pivot", 45}};
  for (const auto& [name, id] : table) {
    EXPECT_EQ(bap_id(name), id) << name;
    EXPECT_EQ(bap_name(id), name);
  }
  EXPECT_EQ(bap_name(1), "sacroiliac_tilt");
  EXPECT_EQ(bap_name(181), "HumanoidRoot_tr_vertical");
  EXPECT_EQ(bap_name(186), "HumanoidRoot_rt_body_tilt");
  EXPECT_EQ(bap_id("no_such_bap"), 0);
  EXPECT_THROW(bap_name(0), Error);
  EXPECT_THROW(bap_name(187), Error);
  EXPECT_TRUE(bap_is_translation(182));
  EXPECT_FALSE(bap_is_translation(184));
}

TEST(Mpeg4Bap, RoundTripKeepsValuesToTheFileResolution) {
  BapFile file;
  file.name = "gestures";
  file.fps = 25;
  for (int k = 0; k < 3; ++k) {
    BapFrame f;
    f.number = 10 + k;
    f.set(32, -0.7 + 0.1234567 * k);
    f.set(39, -1.2);
    f.set(121, 3.0 * k - 3.0);
    f.set(181, 0.9876543);
    f.set(183, -1.5 + k);
    file.frames.push_back(f);
  }
  testing::TempDir dir;
  write_bap(dir / "a.bap", file);
  const BapFile back = read_bap(dir / "a.bap");
  EXPECT_EQ(back.name, "gestures");
  EXPECT_EQ(back.fps, 25);
  ASSERT_EQ(back.frames.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(back.frames[k].number, file.frames[k].number);
    EXPECT_EQ(back.frames[k].mask, file.frames[k].mask);
    for (int id = 1; id <= kBapCount; ++id) {
      const double tol = bap_is_translation(id) ? 0.5e-3 : 0.5e-5;
      EXPECT_NEAR(back.frames[k].values[id - 1], file.frames[k].values[id - 1], tol)
          << bap_name(id);
    }
  }
  // Writing what was read gives the same bytes.
  EXPECT_EQ(format_bap(back), format_bap(file));
}

TEST(Mpeg4Bap, BadFilesNameTheLine) {
  const std::string mask_line = [] {
    std::string s;
    for (int i = 0; i < kBapCount; ++i) s += i == 3 ? " 1" : (i ? " 0" : "0");
    return s;
  }();
  EXPECT_NE(testing::error_of([] { parse_bap("2.0 x 25 0\n", "f.bap"); }).find("f.bap:1"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] {
              parse_bap("3.1 x 25 1\n" + mask_line + "\n7\n", "f.bap");
            }).find("l_hip_flexion"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] {
              parse_bap("3.1 x 25 1\n# note\n" + mask_line + "\n7 1.5\n", "f.bap");
            }).find("f.bap:4"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] {
              parse_bap("3.1 x 25 1\n" + mask_line + "\n7 15\n8\n", "f.bap");
            }).find("end of the file"),
            std::string::npos);
  EXPECT_NO_THROW(parse_bap("3.1 x 25 1\n# note\n" + mask_line + "\n7 15\n", "f.bap"));
  // Any whitespace separates, and a frame with a missing value is an error, not a 0.
  EXPECT_EQ(parse_bap("3.1\fx\v25 1\n" + mask_line + "\n7\f15\n", "f.bap").frames[0].number, 7);
  EXPECT_NE(testing::error_of([&] {
              parse_bap("3.1 x 25 1\n" + mask_line + "\n7 \f\n", "f.bap");
            }).find("l_hip_flexion"),
            std::string::npos);
  BapFile spaced;
  spaced.name = "two words";
  EXPECT_THROW(format_bap(spaced), Error);
}

}  // namespace
}  // namespace simcap
