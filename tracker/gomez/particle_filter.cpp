// The particle filter with heuristics H1-H5 (particle_filter.h).
#include "tracker/gomez/particle_filter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "models/pose.h"
#include "tracker/gomez/nelder_mead.h"
#include "tracker/gomez/root_depth.h"

namespace simcap::tracker::gomez {
namespace {

std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The class most cells of the capsules carried by `joint` have; 0 when none.
std::uint8_t majority_class(const BodyShape& shape, const std::vector<std::uint8_t>& cell_class,
                            int joint) {
  std::array<int, 256> votes{};
  for (size_t c = 0; c < shape.capsules.size(); ++c) {
    if (shape.capsules[c].joint != joint) continue;
    for (int k = 0; k < kCellsPerCapsule; ++k) {
      const size_t cell = c * kCellsPerCapsule + k;
      if (cell < cell_class.size()) ++votes[cell_class[cell]];
    }
  }
  const auto top = std::max_element(votes.begin() + 1, votes.end());
  return *top > 0 ? static_cast<std::uint8_t>(top - votes.begin()) : 0;
}

bool is_arm_chain(const BodyDofs& dofs, int i) {
  const std::string& joint = dofs.skeleton()[dofs[i].joint].name;
  return joint.ends_with("_shoulder") || joint.ends_with("_elbow");
}

}  // namespace

bool h2_diffuses(const Dof& dof, const std::array<bool, kPartCount>& moved) {
  if (moved[static_cast<int>(dof.part)]) return true;
  return dof.translation &&
         (moved[static_cast<int>(Part::left_leg)] || moved[static_cast<int>(Part::right_leg)]);
}

// One random stream per (seed, frame, stream): the filter's result does not depend on which
// thread handled which group.
struct ParticleFilter::Rng {
  Rng(std::uint64_t seed, int frame, std::uint64_t stream)
      : engine(mix(mix(seed) ^ mix(static_cast<std::uint64_t>(frame) + 0x51ed) ^ mix(stream))) {}
  double normal() { return gauss(engine); }
  std::mt19937_64 engine;
  std::normal_distribution<double> gauss;
};

ParticleFilter::ParticleFilter(const PoseScorer& scorer, const ArmKinematics* arms,
                               const FilterOptions& options, const ArmKinematics* legs)
    : scorer_(&scorer),
      arms_(arms),
      legs_(legs),
      mirror_(scorer.dofs()),
      mirror_tells_(tells_front_from_back(scorer.shape(), scorer.cell_class())),
      options_(options) {
  const BodyShape& shape = scorer.shape();
  const Skeleton& skeleton = scorer.dofs().skeleton();
  for (size_t c = 0; c < shape.capsules.size(); ++c) {
    const std::string& joint = skeleton[shape.capsules[c].joint].name;
    if (joint == "l_radiocarpal") hand_capsule_[0] = static_cast<int>(c);
    if (joint == "r_radiocarpal") hand_capsule_[1] = static_cast<int>(c);
    if (joint == "l_talocrural") foot_capsule_[0] = static_cast<int>(c);
    if (joint == "r_talocrural") foot_capsule_[1] = static_cast<int>(c);
    if (shape.capsules[c].front.squaredNorm() > 0) face_capsule_ = static_cast<int>(c);
  }
  const int trunk = skeleton.find("vl5");
  if (hand_capsule_[0] >= 0 && hand_capsule_[1] >= 0 && face_capsule_ >= 0 && trunk >= 0) {
    const auto& cells = scorer.cell_class();
    const std::uint8_t left = majority_class(shape, cells, shape.capsules[hand_capsule_[0]].joint);
    const std::uint8_t right = majority_class(shape, cells, shape.capsules[hand_capsule_[1]].joint);
    if (left == right && left != majority_class(shape, cells, trunk)) hand_class_ = left;
  }
}

std::vector<State> ParticleFilter::hand_proposals(const State& x, const FrameCues& cues) const {
  std::vector<State> out;
  if (!arms_ || hand_class_ == 0 || options_.hand_depths <= 0) return out;
  const BodyDofs& dofs = scorer_->dofs();
  const BodyShape& shape = scorer_->shape();
  const Camera& camera = *cues.view.camera;
  const auto g = forward_kinematics(dofs.skeleton(), dofs.pose(x));
  const Capsule& face = shape.capsules[face_capsule_];
  const Eigen::Vector3d face_centre = g[face.joint] * (0.5 * (face.a + face.b));
  const double face_depth = camera.to_camera(face_centre).z();
  const auto face_px = camera.project(face_centre);
  if (!face_px || face_depth <= 0) return out;
  // The face region's own far ends (the chin, the top of the head) are no hand.
  const double face_radius = 1.5 * camera.K(0, 0) * std::max(face.ra, face.rb) / face_depth;
  std::optional<Eigen::Vector2d> tip[2], shoulder[2];
  double reach_px[2] = {0, 0};
  for (int side = 0; side < 2; ++side) {
    const Capsule& hand = shape.capsules[hand_capsule_[side]];
    tip[side] = camera.project(g[hand.joint] * hand.b);
    const auto base = camera.project(g[hand.joint] * hand.a);
    shoulder[side] = camera.project(arms_->points(x, side).shoulder);
    if (tip[side] && base) reach_px[side] = (*tip[side] - *base).norm();
  }
  if (!shoulder[0] || !shoulder[1]) return out;
  // A hand at the working resolution (the person ~120 px tall) is about 3 x 10 pixels: a region
  // of 3 may be a hand half hidden; more than 4 regions are specks of skin-like colour.
  const std::vector<HandBlob> blobs = hand_blobs(cues, hand_class_, 3, 4);
  // Each region's far end as each arm would reach it; a hand explains it when its tip projects
  // within a hand's length (at least a working pixel) of it.
  std::vector<std::array<Eigen::Vector2d, 2>> ends;
  std::vector<bool> explained;
  bool busy[2] = {false, false};
  for (const HandBlob& b : blobs) {
    std::array<Eigen::Vector2d, 2> end{b.farthest_from(*shoulder[0]),
                                       b.farthest_from(*shoulder[1])};
    bool seen = false;
    for (int side = 0; side < 2; ++side) {
      const double near = std::max(reach_px[side], 1.0 * cues.view.factor);
      if (tip[side] && (*tip[side] - end[side]).norm() <= near) {
        busy[side] = true;
        seen = true;
      }
    }
    ends.push_back(end);
    explained.push_back(seen);
  }
  for (size_t k = 0; k < ends.size(); ++k) {
    if (explained[k]) continue;
    for (int side = 0; side < 2; ++side) {
      if (busy[side] || (ends[k][side] - *face_px).norm() <= face_radius) continue;
      const Capsule& hand = shape.capsules[hand_capsule_[side]];
      for (State& y : arms_->reach_ray(x, side, hand.b, camera.centre(),
                                       camera.unproject(ends[k][side]), options_.hand_depths)) {
        out.push_back(std::move(y));
      }
    }
  }
  return out;
}

std::vector<State> ParticleFilter::limb_end_proposals(const State& x, const FrameCues& cues) const {
  std::vector<State> out;
  if (!arms_ || options_.limb_end_depths <= 0 || face_capsule_ < 0) return out;
  const BodyDofs& dofs = scorer_->dofs();
  const BodyShape& shape = scorer_->shape();
  const Skeleton& skeleton = dofs.skeleton();
  const Camera& camera = *cues.view.camera;
  const auto g = forward_kinematics(skeleton, dofs.pose(x));
  Eigen::Vector3d trunk = Eigen::Vector3d::Zero();
  for (const char* joint : {"l_shoulder", "r_shoulder", "l_hip", "r_hip"}) {
    trunk += 0.25 * g[skeleton.require(joint)].translation();
  }
  const double depth = camera.to_camera(trunk).z();
  const auto trunk_px = camera.project(trunk);
  if (!trunk_px || depth <= 0) return out;
  // Lengths on the body at the trunk's depth, in pixels: a limb end explains an extremity within
  // a hand's length of it, and an extremity is one when it lies at least 0.45 m from the trunk's
  // centre along the silhouette (the shoulders' and hips' corners are nearer; a hand hanging
  // beside the thigh, the head's top are farther).
  const double metre_px = camera.K(0, 0) / depth;
  const double tolerance = 0.15 * metre_px;
  const double min_length = 0.45 * metre_px / cues.view.factor;
  const std::vector<SilhouetteEnd> ends = silhouette_ends(cues, *trunk_px, min_length, 6);
  if (ends.empty()) return out;
  // Predicted ends: the hands, the feet (when the legs can be moved); and what explains an
  // extremity without being moved to one: the elbows, the knees, the head.
  struct Limb {
    const ArmKinematics* kinematics;
    int side;
    int capsule;
  };
  std::vector<PredictedEnd> predicted;
  std::vector<Limb> limbs;
  const auto add = [&](int capsule, const ArmKinematics* kinematics, int side) {
    if (capsule < 0) return;
    const Capsule& c = shape.capsules[capsule];
    const auto px = camera.project(g[c.joint] * c.b);
    if (!px) return;
    predicted.push_back({*px, tolerance, true});
    limbs.push_back({kinematics, side, capsule});
  };
  for (int side = 0; side < 2; ++side) add(hand_capsule_[side], arms_, side);
  for (int side = 0; side < 2; ++side) {
    add(foot_capsule_[side], options_.limb_end_legs ? legs_ : nullptr, side);
  }
  // The elbows and knees explain an extremity at them (a bent arm's elbow sticks out as far as a
  // hand does) and are never moved there.
  for (const char* joint : {"l_elbow", "r_elbow", "l_knee", "r_knee"}) {
    if (const auto px = camera.project(g[skeleton.require(joint)].translation())) {
      predicted.push_back({*px, tolerance, false});
      limbs.push_back({nullptr, 0, -1});
    }
  }
  // The head explains every extremity on it (its top, the chin beside a raised arm) and is never
  // moved: a hand put there matches the face's skin as well as the hand's own.
  const Capsule& head = shape.capsules[face_capsule_];
  const auto head_px = camera.project(g[head.joint] * (0.5 * (head.a + head.b)));
  if (head_px) {
    const double reach = 0.5 * (head.b - head.a).norm() + std::max(head.ra, head.rb);
    predicted.push_back({*head_px, 1.5 * reach * metre_px, false});
    limbs.push_back({nullptr, 0, face_capsule_});
  }
  const std::vector<int> owner = assign_ends(ends, predicted);
  for (size_t k = 0; k < ends.size(); ++k) {
    if (owner[k] < 0) continue;
    const Limb& limb = limbs[owner[k]];
    if (!limb.kinematics) continue;
    const Capsule& c = shape.capsules[limb.capsule];
    const Eigen::Vector3d origin = camera.centre(), ray = camera.unproject(ends[k].pixel);
    // First the end at its present depth (the ray's point nearest it: a foot or hand mostly moves
    // across the ray from one frame to the next), then spread over the ray's stretch it reaches.
    const Eigen::Vector3d now = g[c.joint] * c.b;
    const Eigen::Vector3d near = origin + std::max(0.0, (now - origin).dot(ray)) * ray;
    if (auto y = limb.kinematics->reach_point(x, limb.side, c.b, near)) {
      out.push_back(std::move(*y));
    }
    for (State& y :
         limb.kinematics->reach_ray(x, limb.side, c.b, origin, ray, options_.limb_end_depths - 1)) {
      out.push_back(std::move(y));
    }
  }
  return out;
}

void ParticleFilter::reset(const State& x0, const FrameCues& cues) {
  const Energy e = scorer_->energy_of(x0, cues);
  particles_.assign(std::max(1, options_.particles), x0);
  energies_.assign(particles_.size(), e.total());
  best_ = x0;
  previous_best_ = State();
}

State ParticleFilter::diffuse(const State& x, const std::array<bool, kPartCount>& parts, Rng& rng,
                              const Eigen::Matrix3d& camera_to_world) const {
  const BodyDofs& dofs = scorer_->dofs();
  const bool ee = options_.h5_end_effector && arms_;
  const double S = options_.diffusion;
  State y = x;
  for (int i = 0; i < dofs.size(); ++i) {
    if (!h2_diffuses(dofs[i], parts)) continue;
    if (ee && is_arm_chain(dofs, i)) continue;
    y[i] += S * dofs[i].step * rng.normal();
  }
  y = dofs.clamp(y);
  if (!ee) return y;
  for (int side = 0; side < 2; ++side) {
    const Part arm = side == 0 ? Part::left_arm : Part::right_arm;
    if (!parts[static_cast<int>(arm)]) continue;
    const ArmPoints a = arms_->points(y, side);
    const double swivel = arms_->swivel(a) + S * options_.swivel_sigma * rng.normal();
    // A wrist out of the arm's reach is drawn again (the thesis invalidates it), three times at
    // most; then the arm stays as it was.
    for (int tries = 0; tries < 3; ++tries) {
      const Eigen::Vector3d noise(options_.wrist_sigma_m.x() * rng.normal(),
                                  options_.wrist_sigma_m.y() * rng.normal(),
                                  options_.wrist_sigma_m.z() * rng.normal());
      const Eigen::Vector3d wrist = a.wrist + S * (camera_to_world * noise);
      const auto elbow = arms_->swivel_elbow(a, wrist, swivel);
      if (!elbow) continue;
      arms_->solve(y, side, *elbow, wrist);
      break;
    }
  }
  return y;
}

std::array<double, kPartCount> ParticleFilter::part_overlap(const State& x,
                                                            const FrameCues& cues) const {
  std::array<double, kPartCount> out{};
  LabelImage labels;
  scorer_->render(x, cues.view, labels);
  const double pixel = static_cast<double>(cues.view.factor) * cues.view.factor;
  for (int v = labels.v0; v < labels.v1; ++v) {
    for (int u = labels.u0; u < labels.u1; ++u) {
      const std::uint8_t cell = labels.at(u, v);
      if (cell == kNoCell) continue;
      if (cues.cls_at(u, v) != scorer_->cell_class()[cell]) continue;
      out[static_cast<int>(scorer_->shape().capsules[cell / kCellsPerCapsule].part)] += pixel;
    }
  }
  return out;
}

FilterStep ParticleFilter::step(const FrameCues& previous, const FrameCues& current, int frame) {
  const BodyDofs& dofs = scorer_->dofs();
  const int N = std::max(1, options_.particles), D = dofs.size();
  FilterStep out;
  out.moved.fill(true);
  if (options_.h2_partitioned) {
    // Eq. 4.15: the overlap of each part of the last estimate with its colour class in the last
    // and in this frame's segmented image.
    const std::array<double, kPartCount> before = part_overlap(best_, previous);
    const std::array<double, kPartCount> now = part_overlap(best_, current);
    for (int k = 0; k < kPartCount; ++k) {
      out.moved[k] = before[k] - now[k] >= options_.motion_fraction * before[k];
    }
  }
  // The children move on at the root's last velocity; the elite and the simplices' first vertex
  // stay where their parent was, so that a stop (or a still image) is not overshot. A root that
  // jumped (a depth proposal or a reflection won) does not carry the jump on as a speed: the
  // velocity is held to three typical steps a frame (2.7 m/s at 30 frames/s).
  State velocity = State::Zero(D);
  if (options_.root_velocity && previous_best_.size() == D) {
    for (int i = 0; i < D; ++i) {
      if (dofs[i].translation) {
        velocity[i] = std::clamp(best_[i] - previous_best_[i], -3 * dofs[i].step, 3 * dofs[i].step);
      }
    }
  }
  previous_best_ = best_;
  const Eigen::Matrix3d camera_to_world = current.view.camera->R.transpose();

  // Resampling: children per parent.
  const int P = static_cast<int>(particles_.size());
  const double lowest = *std::min_element(energies_.begin(), energies_.end());
  std::vector<double> w(P);
  for (int i = 0; i < P; ++i) w[i] = std::exp(-(energies_[i] - lowest));
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  std::vector<int> children(P, 0);
  const int elite =
      static_cast<int>(std::min_element(energies_.begin(), energies_.end()) - energies_.begin());
  if (options_.h1_resampling) {
    std::vector<std::pair<double, int>> fraction;
    int given = 0;
    for (int i = 0; i < P; ++i) {
      const double share = N * w[i] / total;
      children[i] = static_cast<int>(std::floor(share));
      given += children[i];
      fraction.emplace_back(share - children[i], i);
    }
    std::stable_sort(fraction.begin(), fraction.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (int k = 0; given < N; ++k, ++given) ++children[fraction[k % P].second];
  } else {
    Rng rng(options_.seed, frame, 0xC0DE);
    std::discrete_distribution<int> pick(w.begin(), w.end());
    for (int k = 0; k < N; ++k) ++children[pick(rng.engine)];
  }
  std::vector<int> parents;
  for (int i = 0; i < P; ++i) {
    if (children[i] > 0) parents.push_back(i);
  }
  out.groups = static_cast<int>(parents.size());

  // Prediction and measurement per group.
  struct Group {
    std::vector<State> x;
    std::vector<Energy> e;
    int evaluations = 0;
    bool simplex = false;
  };
  std::vector<Group> groups(parents.size());
  // The DOFs this frame's diffusion moves: H3's simplices span them.
  std::vector<int> active;
  for (int i = 0; i < D; ++i) {
    if (h2_diffuses(dofs[i], out.moved)) active.push_back(i);
  }
  const int d = static_cast<int>(active.size());
  const auto energy_of = [&](const State& x) { return scorer_->energy_of(x, current); };
  tbb::parallel_for(size_t{0}, parents.size(), [&](size_t g) {
    const int p = parents[g], n = children[p];
    Rng rng(options_.seed, frame, static_cast<std::uint64_t>(p) + 1);
    Group& group = groups[g];
    const State& parent = particles_[p];
    const State moving = dofs.clamp(parent + velocity);
    if (options_.h3_simplex && d > 0 && n >= d + 1) {
      // The simplex spans the DOFs the diffusion moves (its other coordinates are the parent's).
      group.simplex = true;
      const auto embed = [&](const Eigen::VectorXd& z) {
        State x = parent;
        for (int k = 0; k < d; ++k) x[active[k]] = z[k];
        return x;
      };
      const auto project = [&](const State& x) {
        Eigen::VectorXd z(d);
        for (int k = 0; k < d; ++k) z[k] = x[active[k]];
        return z;
      };
      std::vector<Eigen::VectorXd> vertices = {project(parent)};
      for (int k = 0; k < d; ++k) {
        vertices.push_back(project(diffuse(moving, out.moved, rng, camera_to_world)));
      }
      NelderMead nm(
          [&](const Eigen::VectorXd& z) {
            const Energy e = energy_of(embed(z));
            return NelderMead::Terms(e.terms());
          },
          project(dofs.lower()), project(dofs.upper()));
      nm.start(std::move(vertices));
      const int iterations = n - d - 1;
      const int regions = static_cast<int>(std::lround(options_.simplex_region_share * iterations));
      nm.set_weights({1.0, 0.0});
      nm.run(regions);
      nm.set_weights({0.0, 1.0});
      nm.run(iterations - regions);
      // The group: its n best distinct points, by the particle energy.
      const auto& hx = nm.history();
      const auto& ht = nm.history_terms();
      std::vector<int> order(hx.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(),
                       [&](int a, int b) { return ht[a].sum() < ht[b].sum(); });
      for (const int k : order) {
        if (static_cast<int>(group.x.size()) == n) break;
        const State x = embed(hx[k]);
        if (!group.x.empty() && x == group.x.back()) continue;
        group.x.push_back(x);
        group.e.push_back({ht[k][0], ht[k][1]});
      }
      group.evaluations = nm.evaluations();
    } else {
      for (int k = 0; k < n; ++k) {
        const bool keep = options_.h1_resampling && p == elite && k == 0;
        group.x.push_back(keep ? parent : diffuse(moving, out.moved, rng, camera_to_world));
        group.e.push_back(energy_of(group.x.back()));
      }
      group.evaluations = n;
    }
  });

  std::vector<State> pool;
  std::vector<Energy> pool_e;
  for (const Group& g : groups) {
    pool.insert(pool.end(), g.x.begin(), g.x.end());
    pool_e.insert(pool_e.end(), g.e.begin(), g.e.end());
    out.evaluations += g.evaluations;
    out.simplex_groups += g.simplex;
  }

  // Kinematic flipping (H4) and the front/back reflection of the best particle of the largest
  // groups, the hand proposals (H5 from the image) of the best particle of all, and the root
  // depths of the largest groups' best particles.
  const bool flip = options_.h4_flipping && arms_ && options_.flip_groups > 0;
  const bool mirror = mirror_.available() && mirror_tells_ && options_.mirror_groups > 0;
  const bool reach = options_.h5_end_effector && arms_ && hand_class_ != 0 &&
                     options_.hand_depths > 0 && !pool.empty();
  const bool depth = options_.depth_groups > 0;
  const bool ends = arms_ && options_.limb_end_depths > 0 && !pool.empty();
  if (flip || mirror || reach || depth || ends) {
    std::vector<int> by_size(groups.size());
    std::iota(by_size.begin(), by_size.end(), 0);
    std::stable_sort(by_size.begin(), by_size.end(),
                     [&](int a, int b) { return groups[a].x.size() > groups[b].x.size(); });
    const auto group_best = [&](int k) -> const State& {
      const Group& g = groups[by_size[k]];
      return g.x[std::min_element(
                     g.e.begin(), g.e.end(),
                     [](const Energy& a, const Energy& b) { return a.total() < b.total(); }) -
                 g.e.begin()];
    };
    const int G = static_cast<int>(by_size.size());
    std::vector<State> tested;
    const Eigen::Vector3d centre = current.view.camera->centre();
    for (int k = 0; flip && k < std::min(options_.flip_groups, G); ++k) {
      for (State& y : arms_->flips(group_best(k), centre)) tested.push_back(std::move(y));
    }
    const size_t best =
        std::min_element(pool_e.begin(), pool_e.end(),
                         [](const Energy& a, const Energy& b) { return a.total() < b.total(); }) -
        pool_e.begin();
    if (reach) {
      for (State& y : hand_proposals(pool[best], current)) {
        tested.push_back(std::move(y));
        ++out.hand_proposals;
      }
    }
    if (ends) {
      for (State& y : limb_end_proposals(pool[best], current)) {
        tested.push_back(std::move(y));
        ++out.limb_end_proposals;
      }
    }
    out.flips = static_cast<int>(tested.size()) - out.hand_proposals - out.limb_end_proposals;
    const size_t join_freely = tested.size();
    for (int k = 0; mirror && k < std::min(options_.mirror_groups, G); ++k) {
      tested.push_back(mirror_.reflect(group_best(k), centre));
    }
    const size_t reflections = tested.size();
    for (int k = 0; depth && k < std::min(options_.depth_groups, G); ++k) {
      if (auto y = root_depth_proposal(dofs, scorer_->shape(), group_best(k), current)) {
        tested.push_back(std::move(*y));
        ++out.depth_proposals;
      }
    }
    std::vector<Energy> te(tested.size());
    tbb::parallel_for(size_t{0}, tested.size(), [&](size_t i) { te[i] = energy_of(tested[i]); });
    out.evaluations += static_cast<int>(tested.size());
    // A reflection or a slid root joins only when it beats every particle: one close behind would
    // draw children away from the mode the filter follows into a second one the costs cannot
    // tell apart (a crouched body slid in depth against the same body standing).
    double lowest_pool = INFINITY;
    for (const Energy& e : pool_e) lowest_pool = std::min(lowest_pool, e.total());
    for (size_t i = 0; i < tested.size(); ++i) {
      if (i >= join_freely) {
        if (!(te[i].total() < lowest_pool)) continue;
        if (i < reflections) ++out.reflected;
      }
      pool.push_back(std::move(tested[i]));
      pool_e.push_back(te[i]);
    }
  }

  // The N best survive (the thesis drops as many of the worst as flips were added).
  std::vector<int> order(pool.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return pool_e[a].total() < pool_e[b].total(); });
  order.resize(std::min<size_t>(order.size(), N));
  particles_.clear();
  energies_.clear();
  for (const int k : order) {
    particles_.push_back(pool[k]);
    energies_.push_back(pool_e[k].total());
  }
  best_ = particles_.front();
  out.best = best_;

  out.mean = State::Zero(D);
  double wsum = 0;
  for (size_t k = 0; k < particles_.size(); ++k) {
    const double wk = std::exp(-(energies_[k] - energies_.front()));
    out.mean += wk * particles_[k];
    wsum += wk;
  }
  out.mean /= wsum;
  out.energy = pool_e[order.front()];
  const ScoreOptions& so = scorer_->options();
  out.score = {so.sigma_region * std::sqrt(2 * out.energy.region),
               so.sigma_edge_px * std::sqrt(2 * out.energy.edge)};
  return out;
}

}  // namespace simcap::tracker::gomez
