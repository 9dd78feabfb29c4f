#include "tracker/triangulate/triangulate_job.h"

#include <tbb/parallel_for.h>
#include <Eigen/Dense>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/progress.h"
#include "tracker/triangulate/bone_lengths.h"
#include "tracker/triangulate/butterworth.h"
#include "tracker/triangulate/hanim_joints.h"
#include "tracker/triangulate/rts_smoother.h"
#include "tracker/triangulate/unseen_keypoints.h"

namespace simcap::tracker {
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
using Keypoints3d = std::vector<std::optional<Eigen::Vector3d>>;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::vector<PersonKeypoints> people_of(const std::vector<DetectedPerson>& detected) {
  std::vector<PersonKeypoints> out;
  out.reserve(detected.size());
  for (const DetectedPerson& d : detected) {
    PersonKeypoints p;
    p.keypoints.reserve(d.keypoints.size());
    for (const DetectedKeypoint& k : d.keypoints) p.keypoints.emplace_back(k.x, k.y, k.score);
    out.push_back(std::move(p));
  }
  return out;
}

// Where the ground truth's first frame puts the layout's joint keypoints in every camera: the
// expectation that picks the actor out of several people.
std::vector<PersonKeypoints> truth_expectation(const Dataset& ds, const KeypointLayout& layout,
                                               const JointTrack& truth) {
  std::vector<PersonKeypoints> out(ds.cameras().size());
  if (truth.frames.empty()) return out;
  for (size_t c = 0; c < out.size(); ++c) {
    out[c].keypoints.assign(layout.size(), Eigen::Vector3d::Zero());
    for (int k = 0; k < layout.size(); ++k) {
      const LayoutKeypoint& kp = layout.keypoints[k];
      if (kp.truth != TruthKind::hanim_joint) continue;
      const int j = truth.joint_index(std::string(kp.truth_name));
      if (j < 0 || !truth.positions[0][j].allFinite()) continue;
      if (const auto p = ds.cameras()[c].project(truth.positions[0][j])) {
        out[c].keypoints[k] << *p, 1.0;
      }
    }
  }
  return out;
}

// Each keypoint's pixel noise (σ², px²) pooled over the take from its reprojection residuals;
// keypoints with fewer than 20 degrees of freedom take the pool of all keypoints. Never below
// (0.05 px)²: exact detections would otherwise claim exact points.
std::vector<double> pixel_variances(const std::vector<TriangulatedPose>& poses, int keypoints) {
  std::vector<double> sum(keypoints + 1, 0.0), dof(keypoints + 1, 0.0);
  for (const TriangulatedPose& pose : poses) {
    for (int k = 0; k < keypoints; ++k) {
      const auto& p = pose.keypoints[k];
      const int d = p ? 2 * std::popcount(p->views) - 3 : 0;
      if (d <= 0) continue;
      for (const int i : {k, keypoints}) {
        sum[i] += p->squared_error_px2;
        dof[i] += d;
      }
    }
  }
  constexpr double kFloor = 0.05 * 0.05;
  const double pooled = dof[keypoints] > 0 ? std::max(kFloor, sum[keypoints] / dof[keypoints]) : 1;
  std::vector<double> out(keypoints, pooled);
  for (int k = 0; k < keypoints; ++k) {
    if (dof[k] >= 20) out[k] = std::max(kFloor, sum[k] / dof[k]);
  }
  return out;
}

// The Kalman/RTS smoother on every keypoint; gaps are smoothed through.
void smooth_kalman(std::vector<Keypoints3d>& frames,
                   const std::vector<std::vector<Eigen::Matrix3d>>& information,
                   const std::vector<double>& pixel_variance, double fps) {
  if (frames.empty()) return;
  tbb::parallel_for(size_t{0}, frames[0].size(), [&](size_t k) {
    std::vector<std::optional<PointMeasurement>> z(frames.size());
    for (size_t f = 0; f < frames.size(); ++f) {
      const Eigen::LDLT<Eigen::Matrix3d> ldlt(information[f][k]);
      if (!frames[f][k] || ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) {
        continue;
      }
      z[f] = PointMeasurement{*frames[f][k],
                              pixel_variance[k] * ldlt.solve(Eigen::Matrix3d::Identity())};
    }
    const SmoothedTrack t = rts_smooth_ml(z, 1.0 / fps);
    for (size_t f = 0; f < t.points.size(); ++f) frames[f][k] = t.points[f].position;
  });
}

// Interior gaps filled linearly (Pose2Sim interpolates them too), the ends held; then the
// optional low-pass. Returns how many values were filled.
int smooth(std::vector<Keypoints3d>& frames, const TriangulateOptions& o, double fps) {
  if (frames.empty()) return 0;
  int filled = 0;
  const std::optional<Biquad> filter =
      o.filter == TemporalFilter::butterworth
          ? std::optional<Biquad>(butterworth_lowpass(o.cutoff_hz, fps))
          : std::nullopt;
  for (size_t k = 0; k < frames[0].size(); ++k) {
    std::vector<int> known;
    for (size_t f = 0; f < frames.size(); ++f) {
      if (frames[f][k]) known.push_back(static_cast<int>(f));
    }
    if (known.empty()) continue;
    for (size_t f = 0; f < frames.size(); ++f) {
      if (frames[f][k]) continue;
      const auto next = std::lower_bound(known.begin(), known.end(), static_cast<int>(f));
      if (next == known.begin()) {
        frames[f][k] = frames[known.front()][k];
      } else if (next == known.end()) {
        frames[f][k] = frames[known.back()][k];
      } else {
        const int a = *(next - 1), b = *next;
        const double t = (static_cast<double>(f) - a) / (b - a);
        frames[f][k] = (1 - t) * *frames[a][k] + t * *frames[b][k];
      }
      ++filled;
    }
    if (!filter) continue;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> x(frames.size());
      for (size_t f = 0; f < frames.size(); ++f) x[f] = (*frames[f][k])[axis];
      const std::vector<double> y = filtfilt(*filter, x);
      for (size_t f = 0; f < frames.size(); ++f) (*frames[f][k])[axis] = y[f];
    }
  }
  return filled;
}

const char* kind_name(AssociationKind k) {
  switch (k) {
    case AssociationKind::tracked:
      return "tracked";
    case AssociationKind::joined:
      return "joined";
    case AssociationKind::seeded:
      return "seeded";
    case AssociationKind::none:
      break;
  }
  return "none";
}

}  // namespace

TriangulationResult run_triangulation(const Dataset& ds, const TriangulateOptions& o) {
  if (o.detections.empty()) {
    throw Error(
        "--method triangulate needs --detections FILE (COCO keypoint results JSON, an "
        "OpenPose output folder or a CSV; see simcap track --help)");
  }
  TriangulationResult result;
  auto t0 = Clock::now();
  std::vector<int> frame_numbers = ds.frames("rgb");
  if (o.max_frames >= 0 && static_cast<int>(frame_numbers.size()) > o.max_frames) {
    frame_numbers.resize(o.max_frames);
  }
  std::vector<std::string> names;
  for (const Camera& c : ds.cameras()) names.push_back(c.name);
  const int frame_count = frame_numbers.empty() ? 0 : frame_numbers.back() + 1;
  const Detections detections = read_detections(o.detections, names, frame_count, o.layout);
  const KeypointLayout& layout = keypoint_layout(detections.layout());
  HAnimJoints hanim(layout);
  const JointTrack truth = o.init == InitMethod::gt
                               ? ds.ground_truth("--init gt (the actor and the body's proportions)")
                               : JointTrack{};
  if (!truth.frames.empty()) hanim.calibrate(layout, truth, 0);
  result.stages.read_s = since(t0);

  // Sequential: which person is the actor in each camera, following each camera's choice from
  // frame to frame (people_association.h).
  t0 = Clock::now();
  const size_t n = frame_numbers.size(), cameras = names.size();
  std::vector<std::vector<std::vector<PersonKeypoints>>> people(n);
  std::vector<Association> chosen(n);
  std::vector<PersonKeypoints> expected = o.init == InitMethod::gt
                                              ? truth_expectation(ds, layout, truth)
                                              : std::vector<PersonKeypoints>(cameras);
  std::ostringstream people_csv;
  people_csv << "frame,camera,people,person,how,cost_px\n";
  for (size_t f = 0; f < n; ++f) {
    people[f].resize(cameras);
    for (size_t c = 0; c < cameras; ++c) {
      people[f][c] = people_of(detections.at(frame_numbers[f], static_cast<int>(c)));
    }
    chosen[f] = associate_people(ds.cameras(), people[f], expected, o.association);
    for (size_t c = 0; c < cameras; ++c) {
      const int p = chosen[f].person[c];
      expected[c] = p >= 0 ? people[f][c][p] : PersonKeypoints{};
      if (people[f][c].size() < 2 && chosen[f].kind[c] == AssociationKind::tracked) continue;
      people_csv << frame_numbers[f] << ',' << names[c] << ',' << people[f][c].size() << ',' << p
                 << ',' << kind_name(chosen[f].kind[c]) << ',';
      if (p >= 0) people_csv << chosen[f].cost[c];
      people_csv << '\n';
    }
  }
  result.people = people_csv.str();
  result.stages.associate_s = since(t0);

  // Parallel over frames: each frame's keypoints triangulated on its own.
  t0 = Clock::now();
  std::vector<int> partner(layout.size());
  for (int k = 0; k < layout.size(); ++k) partner[k] = layout.keypoints[k].partner;
  std::vector<TriangulatedPose> poses(n);
  Progress progress("triangulate", static_cast<long>(n), o.quiet);
  tbb::parallel_for(size_t{0}, n, [&](size_t f) {
    std::vector<const PersonKeypoints*> views(cameras, nullptr);
    for (size_t c = 0; c < cameras; ++c) {
      if (chosen[f].person[c] >= 0) views[c] = &people[f][c][chosen[f].person[c]];
    }
    poses[f] = triangulate_pose(ds.cameras(), views, partner, layout.size(), o.triangulation);
    progress.advance();
  });
  progress.finish();
  result.stages.triangulate_s = since(t0);

  t0 = Clock::now();
  std::ostringstream keypoints_csv, swaps_csv;
  keypoints_csv << "frame,keypoint,views,excluded,max_error_px\n";
  swaps_csv << "frame,camera,keypoint,partner\n";
  std::vector<Keypoints3d> positions(n, Keypoints3d(layout.size()));
  std::vector<std::vector<Eigen::Matrix3d>> information(
      n, std::vector<Eigen::Matrix3d>(layout.size(), Eigen::Matrix3d::Zero()));
  for (size_t f = 0; f < n; ++f) {
    for (int k = 0; k < layout.size(); ++k) {
      const auto& p = poses[f].keypoints[k];
      keypoints_csv << frame_numbers[f] << ',' << layout.keypoints[k].name << ',';
      if (p) {
        positions[f][k] = p->position;
        information[f][k] = p->information;
        keypoints_csv << std::popcount(p->views) << ',' << p->excluded << ',' << p->max_error_px;
        result.views_excluded += p->excluded;
      } else {
        keypoints_csv << "0,,";
        ++result.keypoints_missing;
      }
      keypoints_csv << '\n';
    }
    for (const SwapFix& s : poses[f].swaps) {
      swaps_csv << frame_numbers[f] << ',' << names[s.camera] << ','
                << layout.keypoints[s.keypoint].name << ','
                << layout.keypoints[partner[s.keypoint]].name << '\n';
    }
    result.swaps_repaired += static_cast<int>(poses[f].swaps.size());
  }
  if (o.bone_lengths) {
    std::vector<Bone> bones = rigid_bones(layout);
    measure_bone_lengths(bones, positions);
    tbb::parallel_for(size_t{0}, n,
                      [&](size_t f) { project_onto_bones(positions[f], information[f], bones); });
  }
  if (o.filter == TemporalFilter::kalman) {
    smooth_kalman(positions, information, pixel_variances(poses, layout.size()), ds.fps());
  } else {
    smooth(positions, o, ds.fps());
  }
  for (const int k : place_unseen_keypoints(positions, layout)) {
    result.unseen.emplace_back(layout.keypoints[k].name);
  }
  result.track.joints = hanim.joints();
  for (size_t f = 0; f < n; ++f)
    result.track.add_frame(frame_numbers[f], hanim.place(positions[f]));
  result.stages.smooth_s = since(t0);
  result.keypoints = keypoints_csv.str();
  result.swaps = swaps_csv.str();
  result.frames = static_cast<int>(n);
  return result;
}

TrackSummary track_triangulate(const fs::path& dataset, const fs::path& out,
                               const TriangulateOptions& options) {
  const auto t0 = Clock::now();
  const Dataset ds(dataset, options.actor);
  const TriangulationResult r = run_triangulation(ds, options);
  write_joint_track(out / "joints3d.csv", r.track);
  write_text_atomic(out / "diagnostics" / "people.csv", r.people);
  write_text_atomic(out / "diagnostics" / "keypoints.csv", r.keypoints);
  write_text_atomic(out / "diagnostics" / "swaps.csv", r.swaps);
  if (!options.quiet) {
    std::fprintf(stderr,
                 "triangulate: %d frames, %d left/right swaps repaired, %d views excluded, %d "
                 "keypoints missing (filled over time)\n",
                 r.frames, r.swaps_repaired, r.views_excluded, r.keypoints_missing);
    if (!r.unseen.empty()) {
      std::string names;
      for (const std::string& k : r.unseen) names += (names.empty() ? "" : ", ") + k;
      std::fprintf(stderr,
                   "triangulate: never seen by two views, placed from the reference body: %s\n",
                   names.c_str());
    }
  }
  TrackSummary summary;
  summary.frames = r.frames;
  summary.seconds = since(t0);
  return summary;
}

}  // namespace simcap::tracker
