// The upright start of --init auto (upright_start.h).
#include "tracker/gomez/upright_start.h"

#include <cmath>

#include "core/error.h"
#include "models/humanoid.h"
#include "tracker/common/mask_box.h"
#include "tracker/gomez/body.h"
#include "tracker/gomez/pose_scorer.h"

namespace simcap::tracker::gomez {
namespace {

// Mean column of the silhouette's pixels in row `v`.
double row_centre(const cv::Mat& silhouette, int v) {
  double sum = 0;
  int n = 0;
  const std::uint8_t* row = silhouette.ptr<std::uint8_t>(v);
  for (int u = 0; u < silhouette.cols; ++u) {
    if (row[u]) {
      sum += u;
      ++n;
    }
  }
  return n ? sum / n : 0.5 * silhouette.cols;
}

}  // namespace

UprightStart upright_start(const Camera& camera, const cv::Mat& silhouette) {
  const cv::Rect box = mask_box(silhouette);
  if (box.empty()) throw Error("--init auto: the first frame's silhouette is empty");
  const int bottom = box.y + box.height - 1, top = box.y;
  // The feet stand where the lowest row's sight line meets the floor (its lower pixel edge: the
  // soles touch the floor there).
  const Eigen::Vector3d o = camera.centre();
  const Eigen::Vector3d down = camera.unproject({row_centre(silhouette, bottom), bottom + 0.5});
  if (!(down.y() < -1e-6) || !(o.y() > 0)) {
    throw Error("--init auto: the silhouette's lowest row does not look down onto the floor");
  }
  const Eigen::Vector3d feet = o + (-o.y() / down.y()) * down;
  // The head top: where the top row's sight line passes closest to the vertical through the feet.
  const Eigen::Vector3d up = camera.unproject({row_centre(silhouette, top), top - 0.5});
  const Eigen::Vector3d vertical = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d w0 = o - feet;
  const double b = up.dot(vertical), d = up.dot(w0), e = vertical.dot(w0);
  const double denom = 1 - b * b;
  if (denom < 1e-9) throw Error("--init auto: the camera looks straight down on the person");
  const double height = std::clamp((e - b * d) / denom, 1.0, 2.3);

  UprightStart start;
  start.height = height;
  start.skeleton = build_humanoid({height, {}});
  start.pose = Pose::neutral(start.skeleton);
  const Eigen::Vector3d to_camera = o - feet;
  const double heading = std::atan2(to_camera.x(), to_camera.z());
  const int root = start.skeleton.require("humanoid_root");
  start.pose.root_position = {feet.x(), start.skeleton[root].center.y(), feet.z()};
  start.pose.rotations[root] = Eigen::Quaterniond(Eigen::AngleAxisd(heading, vertical));
  return start;
}

Pose fit_silhouette(const UprightStart& start, const Camera& camera, const cv::Mat& silhouette,
                    const CueOptions& cue_options, const RegistrationOptions& options) {
  const Body body(start.skeleton, BodyKind::full, start.pose);
  const ColourClasses one = ColourClasses::uniform(body.shape.cell_count());
  const cv::Mat image(silhouette.size(), CV_8UC3, cv::Scalar::all(128));
  const FrameCues cues = make_cues(camera, image, silhouette, one, {}, cue_options);
  ScoreOptions score;
  score.combine = RegionCombine::pixels;
  const PoseScorer scorer(body.dofs, body.shape, one.cell_class(), score);
  State x = body.dofs.state_of(start.pose, State::Zero(body.dofs.size()));
  x = register_pose(scorer, cues, x, options, true).x;
  return body.dofs.pose(x);
}

}  // namespace simcap::tracker::gomez
