// Shape adjustment on the first silhouette (shape_fit.h).
#include "tracker/gomez/shape_fit.h"

#include "tracker/common/mask_box.h"
#include "tracker/gomez/label_renderer.h"
#include "tracker/gomez/nelder_mead.h"

namespace simcap::tracker::gomez {

ShapeScales fit_shape(const Skeleton& skeleton, BodyKind kind, const Pose& pose,
                      const Camera& camera, const cv::Mat& silhouette,
                      const ShapeFitOptions& options) {
  const auto world = forward_kinematics(skeleton, pose);
  const cv::Rect person = mask_box(silhouette);
  if (person.empty()) return {};
  const cv::Rect box = (person | body_box(make_body_shape(skeleton, kind), world, camera)) &
                       cv::Rect(0, 0, silhouette.cols, silhouette.rows);
  const View view{&camera, box.x, box.y, 1, box.width, box.height};
  const auto scales = [](const Eigen::VectorXd& z) {
    return ShapeScales{z[0], z[1], z[2], z[3], z[4]};
  };
  // Non-overlap of the drawn body and the silhouette inside the view (the feet and whatever
  // the body does not draw count against it alike).
  const auto cost = [&](const Eigen::VectorXd& z) {
    thread_local LabelImage labels;
    render_labels(make_body_shape(skeleton, kind, scales(z)), world, view, labels);
    long both = 0, either = 0;
    for (int v = 0; v < view.height; ++v) {
      const std::uint8_t* mask = silhouette.ptr<std::uint8_t>(view.y0 + v) + view.x0;
      for (int u = 0; u < view.width; ++u) {
        const bool drawn = labels.at(u, v) != kNoCell, seen = mask[u] != 0;
        both += drawn && seen;
        either += drawn || seen;
      }
    }
    const double ratio = either ? static_cast<double>(either - both) / either : 1.0;
    return NelderMead::Terms(ratio, 0.0);
  };
  NelderMead nm(cost, Eigen::VectorXd::Constant(5, options.lower),
                Eigen::VectorXd::Constant(5, options.upper));
  nm.start(Eigen::VectorXd::Ones(5), Eigen::VectorXd::Constant(5, 0.1));
  nm.set_weights({1.0, 0.0});
  nm.run(options.evaluations);
  return scales(nm.best());
}

}  // namespace simcap::tracker::gomez
