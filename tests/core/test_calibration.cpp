// Calibration files: written by simcap, read back by cv::FileStorage (an independent reader) and
// by simcap; bad files are rejected with the file, camera and field named.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <fstream>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/core/persistence.hpp>

#include "core/atomic_file.h"
#include "core/calibration.h"
#include "core/rig.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::error_of;
using simcap::testing::TempDir;

std::vector<Camera> sample_rig() {
  auto cams = ring_rig(3, {0, 1, 0}, 3.0, 2.0, ImageSpec{800, 600, 1.2});
  cams[1].dist << -0.2, 0.05, 0.001, -0.002, 0.01;
  return cams;
}

Eigen::MatrixXd read_mat(const cv::FileNode& n) {
  cv::Mat m;
  n >> m;
  Eigen::MatrixXd out;
  cv::cv2eigen(m, out);
  return out;
}

TEST(Calibration, OpenCVYamlIsReadableByFileStorage) {
  TempDir dir;
  const auto cams = sample_rig();
  const auto path = dir / "opencv.yaml";
  write_opencv_calibration(path, cams);
  cv::FileStorage fs(path.string(), cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened());
  std::vector<std::string> names;
  fs["camera_names"] >> names;
  ASSERT_EQ(names, (std::vector<std::string>{"cam00", "cam01", "cam02"}));
  for (const auto& c : cams) {
    const cv::FileNode n = fs[c.name];
    EXPECT_EQ(static_cast<int>(n["image_width"]), 800);
    EXPECT_EQ(static_cast<int>(n["image_height"]), 600);
    EXPECT_TRUE(read_mat(n["K"]).isApprox(c.K, 1e-12));
    EXPECT_TRUE(read_mat(n["R"]).isApprox(c.R, 1e-12));
    EXPECT_TRUE(read_mat(n["t"]).isApprox(c.t, 1e-12));
    EXPECT_TRUE(read_mat(n["dist"]).transpose().isApprox(c.dist, 1e-12) || c.dist.isZero());
    cv::Mat rvec, R;
    n["rvec"] >> rvec;
    cv::Rodrigues(rvec, R);
    Eigen::Matrix3d Re;
    cv::cv2eigen(R, Re);
    EXPECT_TRUE(Re.isApprox(c.R, 1e-9));
  }
}

TEST(Calibration, OpenCVYamlRoundTrips) {
  TempDir dir;
  const auto cams = sample_rig();
  write_opencv_calibration(dir / "opencv.yaml", cams);
  const auto back = read_opencv_calibration(dir / "opencv.yaml");
  ASSERT_EQ(back.size(), cams.size());
  for (size_t i = 0; i < cams.size(); ++i) {
    EXPECT_EQ(back[i].name, cams[i].name);
    EXPECT_EQ(back[i].width, 800);
    EXPECT_TRUE(back[i].K.isApprox(cams[i].K, 1e-12));
    EXPECT_TRUE((back[i].dist - cams[i].dist).norm() < 1e-12);
    EXPECT_TRUE(back[i].R.isApprox(cams[i].R, 1e-12));
    EXPECT_TRUE((back[i].t - cams[i].t).norm() < 1e-12);
  }
  EXPECT_EQ(&find_camera(back, "cam02", "x"), &back[2]);
  EXPECT_NE(
      error_of([&] { find_camera(back, "cam09", "calib.yaml"); }).find("unknown camera 'cam09'"),
      std::string::npos);
}

TEST(Calibration, EasyMocapPairIsReadableByFileStorage) {
  TempDir dir;
  const auto cams = sample_rig();
  write_easymocap_calibration(dir / "intri.yml", dir / "extri.yml", cams);
  cv::FileStorage intri((dir / "intri.yml").string(), cv::FileStorage::READ);
  cv::FileStorage extri((dir / "extri.yml").string(), cv::FileStorage::READ);
  std::vector<std::string> names;
  intri["names"] >> names;
  EXPECT_EQ(names.size(), 3u);
  for (const auto& c : cams) {
    EXPECT_TRUE(read_mat(intri["K_" + c.name]).isApprox(c.K, 1e-12));
    EXPECT_TRUE(read_mat(extri["Rot_" + c.name]).isApprox(c.R, 1e-12));
    const Eigen::MatrixXd T = read_mat(extri["T_" + c.name]);
    ASSERT_EQ(T.rows(), 3);
    EXPECT_TRUE((T - c.t).norm() < 1e-12);
    const Eigen::MatrixXd r = read_mat(extri["R_" + c.name]);
    ASSERT_EQ(r.rows(), 3);
    ASSERT_EQ(r.cols(), 1);
  }
  const auto back = read_easymocap_calibration(dir / "intri.yml", dir / "extri.yml");
  ASSERT_EQ(back.size(), 3u);
  EXPECT_TRUE(back[1].R.isApprox(cams[1].R, 1e-12));
  EXPECT_TRUE((back[1].dist - cams[1].dist).norm() < 1e-12);
}

// Writes a valid file, then applies `edit` to its text, and returns the error reading it gives.
std::string error_after_edit(const std::function<std::string(std::string)>& edit) {
  TempDir dir;
  write_opencv_calibration(dir / "opencv.yaml", sample_rig());
  write_text_atomic(dir / "opencv.yaml", edit(read_text(dir / "opencv.yaml")));
  return error_of([&] { read_opencv_calibration(dir / "opencv.yaml"); });
}

std::string replace_first(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

TEST(Calibration, MissingKeyNamesFileCameraAndField) {
  const auto msg = error_after_edit(
      [](std::string s) { return replace_first(s, "   image_height: 600\n", ""); });
  EXPECT_NE(msg.find("opencv.yaml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("camera 'cam00'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("field 'image_height'"), std::string::npos) << msg;
}

TEST(Calibration, WrongMatrixShapeIsRejected) {
  const auto msg2 = error_after_edit([](std::string s) {
    const auto k = s.find("K: !!opencv-matrix");
    return s.replace(s.find("rows: 3", k), 7, "rows: 1")
        .replace(s.find("cols: 3", k), 7, "cols: 9");
  });
  EXPECT_NE(msg2.find("field 'K': expected a 3x3 matrix, got 1x9"), std::string::npos) << msg2;
}

TEST(Calibration, NonRotationIsRejected) {
  TempDir dir;
  auto cams = sample_rig();
  cams[2].R(0, 0) *= 1.5;
  write_opencv_calibration(dir / "opencv.yaml", cams);
  const auto msg = error_of([&] { read_opencv_calibration(dir / "opencv.yaml"); });
  EXPECT_NE(msg.find("camera 'cam02': field 'R': not a rotation"), std::string::npos) << msg;
}

TEST(Calibration, ListedCameraWithoutEntryIsRejected) {
  const auto msg = error_after_edit(
      [](std::string s) { return replace_first(s, "   - cam02\n", "   - cam02\n   - cam07\n"); });
  EXPECT_NE(msg.find("camera 'cam07'"), std::string::npos) << msg;
}

TEST(Calibration, MissingAndGarbledFilesAreErrors) {
  TempDir dir;
  EXPECT_NE(error_of([&] { read_opencv_calibration(dir / "nope.yaml"); }).find("not found"),
            std::string::npos);
  write_text_atomic(dir / "bad.yaml", "%YAML:1.0\n---\ncamera_names: [ \"a\"\n  : : :\n");
  const auto msg = error_of([&] { read_opencv_calibration(dir / "bad.yaml"); });
  EXPECT_NE(msg.find("bad.yaml:4: not valid YAML"), std::string::npos) << msg;
  // yaml-cpp 0.7 reads this as endless empty documents (YAML::LoadAll never returns).
  write_text_atomic(dir / "comma.yaml", "%YAML:1.0\n---\n,\n");
  const auto comma = error_of([&] { read_opencv_calibration(dir / "comma.yaml"); });
  EXPECT_NE(comma.find("comma.yaml"), std::string::npos) << comma;
  // A plain scalar to yaml-cpp, a document start to OpenCV, whose reader loops on this file.
  write_text_atomic(dir / "dashes.yaml", "%YAML:1.0\n---a: 0\n----x\n");
  const auto dashes = error_of([&] { read_opencv_calibration(dir / "dashes.yaml"); });
  EXPECT_NE(dashes.find("dashes.yaml:2: '---' (a document start) needs a blank"), std::string::npos)
      << dashes;
  // The same for a document end: OpenCV's reader loops on this one too.
  write_text_atomic(dir / "dots.yaml", "%YAML:1.0\n---\na: 1\n...-\n");
  const auto dots = error_of([&] { read_opencv_calibration(dir / "dots.yaml"); });
  EXPECT_NE(dots.find("dots.yaml:4: '...' (a document end) needs a blank"), std::string::npos)
      << dots;
  // A NUL in the header line: OpenCV's reader loops on the rest of this file.
  const char nul_text[] = "%YAML:1.\0\n:\n   -x\nc\n";
  write_text_atomic(dir / "nul.yaml", std::string(nul_text, sizeof nul_text - 1));
  const auto nul = error_of([&] { read_opencv_calibration(dir / "nul.yaml"); });
  EXPECT_NE(nul.find("nul.yaml:1: a control character (byte 0x00)"), std::string::npos) << nul;
  // A ']' that closes nothing continues the plain scalar above it; OpenCV's reader loops on it.
  write_text_atomic(dir / "bracket.yaml", "%YAML:1.0\n   -$3\n]\n");
  const auto bracket = error_of([&] { read_opencv_calibration(dir / "bracket.yaml"); });
  EXPECT_NE(bracket.find("bracket.yaml:3: this line continues a value"), std::string::npos)
      << bracket;
}

TEST(Calibration, EasyMocapMissingFieldNamesTheFile) {
  TempDir dir;
  write_easymocap_calibration(dir / "intri.yml", dir / "extri.yml", sample_rig());
  std::string extri = read_text(dir / "extri.yml");
  extri = replace_first(extri, "T_cam01:", "X_cam01:");
  write_text_atomic(dir / "extri.yml", extri);
  const auto msg =
      error_of([&] { read_easymocap_calibration(dir / "intri.yml", dir / "extri.yml"); });
  EXPECT_NE(msg.find("extri.yml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("field 'T_cam01'"), std::string::npos) << msg;

  // An extrinsics file whose top is a list, not the map of fields (OpenCV asserted on it).
  write_text_atomic(dir / "extri.yml", "%YAML:1.0\n---\n- 1\n- 2\n");
  const auto list =
      error_of([&] { read_easymocap_calibration(dir / "intri.yml", dir / "extri.yml"); });
  EXPECT_NE(list.find("extri.yml: expected a map of fields at the top (Rot_cam00, T_cam00, ...)"),
            std::string::npos)
      << list;
}

}  // namespace
}  // namespace simcap
