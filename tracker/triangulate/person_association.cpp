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

// Median distance between a person's confident keypoints and the expected ones, and the
// expectation's bounding-box diagonal.
std::pair<double, double> distance_to(const PersonKeypoints& person,
                                      const PersonKeypoints& expected, double min_confidence) {
  std::vector<double> d;
  std::vector<Eigen::Vector2d> points;
  for (size_t k = 0; k < expected.keypoints.size() && k < person.keypoints.size(); ++k) {
    const Eigen::Vector3d &e = expected.keypoints[k], &kp = person.keypoints[k];
    if (e.z() <= 0) continue;
    points.push_back(e.head<2>());
    if (kp.z() >= min_confidence) d.push_back((kp.head<2>() - e.head<2>()).norm());
  }
  return {median(d), diagonal(points)};
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

// The chosen people's keypoints triangulated (plain DLT) and projected into `camera`: where the
// actor must be there. Keypoints fewer than two cameras chose are unknown (score 0).
PersonKeypoints projected(std::span<const Camera> cameras,
                          const std::vector<std::vector<PersonKeypoints>>& people,
                          const Association& a, const Camera& camera, double min_confidence) {
  size_t count = 0;
  for (size_t c = 0; c < cameras.size(); ++c) {
    if (a.person[c] >= 0) count = std::max(count, people[c][a.person[c]].keypoints.size());
  }
  PersonKeypoints out;
  out.keypoints.assign(count, Eigen::Vector3d::Zero());
  for (size_t k = 0; k < count; ++k) {
    std::vector<PixelObservation> views;
    for (size_t c = 0; c < cameras.size(); ++c) {
      if (a.person[c] < 0) continue;
      const auto& kps = people[c][a.person[c]].keypoints;
      if (k < kps.size() && kps[k].z() >= min_confidence) {
        views.push_back({&cameras[c], kps[k].head<2>()});
      }
    }
    const auto x = triangulate(views);
    const auto p = x ? camera.project(*x) : std::nullopt;
    if (p) out.keypoints[k] << *p, 1.0;
  }
  return out;
}

// Cameras without a person join. With one camera chosen, the best-agreeing pair of views
// (over every other camera and person) joins first; with two or more, each camera takes the
// person nearest the chosen people's triangulated keypoints (a pair of views alone cannot tell
// two people of one height apart when the cameras stand at one height: the epipolar lines run
// along the body).
void join(std::span<const Camera> cameras, const std::vector<std::vector<PersonKeypoints>>& people,
          int ref_camera, int ref_person, const AssociationOptions& o, Association& a) {
  const auto known = [&a] {
    return std::count_if(a.person.begin(), a.person.end(), [](int p) { return p >= 0; });
  };
  if (known() == 1) {
    const PersonKeypoints& ref = people[ref_camera][ref_person];
    double best = o.join_error_px;
    int best_camera = -1, best_person = -1;
    for (size_t c = 0; c < cameras.size(); ++c) {
      if (a.person[c] >= 0) continue;
      for (size_t p = 0; p < people[c].size(); ++p) {
        const double e =
            pair_error(cameras[ref_camera], ref, cameras[c], people[c][p], o.min_confidence);
        if (e <= best) {
          best = e;
          best_camera = static_cast<int>(c);
          best_person = static_cast<int>(p);
        }
      }
    }
    if (best_camera < 0) return;
    a.person[best_camera] = best_person;
    a.cost[best_camera] = best;
    a.kind[best_camera] = AssociationKind::joined;
  }
  const Association chosen = a;
  for (size_t c = 0; c < cameras.size(); ++c) {
    if (a.person[c] >= 0) continue;
    const PersonKeypoints expected =
        projected(cameras, people, chosen, cameras[c], o.min_confidence);
    for (size_t p = 0; p < people[c].size(); ++p) {
      const auto [d, size] = distance_to(people[c][p], expected, o.min_confidence);
      if (d <= o.gate * size && d < a.cost[c]) {
        a.cost[c] = d;
        a.person[c] = static_cast<int>(p);
        a.kind[c] = AssociationKind::joined;
      }
    }
  }
}

}  // namespace

Association associate_people(std::span<const Camera> cameras,
                             const std::vector<std::vector<PersonKeypoints>>& people,
                             const std::vector<PersonKeypoints>& expected,
                             const AssociationOptions& o) {
  const size_t n = cameras.size();
  Association a{std::vector<int>(n, -1), std::vector<double>(n, kInfinity),
                std::vector<AssociationKind>(n, AssociationKind::none)};
  for (size_t c = 0; c < n && c < expected.size(); ++c) {
    for (size_t p = 0; p < people[c].size(); ++p) {
      const auto [d, size] = distance_to(people[c][p], expected[c], o.min_confidence);
      if (d < a.cost[c] && d <= o.gate * size) {
        a.cost[c] = d;
        a.person[c] = static_cast<int>(p);
        a.kind[c] = AssociationKind::tracked;
      }
    }
  }
  // The reference: the most prominent tracked person, or without one the most prominent of all.
  int ref_camera = -1, ref_person = -1;
  double best = 0;
  const bool any_tracked =
      std::find(a.kind.begin(), a.kind.end(), AssociationKind::tracked) != a.kind.end();
  for (size_t c = 0; c < n; ++c) {
    for (size_t p = 0; p < people[c].size(); ++p) {
      if (any_tracked && a.person[c] != static_cast<int>(p)) continue;
      const double s = prominence(people[c][p], o.min_confidence);
      if (s > best) {
        best = s;
        ref_camera = static_cast<int>(c);
        ref_person = static_cast<int>(p);
      }
    }
  }
  if (ref_camera < 0) return a;
  if (!any_tracked) {
    a.person[ref_camera] = ref_person;
    a.cost[ref_camera] = 0;
    a.kind[ref_camera] = AssociationKind::seeded;
  }
  join(cameras, people, ref_camera, ref_person, o, a);
  return a;
}

}  // namespace simcap::tracker
