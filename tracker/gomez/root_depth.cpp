// The root's distance from the silhouette's feet and top rows (root_depth.h).
#include "tracker/gomez/root_depth.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/pose.h"
#include "tracker/gomez/label_renderer.h"

namespace simcap::tracker::gomez {

std::optional<State> root_depth_proposal(const BodyDofs& dofs, const BodyShape& shape,
                                         const State& x, const FrameCues& cues,
                                         const RootDepthOptions& options) {
  const int tx = dofs.find("root_tx"), tz = dofs.find("root_tz");
  const bool feet = std::isfinite(cues.feet_row);
  // The feet row fixes the depth whatever the pose (the floor holds the feet); the top row only
  // with the body's height, which a crouch changes: it is used when the feet are cut off.
  bool top = !feet && std::isfinite(cues.top_row);
  if (tx < 0 || tz < 0 || (!feet && !top) || !cues.view.camera) return std::nullopt;
  const Camera& camera = *cues.view.camera;
  // The top row tells the depth only where it is the head's: a raised hand above the head would
  // pull the body wherever the hand the pose lost makes the silhouette's top. The head's own
  // capsules give the model's top; the silhouette's topmost working row must lie over them.
  BodyShape head;
  for (const Capsule& c : shape.capsules) {
    if (c.part == Part::head) head.capsules.push_back(c);
  }
  const View& view = cues.view;
  double top_u0 = INFINITY, top_u1 = -INFINITY;
  for (int v = 0; v < view.height && !(top_u0 <= top_u1); ++v) {
    for (int u = 0; u < view.width; ++u) {
      if (cues.cls_at(u, v) == 0) continue;
      top_u0 = std::min(top_u0, view.x0 + (u + 0.5) * view.factor - 0.5);
      top_u1 = std::max(top_u1, view.x0 + (u + 0.5) * view.factor - 0.5);
    }
  }
  const Pose pose = dofs.pose(x);
  const std::vector<Eigen::Isometry3d> g = forward_kinematics(dofs.skeleton(), pose);
  Eigen::Vector3d along = pose.root_position - camera.centre();
  along.y() = 0;
  if (along.norm() < 1e-6) return std::nullopt;
  along.normalize();
  const Eigen::AlignedBox2d head_box = body_extent(head, g, camera);
  top = top && !head_box.isEmpty() && top_u0 <= head_box.max().x() && top_u1 >= head_box.min().x();
  if (!feet && !top) return std::nullopt;

  // The rows' offsets of the body slid by `s` metres, working pixels.
  std::vector<Eigen::Isometry3d> moved(g.size());
  const auto offsets = [&](double s) {
    for (size_t j = 0; j < g.size(); ++j) moved[j] = Eigen::Translation3d(s * along) * g[j];
    const Eigen::AlignedBox2d box = body_extent(shape, moved, camera);
    const Eigen::AlignedBox2d crown = body_extent(head, moved, camera);
    if (box.isEmpty() || crown.isEmpty()) return Eigen::Vector2d(INFINITY, INFINITY);
    return Eigen::Vector2d(feet ? (box.max().y() - cues.feet_row) / view.factor : 0.0,
                           top ? (crown.min().y() - cues.top_row) / view.factor : 0.0);
  };
  const auto cost = [&](double s) { return offsets(s).squaredNorm(); };
  if (offsets(0).cwiseAbs().maxCoeff() <= options.least_px) return std::nullopt;

  // A scan every 5 cm (the cost need not be convex: a slide towards the camera may cut the feet
  // off the extent's reach), then one every 2.5 mm about its best point.
  const auto scan = [&](double from, double to, double step) {
    double best = 0, best_cost = cost(0);
    for (double s = from; s <= to + 1e-9; s += step) {
      const double c = cost(s);
      if (c < best_cost) best = s, best_cost = c;
    }
    return best;
  };
  const double coarse = scan(-options.reach_m, options.reach_m, 0.05);
  const double s = scan(coarse - 0.05, coarse + 0.05, 0.0025);
  if (offsets(s).cwiseAbs().maxCoeff() > options.tolerance_px) {
    return std::nullopt;
  }
  State y = x;
  y[tx] += s * along.x();
  y[tz] += s * along.z();
  if (!dofs.inside(y)) return std::nullopt;
  return y;
}

}  // namespace simcap::tracker::gomez
