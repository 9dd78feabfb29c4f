#include "tracker/unzueta/sik_collision.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"

namespace simcap {
namespace {

// Spine segments shorter than this in height hold no prism (CMU's lowerback sits on the hips).
constexpr double kMinPrismHeight = 0.01;
// Share of the forearm next to the elbow / wrist whose mesh gives the sphere radius (simcap's
// reading of the thesis' "vertices that are near the elbow joint").
constexpr double kJointZone = 0.15;

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Median distance from the line a->b of the mesh vertices labelled `joint` whose projection on
// it falls in [from, to] (fractions of |ab|).
double tube_radius(const BodyMesh& mesh, int joint, const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b, double from, double to) {
  const Eigen::Vector3d ab = b - a;
  std::vector<double> distances;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (mesh.vertex_segment[v] != joint) continue;
    const Eigen::Vector3d p = mesh.vertices[v].cast<double>() - a;
    const double t = p.dot(ab) / ab.squaredNorm();
    if (t >= from && t <= to) distances.push_back((p - t * ab).norm());
  }
  return median(std::move(distances));
}

}  // namespace

SikCollider::SikCollider(const SikBody& body, const BodyMesh& mesh, double floor_y)
    : floor_y_(floor_y) {
  const Skeleton& sk = body.skeleton();
  if (mesh.vertex_segment.size() != mesh.vertices.size()) {
    throw Error("SIK collisions: the body mesh has no part label per vertex");
  }
  for (std::uint16_t j : mesh.vertex_segment) {
    if (j >= sk.size()) throw Error("SIK collisions: the body mesh was built for another skeleton");
  }

  // Torso vertices: not on an arm, a leg or the head.
  std::vector<int> limbs_and_head = {body.head()};
  for (int side : {kLeft, kRight}) {
    limbs_and_head.push_back(body.arm(side).a);
    limbs_and_head.push_back(body.leg(side).a);
  }
  auto is_torso = [&](int joint) {
    return std::none_of(limbs_and_head.begin(), limbs_and_head.end(),
                        [&](int top) { return sk.is_descendant(joint, top); });
  };

  // One prism per spine segment below the neck; the lowest one reaches down over the pelvis.
  std::vector<int> chain = body.spine();
  chain.push_back(body.head());
  double lowest = INFINITY;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (is_torso(mesh.vertex_segment[v])) lowest = std::min<double>(lowest, mesh.vertices[v].y());
  }
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    if (sk[chain[i]].name.starts_with("vc")) break;
    const Eigen::Vector3d axis = body.offset(chain[i + 1]);
    if (axis.y() < kMinPrismHeight) continue;
    const Eigen::Vector3d base = sk[chain[i]].center;
    const double bottom = prisms_.empty() ? lowest : base.y();
    SikTorsoPrism prism;
    prism.joint = chain[i];
    prism.axis = axis;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      const Eigen::Vector3d p = mesh.vertices[v].cast<double>();
      if (!is_torso(mesh.vertex_segment[v]) || p.y() < bottom || p.y() > base.y() + axis.y()) {
        continue;
      }
      const Eigen::Vector3d r = p - base - (p.y() - base.y()) / axis.y() * axis;
      prism.half_width = std::max(prism.half_width, std::abs(r.x()));
      prism.front = std::max(prism.front, r.z());
      prism.back = std::max(prism.back, -r.z());
    }
    if (prism.half_width > 0) prisms_.push_back(prism);
  }
  if (prisms_.empty()) throw Error("SIK collisions: the body mesh has no torso");

  for (int side : {kLeft, kRight}) {
    const SikLimb& arm = body.arm(side);
    const Eigen::Vector3d elbow = sk[arm.b].center, wrist = sk[arm.c].center;
    elbow_radius_[side] = tube_radius(mesh, arm.b, elbow, wrist, 0.0, kJointZone);
    wrist_radius_[side] = tube_radius(mesh, arm.b, elbow, wrist, 1.0 - kJointZone, 1.0);
    // The foot's support points: its extreme vertices along 26 directions, ankle-relative.
    const int ankle = body.leg(side).c;
    std::vector<Eigen::Vector3d> points;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      if (sk.is_descendant(mesh.vertex_segment[v], ankle)) {
        points.push_back(mesh.vertices[v].cast<double>() - sk[ankle].center);
      }
    }
    if (points.empty()) throw Error("SIK collisions: the body mesh has no " + sk[ankle].name);
    std::set<size_t> extremes;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const Eigen::Vector3d d(dx, dy, dz);
          if (d.isZero()) continue;
          size_t best = 0;
          for (size_t k = 1; k < points.size(); ++k) {
            if (points[k].dot(d) > points[best].dot(d)) best = k;
          }
          extremes.insert(best);
        }
      }
    }
    for (size_t k : extremes) foot_[side].push_back(points[k]);
  }
}

SikPenetration SikCollider::torso(const std::vector<Eigen::Quaterniond>& rotation,
                                  const std::vector<Eigen::Vector3d>& position,
                                  const Eigen::Vector3d& centre, double radius) const {
  SikPenetration worst;
  for (const SikTorsoPrism& prism : prisms_) {
    const Eigen::Quaterniond& r = rotation[prism.joint];
    const Eigen::Vector3d q = r.conjugate() * (centre - position[prism.joint]);
    const double t = q.y() / prism.axis.y();
    const bool lowest = &prism == &prisms_.front();
    if (t > 1.0 || (t < 0.0 && !lowest)) continue;
    // Cross-section coordinates relative to the box centre.
    const Eigen::Vector3d on_axis = t * prism.axis;
    const double half_depth = 0.5 * (prism.front + prism.back);
    const double mid_z = 0.5 * (prism.front - prism.back);
    Eigen::Vector2d p(q.x() - on_axis.x(), q.z() - on_axis.z() - mid_z);
    const double distance = p.norm();
    const Eigen::Vector2d dir =
        distance > 1e-9 ? Eigen::Vector2d(p / distance) : Eigen::Vector2d(1.0, 0.0);
    // Where the ray from the centre along dir leaves the box, and how far the sphere reaches in.
    const double exit =
        std::min(std::abs(dir.x()) > 1e-12 ? prism.half_width / std::abs(dir.x()) : INFINITY,
                 std::abs(dir.y()) > 1e-12 ? half_depth / std::abs(dir.y()) : INFINITY);
    const double inner = distance - radius;
    const double depth = exit - inner;
    if (depth <= worst.depth) continue;
    auto world = [&](double s) {
      const Eigen::Vector3d local(on_axis.x() + s * dir.x(), on_axis.y(),
                                  on_axis.z() + mid_z + s * dir.y());
      return Eigen::Vector3d(position[prism.joint] + r * local);
    };
    worst.depth = depth;
    worst.deepest = world(inner);
    worst.outer = world(exit);
  }
  return worst;
}

Eigen::Vector3d SikCollider::lowest_foot_point(int side, const Eigen::Quaterniond& ankle_rotation,
                                               const Eigen::Vector3d& ankle_position) const {
  Eigen::Vector3d lowest = ankle_position;
  double y = INFINITY;
  for (const Eigen::Vector3d& p : foot_[side]) {
    const Eigen::Vector3d w = ankle_position + ankle_rotation * p;
    if (w.y() < y) {
      y = w.y();
      lowest = w;
    }
  }
  return lowest;
}

}  // namespace simcap
