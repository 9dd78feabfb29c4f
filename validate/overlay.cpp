#include "validate/overlay.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "models/humanoid.h"

namespace simcap {

namespace {

// The HumanEva stick figure in H-Anim names (the thorax joint vc7 carries head and shoulders).
constexpr std::pair<const char*, const char*> kHe15Bones[] = {
    {"humanoid_root", "vc7"},     {"vc7", "skullbase"},         {"vc7", "l_shoulder"},
    {"vc7", "r_shoulder"},        {"l_shoulder", "l_elbow"},    {"r_shoulder", "r_elbow"},
    {"l_elbow", "l_radiocarpal"}, {"r_elbow", "r_radiocarpal"}, {"humanoid_root", "l_hip"},
    {"humanoid_root", "r_hip"},   {"l_hip", "l_knee"},          {"r_hip", "r_knee"},
    {"l_knee", "l_talocrural"},   {"r_knee", "r_talocrural"}};

const cv::Scalar kTruthColour(40, 200, 40);  // RGB order
const cv::Scalar kEstimateColour(230, 40, 40);

int index_of(const std::vector<std::string>& joints, const std::string& name) {
  const auto it = std::find(joints.begin(), joints.end(), name);
  return it == joints.end() ? -1 : static_cast<int>(it - joints.begin());
}

void draw_skeleton(cv::Mat& img, const Camera& camera, const Eigen::Matrix3Xd& points,
                   const std::vector<std::pair<int, int>>& bones, const cv::Scalar& colour,
                   int thickness) {
  std::vector<std::optional<cv::Point2d>> px;
  for (Eigen::Index j = 0; j < points.cols(); ++j) {
    const auto p = camera.project(points.col(j));
    px.push_back(p ? std::optional(cv::Point2d(p->x(), p->y())) : std::nullopt);
  }
  // Sub-pixel precision (4 fractional bits) keeps the lines where the projection puts them.
  constexpr int kShift = 4;
  const auto fixed = [](const cv::Point2d& p) {
    return cv::Point(cvRound(p.x * (1 << kShift)), cvRound(p.y * (1 << kShift)));
  };
  for (const auto& [a, b] : bones) {
    if (px[a] && px[b]) {
      cv::line(img, fixed(*px[a]), fixed(*px[b]), colour, thickness, cv::LINE_AA, kShift);
    }
  }
  for (const auto& p : px) {
    if (p)
      cv::circle(img, fixed(*p), (thickness + 1) << kShift, colour, cv::FILLED, cv::LINE_AA,
                 kShift);
  }
}

}  // namespace

std::vector<std::pair<int, int>> stick_figure_bones(const std::vector<std::string>& joints) {
  std::vector<std::pair<int, int>> bones;
  for (const auto& [a, b] : kHe15Bones) {
    const int ia = index_of(joints, a), ib = index_of(joints, b);
    if (ia >= 0 && ib >= 0) bones.emplace_back(ia, ib);
  }
  const auto& he15 = he15_joints();
  const Skeleton skeleton = build_humanoid();
  for (size_t j = 0; j < joints.size(); ++j) {
    if (std::find(he15.begin(), he15.end(), joints[j]) != he15.end()) continue;
    int s = skeleton.find(joints[j]);
    if (s < 0) continue;
    for (s = skeleton[s].parent; s >= 0; s = skeleton[s].parent) {
      const int parent = index_of(joints, skeleton[s].name);
      if (parent >= 0) {
        bones.emplace_back(parent, static_cast<int>(j));
        break;
      }
    }
  }
  return bones;
}

cv::Mat draw_overlay(const cv::Mat& rgb, const Camera& camera, const Eigen::Matrix3Xd& truth,
                     const Eigen::Matrix3Xd& estimate,
                     const std::vector<std::pair<int, int>>& bones, const std::string& caption) {
  cv::Mat img = rgb.clone();
  // The truth is drawn wider, under the track, so that it shows where the two coincide.
  const int thickness = std::max(1, img.cols / 320);
  draw_skeleton(img, camera, truth, bones, kTruthColour, 2 * thickness);
  draw_skeleton(img, camera, estimate, bones, kEstimateColour, thickness);
  const double scale = std::max(0.4, img.cols / 1280.0);
  const int baseline_y = static_cast<int>(22 * scale * 2);
  cv::rectangle(img, cv::Point(0, 0), cv::Point(img.cols, baseline_y + 8), cv::Scalar(0, 0, 0),
                cv::FILLED);
  cv::putText(img, caption, cv::Point(6, baseline_y), cv::FONT_HERSHEY_SIMPLEX, scale,
              cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  return img;
}

}  // namespace simcap
