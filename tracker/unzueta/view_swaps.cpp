#include "tracker/unzueta/view_swaps.h"

namespace simcap::tracker {

bool tracks_swapped(const Camera& camera, const Eigen::Vector2d& left_px,
                    const Eigen::Vector2d& right_px, const Eigen::Vector3d& left,
                    const Eigen::Vector3d& right, double inlier_px) {
  if (camera.to_camera(left).z() <= 0 || camera.to_camera(right).z() <= 0) return false;
  const auto l = camera.project(left), r = camera.project(right);
  if (!l || !r || (*l - *r).norm() <= inlier_px) return false;
  const double kept_l = (*l - left_px).norm(), kept_r = (*r - right_px).norm();
  const double swapped_l = (*l - right_px).norm(), swapped_r = (*r - left_px).norm();
  return swapped_l <= inlier_px && swapped_r <= inlier_px &&
         (kept_l > inlier_px || kept_r > inlier_px) && swapped_l + swapped_r < kept_l + kept_r;
}

}  // namespace simcap::tracker
