#include "tracker/unzueta/initial_regions.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/error.h"

namespace simcap::tracker {
namespace {

// Part sizes as fractions of the person's height: the head is ~0.13 H tall, a hand ~0.11 H
// long, a foot ~0.15 H long but ~0.06 H high (Drillis & Contini); ROIs are a little larger.
constexpr double kHeadSide = 0.16, kHandSide = 0.12, kFootSide = 0.11;

cv::Rect2d square(cv::Point2d centre, double side) {
  return {centre.x - 0.5 * side, centre.y - 0.5 * side, side, side};
}

}  // namespace

InitialRegions calibration_posture_regions(const cv::Mat& mask) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask != 0, labels, stats, centroids, 8, CV_32S);
  int best = 0;
  for (int i = 1; i < n; ++i) {
    if (best == 0 || stats.at<int>(i, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA))
      best = i;
  }
  if (best == 0) throw Error("calibration posture: the silhouette is empty");
  const cv::Mat blob = labels == best;
  const cv::Rect box(stats.at<int>(best, cv::CC_STAT_LEFT), stats.at<int>(best, cv::CC_STAT_TOP),
                     stats.at<int>(best, cv::CC_STAT_WIDTH),
                     stats.at<int>(best, cv::CC_STAT_HEIGHT));
  InitialRegions r;
  r.person_px = box.height;
  const double h = box.height;

  std::vector<int> xs;
  for (int y = box.y; y < box.br().y; ++y) {
    const unsigned char* row = blob.ptr<unsigned char>(y);
    for (int x = box.x; x < box.br().x; ++x) {
      if (row[x]) xs.push_back(x);
    }
  }
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  const int median_x = xs[xs.size() / 2];
  const int gap = static_cast<int>(0.08 * h);  // half a head's width and a little more

  // Topmost (hands) or lowest (feet) silhouette pixel in the columns [x0, x1).
  auto extreme = [&](int x0, int x1, bool top) -> std::optional<cv::Point> {
    x0 = std::max(x0, box.x), x1 = std::min(x1, box.br().x);
    for (int k = 0; k < box.height; ++k) {
      const int y = top ? box.y + k : box.br().y - 1 - k;
      const unsigned char* row = blob.ptr<unsigned char>(y);
      for (int x = x0; x < x1; ++x) {
        if (row[x]) return cv::Point(x, y);
      }
    }
    return std::nullopt;
  };
  const auto image_left_hand = extreme(box.x, median_x - gap, true);
  const auto image_right_hand = extreme(median_x + gap + 1, box.br().x, true);
  const auto image_left_foot = extreme(box.x, median_x, false);
  const auto image_right_foot = extreme(median_x + 1, box.br().x, false);
  if (!image_left_hand || !image_right_hand || !image_left_foot || !image_right_foot ||
      image_left_hand->y > box.y + 0.4 * h || image_right_hand->y > box.y + 0.4 * h) {
    throw Error(
        "calibration posture not found in the first frame (expected the person facing the "
        "camera with both hands raised beside the head and the feet apart; --init gt starts "
        "from the dataset's part labels instead)");
  }
  const double hand = kHandSide * h, foot = kFootSide * h, head = kHeadSide * h;
  // Facing the camera, the person's right hand is on the image's left.
  r.roi[index_of(Effector::right_hand)] =
      square(cv::Point2d(image_left_hand->x, image_left_hand->y + 0.5 * hand), hand);
  r.roi[index_of(Effector::left_hand)] =
      square(cv::Point2d(image_right_hand->x, image_right_hand->y + 0.5 * hand), hand);
  r.roi[index_of(Effector::right_foot)] =
      square(cv::Point2d(image_left_foot->x, image_left_foot->y - 0.5 * foot), foot);
  r.roi[index_of(Effector::left_foot)] =
      square(cv::Point2d(image_right_foot->x, image_right_foot->y - 0.5 * foot), foot);
  const int head_x = (image_left_hand->x + image_right_hand->x) / 2;
  const auto crown = extreme(head_x, head_x + 1, true);
  const double top = crown ? crown->y : box.y;
  r.roi[index_of(Effector::head)] = square(cv::Point2d(head_x, top + 0.5 * head), head);
  return r;
}

InitialRegions labelled_part_regions(const cv::Mat& labels, const std::filesystem::path& parts_json,
                                     int min_pixels) {
  std::ifstream in(parts_json);
  if (!in) throw Error(parts_json.string() + ": cannot read the part-label legend");
  nlohmann::json legend;
  try {
    legend = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw Error(parts_json.string() + ": not JSON (" + e.what() + ")");
  }
  std::map<std::string, int> label_of;
  for (const auto& p : legend.value("parts", nlohmann::json::array())) {
    label_of[p.value("joint", "")] = p.value("label", -1);
  }
  auto label = [&](const std::string& joint) {
    const auto it = label_of.find(joint);
    if (it == label_of.end()) {
      throw_input_error(parts_json, 0, "parts", "has no part for joint '" + joint + "'");
    }
    return it->second;
  };
  cv::Mat l;
  labels.convertTo(l, CV_32S);
  InitialRegions r;
  const cv::Rect body = cv::boundingRect(l > 0);
  r.person_px = body.height;
  for (Effector e : kEffectors) {
    if (e == Effector::pelvis) continue;
    std::vector<int> wanted = {label(std::string(effector_joint(e)))};
    if (e == Effector::left_foot) wanted.push_back(label("l_metatarsophalangeal_2"));
    if (e == Effector::right_foot) wanted.push_back(label("r_metatarsophalangeal_2"));
    cv::Mat part = cv::Mat::zeros(l.size(), CV_8UC1);
    for (int w : wanted) part.setTo(255, l == w);
    if (cv::countNonZero(part) < min_pixels) continue;
    const cv::Rect box = cv::boundingRect(part);
    const cv::Point2d centre(box.x + 0.5 * (box.width - 1), box.y + 0.5 * (box.height - 1));
    const double least = (e == Effector::head                                     ? kHeadSide
                          : e == Effector::left_hand || e == Effector::right_hand ? kHandSide
                                                                                  : kFootSide) *
                         r.person_px;
    r.roi[index_of(e)] = square(centre, std::max({double(box.width), double(box.height), least}));
  }
  return r;
}

}  // namespace simcap::tracker
