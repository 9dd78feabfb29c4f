#include "models/body_mesh.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <span>
#include <string>

#include "core/error.h"
#include "models/generalized_cylinder.h"
#include "models/humanoid.h"

// The body is ten closed parts (torso, head with neck, two shoulder caps, two arms with hands,
// two legs, two shoes), each a generalized cylinder around the skeleton's bones. Overlaps between
// parts are intended: a ray tracer sees their union.
//
// Cross-section semi-axes are fractions of standing height H. They are rounded from mean adult
// dimensions of the ANSUR II survey (Gordon et al. 2014, "2012 Anthropometric Survey of U.S. Army
// Personnel", NATICK/TR-15/007: hip breadth, waist and chest breadth and depth, neck, biceps,
// forearm, wrist, thigh, knee, calf and ankle circumferences, head breadth and length, hand
// breadth) divided by the mean stature, plus a few millimetres of clothing; where the survey has
// no direct measure (shoulder cap, shoe) the value is a simcap choice and is marked so. Lengths
// along the body come from the skeleton (Drillis & Contini via build_humanoid), so the mesh
// follows any BodyProportions.

namespace simcap {

std::string_view material_region_name(MaterialRegion region) {
  switch (region) {
    case MaterialRegion::skin:
      return "skin";
    case MaterialRegion::shirt:
      return "shirt";
    case MaterialRegion::trousers:
      return "trousers";
    case MaterialRegion::shoes:
      return "shoes";
    case MaterialRegion::hair:
      return "hair";
  }
  return "unknown";
}

namespace {

// A skinning influence changes from the previous station's joint to this one over
// [s - blend, s + blend] (smoothstep), so at most two joints share a ring.
struct WeightStation {
  double s;
  int joint;
  double blend;
};

// From arc length `s` on, vertices belong to `joint`'s segment.
struct LabelStation {
  double s;
  int joint;
};

using MaterialRule = std::function<MaterialRegion(const Eigen::Vector3d& centroid, double s)>;
// Where a vertex falls among the stations: its arc length, unless a part bends the boundaries.
using StationCoordinate = std::function<double(const Eigen::Vector3d& vertex, double s)>;

struct Part {
  TubeSpec tube;
  std::vector<LabelStation> labels;
  std::vector<WeightStation> weights;
  MaterialRule material;
  StationCoordinate coordinate = [](const Eigen::Vector3d&, double s) { return s; };
};

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// Shrinks each blend so that neighbouring zones cannot overlap.
void limit_blends(std::vector<WeightStation>& stations) {
  for (size_t k = 1; k < stations.size(); ++k) {
    double room = stations[k].s - stations[k - 1].s;
    if (k + 1 < stations.size()) room = std::min(room, stations[k + 1].s - stations[k].s);
    stations[k].blend = std::min(stations[k].blend, 0.5 * room);
  }
}

std::map<int, double> weights_at(const std::vector<WeightStation>& stations, double s) {
  for (size_t k = 1; k < stations.size(); ++k) {
    const WeightStation& w = stations[k];
    if (s < w.s - w.blend) return {{stations[k - 1].joint, 1.0}};
    if (s <= w.s + w.blend && w.blend > 0 && w.joint != stations[k - 1].joint) {
      const double t = smoothstep((s - (w.s - w.blend)) / (2 * w.blend));
      return {{stations[k - 1].joint, 1.0 - t}, {w.joint, t}};
    }
  }
  return {{stations.back().joint, 1.0}};
}

int label_at(const std::vector<LabelStation>& stations, double s) {
  int joint = stations.front().joint;
  for (const LabelStation& l : stations) {
    if (s >= l.s) joint = l.joint;
  }
  return joint;
}

// Maps heights of the canonical humanoid (fractions of H) onto this skeleton, piecewise linearly
// through the hip, C7, skull base and head top, so torso and head keys follow its proportions.
class HeightMap {
 public:
  HeightMap(const Skeleton& reference, const Skeleton& skeleton) {
    for (const char* name : {"l_hip", "vc7", "skullbase", "skull_tip"}) {
      from_.push_back(reference[reference.require(name)].center.y());
      to_.push_back(skeleton[skeleton.require(name)].center.y());
    }
  }
  double operator()(double h) const {
    size_t i = 1;
    while (i + 1 < from_.size() && h > from_[i]) ++i;
    const double t = (h - from_[i - 1]) / (from_[i] - from_[i - 1]);
    return to_[i - 1] + t * (to_[i] - to_[i - 1]);
  }

 private:
  std::vector<double> from_, to_;
};

class BodyPlan {
 public:
  BodyPlan(const Skeleton& skeleton, const BodyShape& shape)
      : sk_(skeleton),
        reference_(build_humanoid(BodyParameters{.height = 1.0, .proportions = {}})),
        height_(reference_, skeleton),
        H_(skeleton[skeleton.require("skull_tip")].center.y()),
        girth_(shape.girth) {
    if (!(H_ > 0.3)) throw Error("body mesh: the skeleton's skull_tip must be above the floor");
    if (!(girth_ >= 0.5 && girth_ <= 2.0)) {
      throw Error("body mesh: girth must be between 0.5 and 2, got " + std::to_string(girth_));
    }
  }

  std::vector<Part> parts() const {
    std::vector<Part> out;
    out.push_back(torso());
    out.push_back(head());
    for (const char* side : {"l_", "r_"}) {
      out.push_back(shoulder_cap(side));
      out.push_back(arm(side));
      out.push_back(leg(side));
      out.push_back(shoe(side));
    }
    return out;
  }

 private:
  int joint(const std::string& name) const { return sk_.require(name); }
  Eigen::Vector3d at(const std::string& name) const { return sk_[joint(name)].center; }
  // A cross-section key: semi-axes u and v in units of H (scaled by the girth), offset in metres.
  TubeSection k(double s, double u, double v, Eigen::Vector3d offset = Eigen::Vector3d::Zero(),
                double exponent = 2.0) const {
    return {s, u * H_ * girth_, v * H_ * girth_, offset, exponent};
  }
  double spacing() const { return 0.0055 * H_; }
  // An end cap of `wanted` metres, but at most `share` of a tube `length` long: a short foot or
  // shoulder (small proportions) keeps room for the keys between its caps.
  static double cap(double wanted, double length, double share) {
    return std::min(wanted, share * length);
  }

  // A cross-section of the upright trunk or head at canonical height h (fraction of H): semi-axes
  // in units of H, shifted forward by z H.
  struct Row {
    double h, half_width, half_depth, z;
  };
  // A vertical tube from `bottom` to `top` (metres) through `rows`, capped beyond the first and
  // last row.
  Part upright_tube(std::span<const Row> rows, double bottom, double top, int segments,
                    int cap_rings) const {
    Part p;
    p.tube.axis = {{0, bottom, 0}, {0, top, 0}};
    p.tube.start_cap = height_(rows.front().h) - bottom;
    p.tube.end_cap = top - height_(rows.back().h);
    for (const Row& r : rows) {
      p.tube.sections.push_back(
          k(height_(r.h) - bottom, r.half_width, r.half_depth, {0, 0, r.z * H_}));
    }
    p.tube.segments = segments;
    p.tube.ring_spacing = spacing();
    p.tube.cap_rings = cap_rings;
    return p;
  }

  // Pelvis and trunk, crotch to the base of the neck. The belt line at 0.60 H separates the
  // trousers from the shirt.
  Part torso() const {
    // Hip breadth ~0.205 H, waist breadth ~0.18 H, chest breadth ~0.175 H, chest depth ~0.135 H
    // (ANSUR II means / stature, clothed); the top rows narrow into the neck (simcap choice).
    const Row rows[] = {{0.485, 0.082, 0.056, 0.000},  {0.505, 0.097, 0.064, -0.002},
                        {0.530, 0.103, 0.068, -0.004}, {0.560, 0.100, 0.066, -0.002},
                        {0.600, 0.090, 0.060, 0.002},  {0.630, 0.086, 0.058, 0.004},
                        {0.680, 0.086, 0.062, 0.006},  {0.720, 0.087, 0.068, 0.008},
                        {0.760, 0.085, 0.068, 0.006},  {0.790, 0.080, 0.063, 0.002},
                        {0.810, 0.072, 0.056, -0.002}, {0.822, 0.062, 0.048, -0.006}};
    const double bottom = height_(0.460);
    Part p = upright_tube(rows, bottom, height_(0.844), 72, 8);
    const auto s_of = [&](const char* name) { return at(name).y() - bottom; };
    p.labels = {{0, joint("sacroiliac")}};
    p.weights = {{0, joint("sacroiliac"), 0}};
    for (const char* name : {"vl5", "vl3", "vl1", "vt10", "vt6", "vt1"}) {
      p.labels.push_back({s_of(name), joint(name)});
      p.weights.push_back({s_of(name), joint(name), 0.03 * H_});
    }
    const double belt = height_(0.600);
    p.material = [belt](const Eigen::Vector3d& c, double) {
      return c.y() < belt ? MaterialRegion::trousers : MaterialRegion::shirt;
    };
    return p;
  }

  // Neck and head, from inside the torso to the head top. Neck circumference ~0.22 H, head
  // breadth ~0.088 H and length ~0.112 H (ANSUR II / stature); the jaw and face rows push the
  // section forward of the cervical spine (simcap choice).
  Part head() const {
    const Row rows[] = {{0.815, 0.036, 0.036, -0.010}, {0.840, 0.034, 0.035, -0.008},
                        {0.862, 0.033, 0.035, -0.004}, {0.876, 0.037, 0.042, 0.002},
                        {0.890, 0.042, 0.050, 0.006},  {0.910, 0.045, 0.055, 0.007},
                        {0.935, 0.047, 0.057, 0.005}};
    const double bottom = height_(0.800);
    Part p = upright_tube(rows, bottom, at("skull_tip").y(), 56, 12);
    const auto s_of = [&](const char* name) { return at(name).y() - bottom; };
    p.labels = {{0, joint("vt1")},
                {s_of("vc7"), joint("vc7")},
                {s_of("vc4"), joint("vc4")},
                {s_of("skullbase"), joint("skullbase")}};
    p.weights = {{0, joint("vt1"), 0},
                 {s_of("vc7"), joint("vc7"), 0.012 * H_},
                 {s_of("vc4"), joint("vc4"), 0.02 * H_},
                 {s_of("skullbase"), joint("skullbase"), 0.02 * H_}};
    // The jaw hangs below the skull base in front: chin, jaw and face belong to the skull (and
    // move with it) from the chin height (0.870 H, Winter Fig. 4.1) up, the throat to the neck.
    const double chin = height_(0.870), jaw_shift = at("skullbase").y() - chin + 0.015 * H_;
    const double throat = 0.02 * H_, band = 0.012 * H_;
    p.coordinate = [=](const Eigen::Vector3d& v, double s) {
      const double in_front = smoothstep((v.z() - throat) / throat);
      const double above_chin = smoothstep((v.y() - (chin - band)) / band);
      return s + jaw_shift * in_front * above_chin;
    };
    // Hairline: at the forehead 0.955 H, sloping down to the nape at 0.895 H (simcap choice).
    const double front = height_(0.955), nape = height_(0.895), depth = 0.057 * H_;
    p.material = [front, nape, depth](const Eigen::Vector3d& c, double) {
      const double back = std::clamp(0.5 - c.z() / depth, 0.0, 1.0);
      return c.y() > front + back * (nape - front) ? MaterialRegion::hair : MaterialRegion::skin;
    };
    return p;
  }

  // The top of the shoulder from the neck to the deltoid, over the clavicle (simcap choice:
  // sizes set so the shoulder line meets the acromion height of Drillis & Contini).
  Part shoulder_cap(const std::string& side) const {
    const double sign = side == "l_" ? 1.0 : -1.0;
    const Eigen::Vector3d shoulder = at(side + "shoulder");
    const Eigen::Vector3d medial(sign * 0.02 * H_, at("vc7").y() - 0.006 * H_, -0.012 * H_);
    const Eigen::Vector3d lateral = shoulder + Eigen::Vector3d(sign * 0.024 * H_, 0.002 * H_, 0);
    Part p;
    p.tube.axis = {medial, lateral};
    p.tube.reference = Eigen::Vector3d::UnitY();
    const double length = (lateral - medial).norm();
    p.tube.start_cap = cap(0.02 * H_, length, 0.3);
    p.tube.end_cap = cap(0.025 * H_, length, 0.35);
    p.tube.sections = {k(p.tube.start_cap, 0.024, 0.038), k(length - p.tube.end_cap, 0.027, 0.032)};
    p.tube.segments = 32;
    p.tube.ring_spacing = spacing();
    p.tube.cap_rings = 6;
    const double s_shoulder = (shoulder - medial).dot((lateral - medial).normalized());
    p.labels = {{0, joint(side + "sternoclavicular")}, {s_shoulder, joint(side + "shoulder")}};
    p.weights = {{0, joint("vt1"), 0},
                 {0.03 * H_, joint(side + "sternoclavicular"), 0.025 * H_},
                 {s_shoulder, joint(side + "shoulder"), 0.02 * H_}};
    p.material = [](const Eigen::Vector3d&, double) { return MaterialRegion::shirt; };
    return p;
  }

  // Upper arm, forearm and hand hanging at the side, palm towards the thigh: the hand is thin
  // along x and wide along z. Biceps ~0.18 H, forearm ~0.165 H, wrist ~0.10 H circumference,
  // hand breadth ~0.05 H (ANSUR II / stature); short sleeves end at 55% of the upper arm.
  Part arm(const std::string& side) const {
    const Eigen::Vector3d shoulder = at(side + "shoulder"), elbow = at(side + "elbow"),
                          wrist = at(side + "radiocarpal"), tip = at(side + "hand_tip");
    const double cap = 0.035 * H_;
    Part p;
    p.tube.axis = {shoulder + Eigen::Vector3d(0, cap, 0), shoulder, elbow, wrist, tip};
    p.tube.start_cap = cap;
    p.tube.end_cap = 0.018 * H_;
    const double s_sh = cap, s_el = s_sh + (elbow - shoulder).norm(),
                 s_wr = s_el + (wrist - elbow).norm(), s_tip = s_wr + (tip - wrist).norm();
    const double upper = s_el - s_sh, fore = s_wr - s_el, hand = s_tip - s_wr;
    const double sleeve = s_sh + 0.55 * upper;
    p.tube.sections = {k(s_sh, 0.029, 0.031),
                       k(s_sh + 0.35 * upper, 0.027, 0.028),
                       k(sleeve, 0.026, 0.027),
                       k(s_el - 0.15 * upper, 0.022, 0.024),
                       k(s_el, 0.021, 0.023),
                       k(s_el + 0.25 * fore, 0.023, 0.025),
                       k(s_wr - 0.1 * fore, 0.014, 0.018),
                       k(s_wr, 0.012, 0.017),
                       k(s_wr + 0.25 * hand, 0.010, 0.025, Eigen::Vector3d::Zero(), 2.6),
                       k(s_wr + 0.5 * hand, 0.010, 0.025, Eigen::Vector3d::Zero(), 2.6),
                       k(s_wr + 0.6 * hand, 0.008, 0.022, Eigen::Vector3d::Zero(), 2.6),
                       k(s_tip - p.tube.end_cap, 0.007, 0.018, Eigen::Vector3d::Zero(), 2.6)};
    p.tube.segments = 32;
    p.tube.ring_spacing = spacing();
    p.tube.cap_rings = 6;
    p.labels = {{0, joint(side + "shoulder")},
                {s_el, joint(side + "elbow")},
                {s_wr, joint(side + "radiocarpal")}};
    p.weights = {{0, joint(side + "shoulder"), 0},
                 {s_el, joint(side + "elbow"), 0.03 * H_},
                 {s_wr, joint(side + "radiocarpal"), 0.012 * H_}};
    p.material = [sleeve](const Eigen::Vector3d&, double s) {
      return s < sleeve ? MaterialRegion::shirt : MaterialRegion::skin;
    };
    return p;
  }

  // Thigh and calf in trousers, from inside the pelvis to inside the shoe. Thigh ~0.34 H,
  // knee ~0.22 H, calf ~0.22 H circumference (ANSUR II / stature), trousers hang loose below
  // the calf (simcap choice).
  Part leg(const std::string& side) const {
    const Eigen::Vector3d hip = at(side + "hip"), knee = at(side + "knee"),
                          ankle = at(side + "talocrural");
    const double cap = 0.05 * H_;
    Part p;
    p.tube.axis = {hip + Eigen::Vector3d(0, cap, 0), hip, knee, ankle,
                   ankle - Eigen::Vector3d(0, 0.02 * H_, 0)};
    p.tube.start_cap = cap;
    p.tube.end_cap = 0.02 * H_;
    const double s_hip = cap, s_kn = s_hip + (knee - hip).norm(),
                 s_an = s_kn + (ankle - knee).norm();
    const double thigh = s_kn - s_hip, calf = s_an - s_kn;
    const Eigen::Vector3d back(0, 0, -0.004 * H_);
    p.tube.sections = {k(s_hip, 0.052, 0.056, 0.75 * back),
                       k(s_hip + 0.12 * thigh, 0.050, 0.053),
                       k(s_hip + 0.5 * thigh, 0.045, 0.047),
                       k(s_kn - 0.1 * thigh, 0.038, 0.040),
                       k(s_kn, 0.036, 0.038),
                       k(s_kn + 0.3 * calf, 0.036, 0.040, back),
                       k(s_kn + 0.7 * calf, 0.029, 0.031),
                       k(s_an, 0.027, 0.029)};
    p.tube.segments = 40;
    p.tube.ring_spacing = spacing();
    p.tube.cap_rings = 6;
    p.labels = {{0, joint(side + "hip")}, {s_kn, joint(side + "knee")}};
    p.weights = {{0, joint("sacroiliac"), 0},
                 {s_hip, joint(side + "hip"), 0.03 * H_},
                 {s_kn, joint(side + "knee"), 0.03 * H_}};
    p.material = [](const Eigen::Vector3d&, double) { return MaterialRegion::trousers; };
    return p;
  }

  // A shoe from heel to toe with a flat sole on the floor. The heel lies behind the ankle by a
  // third of the ankle-to-toe distance (the Drillis & Contini foot has its ankle a quarter of the
  // way from the heel); widths and heights are simcap choices for a casual shoe.
  Part shoe(const std::string& side) const {
    const Eigen::Vector3d ankle = at(side + "talocrural"), toe = at(side + "toe_tip"),
                          ball = at(side + "metatarsophalangeal_2");
    const double heel_z = ankle.z() - (toe.z() - ankle.z()) / 3.0;
    const double margin = 0.008 * H_;
    const Eigen::Vector3d heel_pole(ankle.x(), 0, heel_z - margin),
        toe_pole(toe.x(), 0, toe.z() + margin);
    Part p;
    p.tube.axis = {heel_pole, toe_pole};
    const double length = (toe_pole - heel_pole).norm();
    // The keys below lie at 0.25 to 0.85 of the length.
    p.tube.start_cap = cap(0.018 * H_, length, 0.2);
    p.tube.end_cap = cap(0.022 * H_, length, 0.13);
    const auto row = [&](double s, double half_width, double half_height) {
      return k(s, half_width, half_height, {0, half_height * H_ * girth_, 0}, 3.0);
    };
    p.tube.sections = {
        row(p.tube.start_cap, 0.024, 0.036), row(0.25 * length, 0.027, 0.036),
        row(0.45 * length, 0.030, 0.030),    row(0.68 * length, 0.032, 0.021),
        row(0.85 * length, 0.029, 0.016),    row(length - p.tube.end_cap, 0.024, 0.013)};
    p.tube.segments = 32;
    p.tube.ring_spacing = spacing();
    p.tube.cap_rings = 6;
    const double s_ball = ball.z() - heel_pole.z();
    const int mtp = joint(side + "metatarsophalangeal_2");
    p.labels = {{0, joint(side + "talocrural")}, {s_ball, mtp}};
    p.weights = {{0, joint(side + "talocrural"), 0}, {s_ball, mtp, 0.015 * H_}};
    p.material = [](const Eigen::Vector3d&, double) { return MaterialRegion::shoes; };
    return p;
  }

  const Skeleton& sk_;
  Skeleton reference_;
  HeightMap height_;
  double H_, girth_;
};

// Influences below this are dropped (the largest weight takes up the rest).
constexpr double kNegligibleWeight = 1e-6;

void append_part(const Part& part, BodyMesh& mesh) {
  const TubeSurface tube = build_tube(part.tube);
  std::vector<WeightStation> weights = part.weights;
  limit_blends(weights);
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (size_t i = 0; i < tube.vertices.size(); ++i) {
    const double s = part.coordinate(tube.vertices[i], tube.vertex_s[i]);
    mesh.vertices.push_back(tube.vertices[i].cast<float>());
    mesh.vertex_segment.push_back(static_cast<std::uint16_t>(label_at(part.labels, s)));
    std::array<std::uint16_t, 4> joints{};
    std::array<float, 4> w{};
    int n = 0, largest = 0;
    for (const auto& [j, weight] : weights_at(weights, s)) {
      if (weight < kNegligibleWeight) continue;
      joints[n] = static_cast<std::uint16_t>(j);
      w[n] = static_cast<float>(weight);
      if (w[n] > w[largest]) largest = n;
      ++n;
    }
    // The largest weight absorbs float rounding, so the weights sum to exactly 1 in float.
    float others = 0.0f;
    for (int m = 0; m < n; ++m) {
      if (m != largest) others += w[m];
    }
    w[largest] = 1.0f - others;
    for (int m = n; m < 4; ++m) joints[m] = joints[0];
    mesh.influence_joint.push_back(joints);
    mesh.influence_weight.push_back(w);
  }
  for (const auto& t : tube.triangles) {
    mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    const Eigen::Vector3d centroid =
        (tube.vertices[t[0]] + tube.vertices[t[1]] + tube.vertices[t[2]]) / 3.0;
    const double s = (tube.vertex_s[t[0]] + tube.vertex_s[t[1]] + tube.vertex_s[t[2]]) / 3.0;
    mesh.triangle_material.push_back(part.material(centroid, s));
  }
}

}  // namespace

BodyMesh build_body_mesh(const Skeleton& skeleton, const BodyShape& shape) {
  const BodyPlan plan(skeleton, shape);
  BodyMesh mesh;
  for (const Part& part : plan.parts()) append_part(part, mesh);
  return mesh;
}

}  // namespace simcap
