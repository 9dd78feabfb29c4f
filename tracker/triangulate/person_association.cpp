#include "tracker/triangulate/person_association.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tracker/common/triangulation.h"

namespace simcap::tracker {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double median(std::vector<double> v) {
  if (v.empty()) return kInfinity;
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double diagonal(const std::vector<Eigen::Vector2d>& points) {
  if (points.empty()) return 0;
  Eigen::Vector2d lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// Median distance between a person's confident keypoints and the prediction's projections, and
// the projections' bounding-box diagonal.
std::pair<double, double> distance_to(const Camera& cam, const PersonKeypoints& person,
                                      const std::vector<std::optional<Eigen::Vector3d>>& predicted,
                                      double min_confidence) {
  std::vector<double> d;
  std::vector<Eigen::Vector2d> projected;
  for (size_t k = 0; k < predicted.size() && k < person.keypoints.size(); ++k) {
    if (!predicted[k]) continue;
    const auto p = cam.project(*predicted[k]);
    if (!p) continue;
    projected.push_back(*p);
    const Eigen::Vector3d& kp = person.keypoints[k];
    if (kp.z() >= min_confidence) d.push_back((kp.head<2>() - *p).norm());
  }
  return {median(d), diagonal(projected)};
}

double prominence(const PersonKeypoints& person, double min_confidence) {
  double score = 0;
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector3d& kp : person.keypoints) {
    if (kp.z() < min_confidence) continue;
    score += kp.z();
    points.push_back(kp.head<2>());
  }
  return score * diagonal(points);
}

// Median over shared confident keypoints of the worse reprojection error of their two-view DLT.
double pair_error(const Camera& ca, const PersonKeypoints& a, const Camera& cb,
                  const PersonKeypoints& b, double min_confidence) {
  std::vector<double> errors;
  for (size_t k = 0; k < a.keypoints.size() && k < b.keypoints.size(); ++k) {
    const Eigen::Vector3d &ka = a.keypoints[k], &kb = b.keypoints[k];
    if (ka.z() < min_confidence || kb.z() < min_confidence) continue;
    const std::vector<PixelObservation> views = {{&ca, ka.head<2>()}, {&cb, kb.head<2>()}};
    const auto x = triangulate(views);
    if (!x) continue;
    const auto pa = ca.project(*x), pb = cb.project(*x);
    if (!pa || !pb) continue;
    errors.push_back(std::max((*pa - ka.head<2>()).norm(), (*pb - kb.head<2>()).norm()));
  }
  // Two people sharing fewer than 3 keypoints cannot be told apart from a chance match.
  return errors.size() < 3 ? kInfinity : median(errors);
}

Association seed(std::span<const Camera> cameras,
                 const std::vector<std::vector<PersonKeypoints>>& people,
                 const AssociationOptions& o) {
  const size_t n = cameras.size();
  Association a{std::vector<int>(n, -1), std::vector<double>(n, kInfinity), true};
  int ref_camera = -1, ref_person = -1;
  double best = 0;
  for (size_t c = 0; c < n; ++c) {
    for (size_t p = 0; p < people[c].size(); ++p) {
      const double s = prominence(people[c][p], o.min_confidence);
      if (s > best) {
        best = s;
        ref_camera = static_cast<int>(c);
        ref_person = static_cast<int>(p);
      }
    }
  }
  if (ref_camera < 0) return a;
  a.person[ref_camera] = ref_person;
  a.cost[ref_camera] = 0;
  const PersonKeypoints& ref = people[ref_camera][ref_person];
  for (size_t c = 0; c < n; ++c) {
    if (static_cast<int>(c) == ref_camera) continue;
    for (size_t p = 0; p < people[c].size(); ++p) {
      const double e =
          pair_error(cameras[ref_camera], ref, cameras[c], people[c][p], o.min_confidence);
      if (e < a.cost[c] && e <= o.seed_error_px) {
        a.cost[c] = e;
        a.person[c] = static_cast<int>(p);
      }
    }
  }
  return a;
}

}  // namespace

Association associate_people(std::span<const Camera> cameras,
                             const std::vector<std::vector<PersonKeypoints>>& people,
                             const std::vector<std::optional<Eigen::Vector3d>>& predicted,
                             const AssociationOptions& o) {
  const size_t n = cameras.size();
  if (predicted.empty()) return seed(cameras, people, o);
  Association a{std::vector<int>(n, -1), std::vector<double>(n, kInfinity), false};
  int matched = 0;
  for (size_t c = 0; c < n; ++c) {
    for (size_t p = 0; p < people[c].size(); ++p) {
      const auto [d, size] = distance_to(cameras[c], people[c][p], predicted, o.min_confidence);
      if (d < a.cost[c] && d <= o.gate * size) {
        a.cost[c] = d;
        a.person[c] = static_cast<int>(p);
      }
    }
    matched += a.person[c] >= 0;
  }
  return matched >= 2 ? a : seed(cameras, people, o);
}

}  // namespace simcap::tracker
