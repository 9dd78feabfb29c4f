#include "tracker/moschini/moschini_job.h"

#include <tbb/parallel_pipeline.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <opencv2/core/utility.hpp>
#include <optional>

#include "core/angle_track.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/joint_track.h"
#include "core/progress.h"
#include "models/humanoid.h"
#include "models/shipped_assets.h"
#include "models/urdf_io.h"
#include "tracker/common/dataset.h"
#include "tracker/moschini/auto_start.h"
#include "tracker/moschini/inspection.h"
#include "tracker/moschini/pose_init.h"
#include "tracker/moschini/shoulder_height.h"
#include "tracker/moschini/surface_fit.h"
#include "tracker/moschini/track_back.h"

namespace simcap::tracker {
namespace fs = std::filesystem;

namespace {

// The URDF whose limits the urdf joint set takes, or empty for the shipped ones.
std::filesystem::path limits_file(const Dataset& ds, const MoschiniOptions& options) {
  if (!options.limits.empty()) {
    if (options.joints == JointSet::moschini) {
      throw Error("--limits " + options.limits.string() +
                  ": the moschini joint set keeps Table 5.1's limits; use --joints urdf");
    }
    return options.limits;
  }
  const std::optional<std::string> text = ds.actor_limits();
  if (!text || options.joints == JointSet::moschini) return {};
  return resolve_asset_path(*text, ds.root());
}

// The hull's working volume: the room from scene.yaml kept 10 cm off the walls and below
// 2.3 m (no one is taller), else Moschini-sized defaults around the origin.
Eigen::AlignedBox3d working_volume(const Dataset& ds) {
  const auto room = ds.room();
  if (!room) return HullOptions{}.volume;
  Eigen::Vector3d lo = room->min(), hi = room->max();
  lo.x() += 0.1, lo.z() += 0.1, hi.x() -= 0.1, hi.z() -= 0.1;
  hi.y() = std::min(hi.y(), 2.3);
  return {lo, hi};
}

// How many first frames --init auto measures the body on.
constexpr int kStartFrames = 5;
// The frame (counted from the first) at whose tracked pose --init auto fits the capsules and
// the centerline's offsets again and from then on trusts the silhouettes, as --init gt does
// from the first frame (MOSCHINI.md, "`--init auto` now"): 3 and 5 did worse on main's start.
constexpr int kRefitFrame = 4;
// --init auto measures the shoulders' height again with the arms refitted on kShoulderFrames
// tracked frames, every kShoulderEvery after the refit (frames 8 to 28: by then the arms have
// moved), and takes it when it differs by at least kShoulderMinChange (half the grid's step: a
// smaller change is within the measurement's noise, and every restart moves a walk's course);
// kShoulderMeasures times in all (frames 32 to 52 next: the trunk the first change moved now
// holds the arms).
constexpr int kShoulderEvery = 4;
constexpr int kShoulderFrames = 6;
constexpr int kShoulderMeasures = 2;
constexpr double kShoulderMinChange = 0.025;
// --init auto among others with silhouettes that show everyone: the silhouette pixels this close
// to the person's own mask are theirs (background subtraction's outline differs from the
// rendered one by a few pixels: shadows, the clean-up's closing).
constexpr int kPointReachPx = 6;

// The lower ankle's height at `pose`.
double ankle_of(const StickModel& model, const StickPose& pose) {
  const StickGeometry g = model.geometry(pose);
  return std::min(g.distal[kLCalf].y(), g.distal[kRCalf].y());
}

// `dims` scaled about the torso's centroid so that a foot under it sinks by `by` metres (rises
// when negative), by at most a tenth of the reach. At the refit --init auto makes the body the
// one that puts the lowest ankle of the frames so far where it stands on the floor: the
// silhouettes' proportions search leaves the stature 2-4% short, the feet afloat (MOSCHINI.md).
BodyDimensions larger(BodyDimensions dims, double by) {
  const double reach = dims.torso_half + dims.thigh + dims.calf;
  const double factor = 1 + std::clamp(by, -0.1 * reach, 0.1 * reach) / reach;
  for (double* length :
       {&dims.torso_half, &dims.spine_pivot, &dims.shoulder_half, &dims.shoulder_forward,
        &dims.hip_forward, &dims.head, &dims.upper_arm, &dims.forearm, &dims.hand, &dims.thigh,
        &dims.calf, &dims.foot, &dims.root_above_hips, &dims.root_forward})
    *length *= factor;
  return dims;
}

// Restarts `tracker` from the last of `frames` with the shoulders' height its arms measure
// (shoulder_height.h), when it differs from the tracked body's by kShoulderMinChange or more;
// returns the pose it restarted from.
std::optional<StickPose> remeasure_shoulders(std::optional<MoschiniTracker>& tracker,
                                             const TrackerOptions& options,
                                             const std::vector<TrackedObservation>& frames) {
  BodyDimensions dims = tracker->model().dimensions();
  const BodySurface surface = tracker->surface();
  const AutoStartOptions range;
  const ShoulderHeight found = shoulders_from_arms(
      dims, surface, options, frames, range.shoulders_lo, range.shoulders_hi, range.evaluations);
  if (std::abs(found.d_s - dims.d_s) < kShoulderMinChange) return std::nullopt;
  dims.d_s = found.d_s;
  tracker.emplace(dims, surface, options);
  tracker->start(found.last);
  return found.last;
}

// What the output (MoschiniSink) writes of an observation whose output waits: the hull's cells,
// the rays, views and images are dropped.
std::shared_ptr<const Observation> written_part(const Observation& obs) {
  auto part = std::make_shared<Observation>();
  part->frame = obs.frame;
  part->hull.count = obs.hull.count;
  part->centerline = obs.centerline;
  part->points = obs.points;
  part->gate = obs.gate;
  part->silhouette_iou = obs.silhouette_iou;
  part->silhouettes_ms = obs.silhouettes_ms;
  part->hull_ms = obs.hull_ms;
  part->centerline_ms = obs.centerline_ms;
  return part;
}

}  // namespace

TrackSummary run_moschini(const fs::path& dataset_path, const MoschiniOptions& options,
                          int max_frames, const MoschiniSink& sink) {
  const Dataset ds(dataset_path, options.actor);
  const SilhouetteMethod method = options.silhouettes;
  PerceptionOptions popt;
  popt.hull.voxel_m = options.voxel_m;
  popt.hull.volume = working_volume(ds);
  popt.colours = options.appearance;
  // Silhouettes that show everyone: the others' pixels next to the person become cover.
  popt.gate.others_to_cover = method != SilhouetteMethod::gt;
  Perception perception(ds, method, popt);
  std::vector<int> frames = ds.frames(perception.silhouettes().image_kind());
  if (popt.colours && perception.silhouettes().image_kind() != "rgb") {
    const std::string hint =
        " (--appearance reads a colour image with every mask; --appearance off tracks on the "
        "masks alone)";
    std::vector<int> colour;
    try {
      colour = ds.frames("rgb");
    } catch (const Error& e) {
      throw Error(std::string(e.what()) + hint);
    }
    if (colour != frames)
      throw Error(dataset_path.string() + ": rgb and mask frames differ" + hint);
  }
  if (max_frames >= 0 && static_cast<int>(frames.size()) > max_frames) frames.resize(max_frames);
  for (const int f : options.inspect) {
    if (std::find(frames.begin(), frames.end(), f) == frames.end()) {
      throw Error("--inspect: frame " + std::to_string(f) + " is not in " + dataset_path.string() +
                  (frames.empty() ? std::string(" (no frames)")
                                  : " (frames " + std::to_string(frames.front()) + " to " +
                                        std::to_string(frames.back()) + ")"));
    }
  }
  const bool compare_masks =
      method != SilhouetteMethod::gt && fs::is_directory(ds.root() / ds.cameras()[0].name / "mask");

  TrackerOptions topt;
  topt.joints = options.joints;
  if (const std::filesystem::path limits = limits_file(ds, options); !limits.empty()) {
    topt.urdf_limits = read_urdf_limits(limits, build_humanoid());
    try {
      StickModel(BodyDimensions{}, topt.joints, topt.urdf_limits);
    } catch (const Error& e) {
      throw_input_error(limits, 0, "", e.what());
    }
  }
  topt.use_filter = options.filter == MotionFilter::ekf;
  topt.traversal = options.traversal;
  std::optional<MoschiniTracker> tracker;
  // --init auto: the frame at which the tracker restarts with capsules fitted to its own pose.
  std::optional<int> refit_frame;
  // --init auto: the lowest ankle of the frames up to the refit, and where it should stand.
  double lowest_ankle = std::numeric_limits<double>::infinity(), ankle_height = 0;
  // Where the tracked body was last: the gate keeps that person's part of the silhouettes
  // when someone else is in view too (person_gate.h). It runs only when the capture has other
  // people (scene.yaml's actors, the capture's metadata like its room): alone, a person's hull
  // is all theirs, and a fast jump that outruns the last pose would lose limbs to the gate
  // (jumps 32.8 -> 68.2 mm on stress/motions.yaml).
  const bool others = ds.actors().size() > 1;
  std::optional<PlacedSurface> last_body;
  // Where the others were, in the gate's voxels (GateResult::others), when the silhouettes
  // show them.
  std::vector<Eigen::Vector3d> others_before;
  // Where scene objects hide the person, learned as tracking goes (occlusion_map.h).
  std::optional<OcclusionMap> occlusion;
  if (options.occlusion) {
    std::vector<cv::Mat> plates;
    for (int c = 0; c < ds.camera_count(); ++c)
      plates.push_back(ds.has_background(c) ? ds.background(c) : cv::Mat());
    occlusion.emplace(ds.cameras(), plates);
  }
  // The parts the first frame hides from a camera, told at once by the first pose.
  auto learn_occlusion = [&](const StickModel& model, const StickPose& pose, Observation& obs) {
    if (!occlusion) return;
    occlusion->observe(place(typical_surface(model.dimensions()), model.geometry(pose)),
                       obs.silhouettes);
    perception.widen(obs, *occlusion);
  };
  // Who wears what, learned on the first frame. Background subtraction shows everyone: the
  // person's colours are learned in the views where no one else touches them, and the others'
  // from their pixels (`dropped`).
  auto learn_colours = [&](const StickModel& model, const BodySurface& surface,
                           const StickPose& pose, const Observation& obs,
                           const std::vector<cv::Mat>& dropped) {
    if (!popt.colours) return;
    const bool mixed = others && method != SilhouetteMethod::gt;
    AppearanceModel appearance(model, surface, pose,
                               mixed ? perception.rays_apart(obs, dropped) : obs.rays);
    if (mixed) appearance.learn_others(perception.colours_under(obs.frame, dropped));
    perception.set_appearance(appearance);
  };
  if (options.init == InitMethod::gt) {
    // The first frame's joints give the sticks and the pose; its silhouettes the capsules, and
    // where the hull's centerline runs relative to the trunk's and head's joint lines.
    const JointTrack gt = ds.ground_truth("--init gt");
    const std::string source = ds.ground_truth_path().string();
    const NamedJoints joints = joints_at(gt, frames.front(), source);
    BodyDimensions dims = dimensions_from_joints(joints, source);
    const StickModel plain(dims, topt.joints, topt.urdf_limits);
    const StickPose start = pose_from_joints(plain, joints, source);
    Observation first = perception.observe(frames.front());
    std::vector<cv::Mat> dropped;  // the others' pixels, when someone else is in view
    if (others) {
      perception.isolate(first, place(typical_surface(dims), plain.geometry(start)), &dropped);
      others_before = first.gate.others;
    }
    learn_occlusion(plain, start, first);
    const FittedBody body = fit_body(dims, topt, start, first);
    dims = body.dims;
    const BodySurface& surface = body.surface;
    learn_colours(plain, surface, start, first, dropped);
    tracker.emplace(dims, surface, topt);
    tracker->start(start);
    last_body = place(surface, plain.geometry(start));
  } else {
    // Assumption: in the first frames the person stands upright on the floor (auto_start.h).
    // The capsules are fitted at a guessed first pose: their silhouette cost cannot overrule
    // the centerline (TrackerOptions::trust_silhouettes) until the refit at kRefitFrame.
    topt.trust_silhouettes = false;
    std::vector<Observation> first;
    for (int i = 0; i < std::min<int>(kStartFrames, static_cast<int>(frames.size())); ++i) {
      Observation obs = perception.observe(frames[i]);
      // Silhouettes that show everyone: the person's own mask says which of them to start on.
      if (others && method != SilhouetteMethod::gt) perception.point_at_person(obs, kPointReachPx);
      perception.abstain_until_seen(obs);
      first.push_back(std::move(obs));
    }
    AutoStart start;
    try {
      start = auto_start(first, topt);
    } catch (const Error& e) {
      throw Error(dataset_path.string() + ": " + e.what());
    }
    const StickModel model(start.dims, topt.joints, topt.urdf_limits);
    learn_occlusion(model, start.pose, first.front());
    // The capsules are fitted to the first pose; the tracker restarts with them.
    const BodySurface surface = fit_surface(model, start.pose, typical_surface(start.dims),
                                            first.front().rays, first.front().views);
    // The pixels the person's mask did not point at are the others'.
    learn_colours(model, surface, start.pose, first.front(), first.front().cover);
    tracker.emplace(start.dims, surface, topt);
    tracker->start(start.pose);
    last_body = place(surface, model.geometry(start.pose));
    // Alone in view only: with others about, the silhouettes hold their pixels too.
    if (!others && static_cast<int>(frames.size()) > kRefitFrame) refit_frame = frames[kRefitFrame];
    ankle_height = start.ankle_height;
  }

  // Frames are observed in parallel; OpenCV's own worker threads inside each would only compete
  // for the same cores.
  const int opencv_threads = cv::getNumThreads();
  cv::setNumThreads(1);
  struct RestoreThreads {
    int n;
    ~RestoreThreads() { cv::setNumThreads(n); }
  } restore{opencv_threads};
  std::optional<JointTrack> truth;
  if (options.oracle) truth = ds.ground_truth("--oracle");
  Progress progress("track", static_cast<long>(frames.size()), options.quiet);
  const auto t0 = std::chrono::steady_clock::now();
  size_t next = 0;
  // --init auto: the frames after the refit the shoulders' height is measured again on, how
  // often it was, and the index of the frame being tracked.
  std::vector<TrackedObservation> shoulder_frames;
  int shoulder_measures = 0, index = -1;
  // --init auto, alone in view: every frame's output waits until the sequence's end, when the
  // frames are tracked again backwards with the final body (track_back.h).
  const bool holding = refit_frame.has_value() && !truth;
  struct HeldFrame {
    std::shared_ptr<const Observation> obs;
    TrackStep step;
  };
  std::vector<HeldFrame> held;
  tbb::parallel_pipeline(
      8, tbb::make_filter<void, int>(tbb::filter_mode::serial_in_order,
                                     [&](tbb::flow_control& fc) {
                                       if (next >= frames.size()) {
                                         fc.stop();
                                         return 0;
                                       }
                                       return frames[next++];
                                     }) &
             tbb::make_filter<int, std::shared_ptr<Observation>>(
                 tbb::filter_mode::parallel,
                 [&](int frame) {
                   return std::make_shared<Observation>(perception.observe(frame, compare_masks));
                 }) &
             tbb::make_filter<std::shared_ptr<Observation>, void>(
                 tbb::filter_mode::serial_in_order, [&](const std::shared_ptr<Observation>& obs) {
                   if (truth) {
                     const std::string source = ds.ground_truth_path().string();
                     tracker->start(pose_from_joints(
                         tracker->model(), joints_at(*truth, obs->frame, source), source));
                   }
                   if (others) {
                     perception.isolate(*obs, *last_body, nullptr, &others_before);
                     others_before = std::move(obs->gate.others);
                   }
                   if (occlusion) perception.widen(*obs, *occlusion);
                   const TrackStep step = tracker->step(*obs);
                   last_body = place(tracker->surface(), tracker->model().geometry(step.pose));
                   if (occlusion) occlusion->observe(*last_body, obs->silhouettes);
                   if (holding) {
                     const bool inspected =
                         std::find(options.inspect.begin(), options.inspect.end(), obs->frame) !=
                         options.inspect.end();
                     held.push_back({inspected ? obs : written_part(*obs), step});
                   } else {
                     sink(ds, *obs, step, *tracker);
                   }
                   if (refit_frame && obs->frame <= *refit_frame)
                     lowest_ankle = std::min(lowest_ankle, ankle_of(tracker->model(), step.pose));
                   ++index;
                   if (refit_frame && index > kRefitFrame &&
                       (index - kRefitFrame) % kShoulderEvery == 0 &&
                       shoulder_measures < kShoulderMeasures) {
                     shoulder_frames.push_back({obs, step.pose});
                     if (static_cast<int>(shoulder_frames.size()) == kShoulderFrames) {
                       const std::optional<StickPose> restart =
                           remeasure_shoulders(tracker, topt, shoulder_frames);
                       // Tracked back from where the tracker goes on.
                       if (restart && holding) held.back().step.pose = *restart;
                       shoulder_frames.clear();
                       ++shoulder_measures;
                     }
                   }
                   if (obs->frame == refit_frame) {
                     // The pose tracked from a right start is near enough the truth for the
                     // capsules and the offsets that --init gt measures on its first frame.
                     const BodyDimensions dims =
                         larger(tracker->model().dimensions(), lowest_ankle - ankle_height);
                     const FittedBody body = fit_body(dims, topt, step.pose, *obs);
                     topt.trust_silhouettes = true;
                     tracker.emplace(body.dims, body.surface, topt);
                     tracker->start(step.pose);
                   }
                   progress.advance();
                 }));
  // Before the refit the body is the start's guess: nothing better to track them with.
  if (holding && index > kRefitFrame) {
    // Each frame observed again: holding them all would take ~1.2 MB a frame.
    TrackBack back(tracker->model().dimensions(), tracker->surface(), topt, held.back().step.pose);
    size_t back_next = held.size();
    tbb::parallel_pipeline(
        8, tbb::make_filter<void, size_t>(tbb::filter_mode::serial_in_order,
                                          [&](tbb::flow_control& fc) {
                                            if (back_next == 0) {
                                              fc.stop();
                                              return size_t{0};
                                            }
                                            return --back_next;
                                          }) &
               tbb::make_filter<size_t, std::pair<size_t, std::shared_ptr<Observation>>>(
                   tbb::filter_mode::parallel,
                   [&](size_t i) {
                     return std::pair{
                         i, std::make_shared<Observation>(perception.observe(held[i].obs->frame))};
                   }) &
               tbb::make_filter<std::pair<size_t, std::shared_ptr<Observation>>, void>(
                   tbb::filter_mode::serial_in_order,
                   [&](const std::pair<size_t, std::shared_ptr<Observation>>& frame) {
                     if (occlusion) perception.widen(*frame.second, *occlusion);
                     back.step(*frame.second, held[frame.first].step);
                   }));
  }
  for (const HeldFrame& frame : held) sink(ds, *frame.obs, frame.step, *tracker);
  progress.finish();
  TrackSummary summary;
  summary.frames = static_cast<int>(frames.size());
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  summary.reinitializations = tracker->reinitializations();
  return summary;
}

TrackSummary track_moschini(const fs::path& dataset, const fs::path& out,
                            const MoschiniOptions& options) {
  if (!(options.voxel_m > 0)) throw Error("--voxel: must be positive");
  const fs::path diag = out / "diagnostics";
  fs::create_directories(diag);
  JointTrack track;
  track.joints = he15_joints();
  AngleTrack angles;
  angles.joints = rotation_joints();
  CsvWriter centerline(diag / "centerline.csv", {"frame", "axis", "x", "y", "z", "voxels"});
  CsvWriter timings(diag / "timings.csv",
                    {"frame", "silhouettes_ms", "hull_ms", "centerline_ms", "icp_ms", "filter_ms",
                     "voxels", "points", "icp_residual_mm", "inlier_fraction", "outside_fraction",
                     "hull_components", "dropped_voxels"});
  CsvWriter reinit(diag / "reinitializations.csv", {"frame", "reason"});
  std::optional<CsvWriter> iou;
  std::optional<BodyDimensions> dims;
  std::optional<BodySurface> surface;
  char buf[256];
  int without_person = 0, first_without_person = -1;
  const TrackSummary run = run_moschini(
      dataset, options, options.max_frames,
      [&](const Dataset& ds, const Observation& obs, const TrackStep& step,
          const MoschiniTracker& tracker) {
        // The last body tracked with: --init auto measures it again after the start.
        dims = tracker.model().dimensions(), surface = tracker.surface();
        track.add_frame(obs.frame, tracker.model().he15(step.pose));
        angles.add_frame(obs.frame, tracker.model().joint_rotations(step.pose));
        for (const CenterlinePoint& p : obs.centerline) {
          std::snprintf(buf, sizeof buf, "%d,%c,%.4f,%.4f,%.4f,%d\n", obs.frame, "xyz"[p.axis],
                        p.position.x(), p.position.y(), p.position.z(), p.voxels);
          centerline.out() << buf;
        }
        std::snprintf(buf, sizeof buf, "%d,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%zu,%.1f,%.3f,%.3f,%d,%d\n",
                      obs.frame, obs.silhouettes_ms, obs.hull_ms, obs.centerline_ms, step.icp_ms,
                      step.filter_ms, obs.hull.count, obs.points.size(),
                      step.icp.mean_distance_m * 1000, step.icp.inlier_fraction,
                      step.outside_fraction, obs.gate.components, obs.gate.dropped_voxels);
        timings.out() << buf;
        if (obs.hull.count == 0 && without_person++ == 0) first_without_person = obs.frame;
        if (step.reinitialized) reinit.out() << obs.frame << "," << step.reason << "\n";
        if (std::find(options.inspect.begin(), options.inspect.end(), obs.frame) !=
            options.inspect.end()) {
          std::snprintf(buf, sizeof buf, "%06d", obs.frame);
          write_inspection(diag / "inspect" / buf, ds, obs, tracker, step.pose);
        }
        if (!obs.silhouette_iou.empty()) {
          if (!iou)
            iou.emplace(diag / "silhouette_iou.csv",
                        std::vector<std::string>{"frame", "camera", "iou"});
          for (size_t c = 0; c < obs.silhouette_iou.size(); ++c) {
            std::snprintf(buf, sizeof buf, "%d,%zu,%.4f\n", obs.frame, c, obs.silhouette_iou[c]);
            iou->out() << buf;
          }
        }
      });
  CsvWriter body(diag / "body_dimensions.csv", {"dimension", "value"});
  const std::pair<const char*, double> values[] = {
      {"torso_half", dims->torso_half},
      {"spine_pivot", dims->spine_pivot},
      {"shoulder_half", dims->shoulder_half},
      {"d_s", dims->d_s},
      {"d_h", dims->d_h},
      {"head", dims->head},
      {"upper_arm", dims->upper_arm},
      {"forearm", dims->forearm},
      {"hand", dims->hand},
      {"thigh", dims->thigh},
      {"calf", dims->calf},
      {"foot", dims->foot},
      {"foot_pitch", dims->foot_pitch},
      {"root_above_hips", dims->root_above_hips},
      {"root_forward", dims->root_forward},
      {"skullbase_fraction", dims->skullbase_fraction}};
  for (const auto& [name, value] : values) {
    std::snprintf(buf, sizeof buf, "%s,%.5f\n", name, value);
    body.out() << buf;
  }
  for (int c = 0; c < kCapsuleCount; ++c) {
    const std::string name(capsule_name(c));
    for (const auto& [end, radius] : {std::pair{"a", (*surface)[c].ra}, {"b", (*surface)[c].rb}}) {
      std::snprintf(buf, sizeof buf, "capsule_%s_radius_%s,%.5f\n", name.c_str(), end, radius);
      body.out() << buf;
    }
  }
  body.commit();
  centerline.commit();
  timings.commit();
  reinit.commit();
  if (iou) iou->commit();
  write_joint_track(out / "joints3d.csv", track);
  write_angle_track(out / "angles.csv", angles);
  TrackSummary summary = run;
  summary.frames_without_person = without_person;
  summary.first_frame_without_person = first_without_person;
  summary.track = out;
  return summary;
}

}  // namespace simcap::tracker
