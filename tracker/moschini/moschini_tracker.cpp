#include "tracker/moschini/moschini_tracker.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <span>

#include "core/error.h"

namespace simcap::tracker {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

MoschiniTracker::MoschiniTracker(const BodyDimensions& dims, const BodySurface& surface,
                                 const TrackerOptions& options)
    : model_(dims, options.joints, options.urdf_limits),
      surface_(surface),
      options_(options),
      icp_(model_, surface, options.icp),
      refiner_(model_, surface, options.icp.refine),
      polisher_(model_, surface, options.polish),
      silhouette_starter_(model_, surface, options.silhouette_start),
      arm_searcher_(model_, surface, options.unexplained.restart),
      filter_(model_, options.filter) {}

IcpTargets MoschiniTracker::targets_of(const Observation& obs) {
  IcpTargets t;
  t.points = obs.points;
  t.hull = &obs.hull;
  t.rays = obs.rays;
  t.views = &obs.views;
  return t;
}

void MoschiniTracker::start(const StickPose& pose) {
  pose_ = pose;
  filter_.reset(pose);
  started_ = true;
  lost_streak_ = 0;
  patience_ = options_.recovery.lost_frames;
  unexplained_wait_ = 0;
  unexplained_backoff_ = 1;
}

double MoschiniTracker::outside_fraction(const StickPose& pose, const Occupancy& hull) const {
  if (hull.count == 0) return 1.0;
  const StickGeometry g = model_.geometry(pose);
  const double step = hull.grid.voxel;
  int total = 0, outside = 0;
  for (int s = 0; s < kSegmentCount; ++s) {
    const Eigen::Vector3d ab = g.distal[s] - g.proximal[s];
    const int n = std::max(1, static_cast<int>(ab.norm() / step));
    for (int i = 0; i <= n; ++i) {
      ++total;
      if (!hull.occupied_near(g.proximal[s] + ab * (static_cast<double>(i) / n), 1)) ++outside;
    }
  }
  return static_cast<double>(outside) / total;
}

double MoschiniTracker::score(const StickPose& pose, const Observation& obs) const {
  return refiner_.cost(targets_of(obs), pose);
}

double MoschiniTracker::silhouette_score(const StickPose& pose, const Observation& obs) const {
  return polisher_.cost(targets_of(obs), pose);
}

void MoschiniTracker::diagnose(const StickPose& pose, const Observation& obs,
                               TrackStep& out) const {
  out.icp = icp_.evaluate(obs.points, pose);
  out.outside_fraction = outside_fraction(pose, obs.hull);
}

StickPose MoschiniTracker::best_upright(const Observation& obs, const StickPose* current) const {
  const IcpTargets targets = targets_of(obs);
  struct Fit {
    double score;
    StickPose pose;
  };
  std::vector<Fit> fits;
  for (StickPose& c : upright_hypotheses(model_, upright_cue(obs.hull, model_.dimensions()),
                                         options_.recovery.headings)) {
    icp_.fit(targets, c);
    fits.push_back({score(c, obs), c});
  }
  std::stable_sort(fits.begin(), fits.end(),
                   [](const Fit& a, const Fit& b) { return a.score < b.score; });
  const double current_score = current ? score(*current, obs) : 0.0;
  Fit best = current ? Fit{options_.recovery.margin * current_score, *current}
                     : Fit{std::numeric_limits<double>::infinity(), {}};
  for (size_t i = 0; i < fits.size(); ++i) {
    if (static_cast<int>(i) < options_.recovery.searched &&
        (!current || fits[i].score < options_.recovery.search_within * current_score)) {
      fits[i].score = search_limbs(targets, fits[i].pose, fits[i].score);
    }
    if (fits[i].score < best.score) best = fits[i];
  }
  if (current && options_.trust_silhouettes &&
      !(silhouette_score(best.pose, obs) <
        options_.recovery.margin * silhouette_score(*current, obs))) {
    return *current;
  }
  return best.pose;
}

double MoschiniTracker::search_limbs(const IcpTargets& targets, StickPose& pose,
                                     std::optional<double> cost, const PoseRefiner* by,
                                     unsigned which) const {
  const PoseRefiner& refiner = by ? *by : refiner_;
  struct Limb {
    std::array<int, 4> angles;  // -1: unused
    double mirror;              // sign of the abduction and twist: 1 on the left, -1 on the right
    bool arm;
  };
  static constexpr std::array<Limb, 4> limbs = {{
      {{kLShoulder1, kLShoulder2, kLShoulder3, kLElbow}, 1.0, true},
      {{kRShoulder1, kRShoulder2, kRShoulder3, kRElbow}, -1.0, true},
      {{kLHip1, kLHip2, kLKnee, -1}, 1.0, false},
      {{kRHip1, kRHip2, kRKnee, -1}, -1.0, false},
  }};
  // Left limbs' angles (abduction, flexion, twist, elbow; abduction, flexion, knee).
  static constexpr std::array<std::array<double, 4>, 5> arms = {{{0.15, 0.0, 0.0, -0.2},
                                                                 {0.2, -0.5, 0.3, -1.5},
                                                                 {0.1, -0.3, 0.8, -1.8},
                                                                 {0.2, 0.4, 0.0, -0.3},
                                                                 {0.2, -1.2, 0.0, -0.5}}};
  static constexpr std::array<std::array<double, 4>, 4> legs = {
      {{0.0, 0.0, 0.0, 0.0}, {0.0, -0.4, 0.3, 0.0}, {0.0, 0.3, 0.2, 0.0}, {0.0, -0.2, 0.8, 0.0}}};
  const auto& ranges = model_.ranges();
  double best = cost ? *cost : refiner.cost(targets, pose);
  for (size_t l = 0; l < limbs.size(); ++l) {
    const Limb& limb = limbs[l];
    if (!(which >> l & 1)) continue;
    const StickPose base = pose;
    const auto configurations = limb.arm ? std::span<const std::array<double, 4>>(arms)
                                         : std::span<const std::array<double, 4>>(legs);
    for (const auto& angles : configurations) {
      StickPose trial = base;
      for (int i = 0; i < 4 && limb.angles[i] >= 0; ++i) {
        // Abduction (first) and an arm's twist (third) turn the other way on the right.
        const double sign = i == 0 || (limb.arm && i == 2) ? limb.mirror : 1.0;
        trial.theta[limb.angles[i]] = limit_angle(sign * angles[i], ranges[limb.angles[i]]);
      }
      refiner.refine(targets, trial);
      const double c = refiner.cost(targets, trial);
      if (c < best) best = c, pose = trial;
    }
  }
  return best;
}

namespace {
constexpr double kSwapWorthRefining = 1.5;
}  // namespace

void MoschiniTracker::resolve_swapped_limbs(const IcpTargets& targets, StickPose& pose,
                                            bool every_pair) const {
  struct Pair {
    std::array<int, 2> ends;                  // left distal reference points of the pair
    std::vector<std::pair<int, int>> angles;  // left/right angles exchanged
  };
  const std::array<Pair, 2> pairs = {{
      {{kLAnklePoint, kLKneePoint},
       {{kLHip1, kRHip1},
        {kLHip2, kRHip2},
        {kLHipTwist, kRHipTwist},
        {kLKnee, kRKnee},
        {kLAnkle, kRAnkle}}},
      {{kLHandTip, kLElbowPoint},
       {{kLShoulder1, kRShoulder1},
        {kLShoulder2, kRShoulder2},
        {kLShoulder3, kRShoulder3},
        {kLElbow, kRElbow},
        {kLWristFlexion, kRWristFlexion},
        {kLWristDeviation, kRWristDeviation}}},
  }};
  const double margin = 0.03;
  const auto& ranges = model_.ranges();
  std::optional<double> current;  // cost of `pose`, once asked for (it is not cheap)
  for (const Pair& pair : pairs) {
    const auto r = model_.reference_points(model_.geometry(pose));
    // The right-side reference point always follows its left one in ReferencePoint.
    auto lateral = [&](int i) { return pose.R0.col(0).dot(r[i] - pose.t0); };
    const bool crossed = lateral(pair.ends[0]) < lateral(pair.ends[0] + 1) - margin ||
                         lateral(pair.ends[1]) < lateral(pair.ends[1] + 1) - margin;
    if (!crossed && !every_pair) continue;
    StickPose swapped = pose;
    for (const auto& [left, right] : pair.angles) {
      if (right >= model_.angle_count()) continue;
      std::swap(swapped.theta[left], swapped.theta[right]);
      swapped.theta[left] = limit_angle(swapped.theta[left], ranges[left]);
      swapped.theta[right] = limit_angle(swapped.theta[right], ranges[right]);
    }
    if (!current) current = refiner_.cost(targets, pose);
    // An uncrossed pair is only worth a refinement when the plain exchange already fits nearly
    // as well: a right fit's exchange costs several times more, a swapped one's less.
    if (!crossed && refiner_.cost(targets, swapped) > kSwapWorthRefining * *current) continue;
    refiner_.refine(targets, swapped);
    const double swapped_cost = refiner_.cost(targets, swapped);
    if (swapped_cost < *current) pose = swapped, current = swapped_cost;
  }
}

StickPose MoschiniTracker::fit_hypothesis(const Observation& obs, StickPose pose) const {
  const IcpTargets targets = targets_of(obs);
  icp_.fit(targets, pose);
  search_limbs(targets, pose);
  return pose;
}

StickPose MoschiniTracker::fit_hypothesis_to_silhouettes(const Observation& obs,
                                                         StickPose pose) const {
  const IcpTargets targets = targets_of(obs);
  polisher_.refine(targets, pose);
  search_limbs(targets, pose, {}, &polisher_);
  return pose;
}

void MoschiniTracker::start_upright(const Observation& obs) {
  if (obs.points.empty()) {
    throw Error(
        "frame " + std::to_string(obs.frame) +
        ": --init auto found no body in the hull (is the person inside the working volume?)");
  }
  start(best_upright(obs, nullptr));
}

bool MoschiniTracker::leaves_silhouette_unexplained(const IcpTargets& targets,
                                                    const StickPose& pose) const {
  const int every = options_.unexplained.ray_every;
  std::vector<int> rays, missed;
  for (size_t i = 0; i < targets.rays.size(); i += every) {
    const int c = targets.rays[i].camera;
    if (c < 0) continue;
    if (c >= static_cast<int>(rays.size())) rays.resize(c + 1, 0), missed.resize(c + 1, 0);
    ++rays[c];
  }
  for (const int i : polisher_.missed_rays(targets, pose, options_.unexplained.miss_m, every)) {
    if (targets.rays[i].camera >= 0) ++missed[targets.rays[i].camera];
  }
  int cameras = 0;
  for (size_t c = 0; c < rays.size(); ++c) {
    cameras += missed[c] > 0 && missed[c] >= options_.unexplained.fraction * rays[c];
  }
  return cameras >= options_.unexplained.cameras;
}

TrackStep MoschiniTracker::step(const Observation& obs) {
  if (!started_) throw Error("tracker: step() before start()");
  using Clock = std::chrono::steady_clock;
  TrackStep out;
  auto t = Clock::now();
  StickPose measured = pose_;
  if (!obs.points.empty()) {
    IcpTargets targets = targets_of(obs);
    const StickPose prediction = pose_;
    targets.prediction = &prediction;
    // The joint refinement from the previous pose, which cannot be led astray by a limb whose
    // centroids merged with another part's; with TrackerOptions::traversal also Moschini's
    // traversal, which can jump to where the centerline now is.
    if (options_.traversal) {
      StickPose traversed = measured;
      icp_.fit(targets, traversed);
      refiner_.refine(targets, measured);
      if (refiner_.cost(targets, traversed) < refiner_.cost(targets, measured))
        measured = traversed;
    } else {
      refiner_.refine(targets, measured);
    }
    const int every = options_.swap_check_every;
    resolve_swapped_limbs(targets, measured, every > 0 && steps_++ % every == 0);
    polisher_.refine(targets, measured);
    // Not with other people about: the silhouettes alone cannot tell whose pixels they are (the
    // hull the person gate cut to the tracked person's components can).
    if (options_.trust_silhouettes && options_.silhouette_start.iterations > 0 &&
        obs.cover.empty()) {
      StickPose still = pose_;
      silhouette_starter_.refine(targets, still);
      if (polisher_.cost(targets, still) < polisher_.cost(targets, measured)) measured = still;
    }
    // Only where the silhouettes are the person's alone, as for the silhouette start, and show
    // all of it: behind the scene's occluders the restarts put arms where no camera sees them.
    const UnexplainedOptions& unexplained = options_.unexplained;
    if (options_.trust_silhouettes && obs.cover.empty() && !obs.widened &&
        unexplained.fraction > 0 && --unexplained_wait_ <= 0) {
      if (!leaves_silhouette_unexplained(targets, measured)) {
        unexplained_backoff_ = 1;
      } else {
        StickPose searched = measured;
        const double kept = arm_searcher_.cost(targets, searched);
        bool found =
            search_limbs(targets, searched, kept, &arm_searcher_, kLeftArm | kRightArm) < kept;
        if (found) {
          polisher_.refine(targets, searched);
          found = polisher_.cost(targets, searched) < polisher_.cost(targets, measured);
          if (found) measured = searched;
        }
        // What a search cannot explain (a silhouette too noisy, an arm held where no restart
        // reaches) is likely still there next frame: the next search waits longer each time.
        unexplained_backoff_ = found ? 1 : std::min(2 * unexplained_backoff_, unexplained.max_wait);
        unexplained_wait_ = unexplained_backoff_;
      }
    }
    diagnose(measured, obs, out);
    const RecoveryOptions& rec = options_.recovery;
    char why[96] = "";
    if (out.icp.mean_distance_m > rec.lost_distance_m &&
        out.outside_fraction >= rec.lost_distance_outside) {
      std::snprintf(why, sizeof why, "icp residual %.0f mm", out.icp.mean_distance_m * 1000);
    } else if (out.outside_fraction > rec.lost_outside_fraction) {
      std::snprintf(why, sizeof why, "%.0f%% of the model off the hull",
                    out.outside_fraction * 100);
    }
    lost_streak_ = why[0] ? lost_streak_ + 1 : 0;
    if (!why[0]) patience_ = rec.lost_frames;
    if (lost_streak_ >= patience_) {
      lost_streak_ = 0;
      patience_ = std::min(2 * patience_, rec.max_lost_frames);
      const StickPose found = best_upright(obs, &measured);
      if (found.t0 != measured.t0 || found.R0 != measured.R0 || found.theta != measured.theta) {
        out.reinitialized = true;
        out.reason = why;
        ++reinitializations_;
        measured = found;
        filter_.reset(found);
        diagnose(measured, obs, out);
      }
    }
  }
  out.icp_ms = ms_since(t);
  t = Clock::now();
  if (!options_.use_filter || out.reinitialized) {
    pose_ = measured;
    if (options_.use_filter) filter_.reset(measured);
  } else {
    filter_.predict();
    if (!obs.points.empty()) {
      filter_.correct(model_.reference_points(model_.geometry(measured)));
    }
    pose_ = filter_.pose();
  }
  out.filter_ms = ms_since(t);
  out.pose = pose_;
  return out;
}

}  // namespace simcap::tracker
