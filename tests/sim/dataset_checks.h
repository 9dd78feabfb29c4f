// Checks shared by the dataset tests: small renders of shipped scenes, the dataset's tables and
// calibration read back with OpenCV, and every cross-file consistency a dataset promises.
#pragma once

#include <filesystem>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace simcap::testing {

inline constexpr int kFrames = 4;
inline constexpr int kWidth = 320, kHeight = 240;
inline const char* const kKinds[] = {"rgb", "depth", "mask", "parts"};

std::string scene_path(const std::string& name);

// A small, fast render of a scene: kFrames frames at kWidth x kHeight; returns the exit status.
int render(const std::string& scene, const std::filesystem::path& out,
           const std::string& extra = "", std::string* output = nullptr);

struct CameraCalibration {
  cv::Mat K, dist, rvec, t, R;
  int width = 0, height = 0;
};

// An OpenCV calibration file (calibration/opencv.yaml, gt/calibration.yaml) read with OpenCV.
std::map<std::string, CameraCalibration> read_calibration(const std::filesystem::path& file);

struct Joint2d {
  int frame;
  std::string camera, joint;
  double u, v, depth;
  std::string visibility;
};
std::vector<Joint2d> read_joints2d(const std::filesystem::path& file);
// frame -> joint -> position
std::map<int, std::map<std::string, cv::Point3d>> read_joints3d(const std::filesystem::path& file);

std::filesystem::path image_file(const std::filesystem::path& dir, const std::string& cam,
                                 const std::string& kind, int frame);
std::map<std::string, int> count_visibility(const std::vector<Joint2d>& rows);

// Every cross-file consistency the dataset promises, with the true calibration (gt/ when the
// scene perturbed calibration/) and, when the cameras capture off the frame's nominal time, the
// joints where they were at each row's capture time (meta.json "capture"): 2D joints are the
// projection of the 3D joints to 1e-3 px, visible joints lie inside their actor's mask at the
// depth map's depth, masks are exactly where parts are.
void check_consistency(const std::filesystem::path& dir);

}  // namespace simcap::testing
