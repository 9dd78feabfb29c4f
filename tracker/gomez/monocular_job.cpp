// The monocular tracker over a dataset and its output files (monocular_job.h).
#include "tracker/gomez/monocular_job.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/joint_track.h"
#include "core/progress.h"
#include "models/bvh_export.h"
#include "models/humanoid.h"
#include "models/mpeg4_bap.h"
#include "tracker/gomez/bap_export.h"
#include "tracker/gomez/body_fit.h"
#include "tracker/gomez/inspection.h"
#include "tracker/gomez/shape_fit.h"
#include "tracker/gomez/upright_start.h"

namespace simcap::tracker {
namespace fs = std::filesystem;
using namespace gomez;

namespace {

// The named joints of one frame of a joint track, or empty when the track lacks the frame.
std::vector<NamedPoint> joints_at(const JointTrack& track, int frame) {
  std::vector<NamedPoint> joints;
  for (size_t k = 0; k < track.frames.size(); ++k) {
    if (track.frames[k] != frame) continue;
    for (size_t j = 0; j < track.joints.size(); ++j) {
      if (std::isfinite(track.positions[k][j].x())) {
        joints.push_back({track.joints[j], track.positions[k][j]});
      }
    }
  }
  return joints;
}

// The first frame's body and pose.
struct Start {
  std::unique_ptr<Body> body;
  State x;
};

Start start_body(const Dataset& dataset, const MonocularOptions& options, int first_frame,
                 const cv::Mat& silhouette) {
  const Camera& camera = dataset.cameras()[options.camera];
  Skeleton skeleton;
  Pose first;
  if (options.init == InitMethod::gt) {
    const std::vector<NamedPoint> joints =
        joints_at(dataset.ground_truth("--init gt"), first_frame);
    if (joints.empty()) {
      throw Error(dataset.ground_truth_path().string() + ": no row for the first frame " +
                  std::to_string(first_frame) + " (needed by --init gt)");
    }
    skeleton = sized_humanoid(joints);
    Pose neutral = Pose::neutral(skeleton);
    const Body full(skeleton, BodyKind::full, neutral, false);
    first = full.dofs.pose(fit_joints(full.dofs, joints, start_from_joints(full.dofs, joints)));
  } else {
    const UprightStart upright = upright_start(camera, silhouette);
    RegistrationOptions fit = options.tracker.registration;
    fit.evaluations = 4 * fit.evaluations;
    fit.simplex_size = 2.0;
    skeleton = upright.skeleton;
    first = fit_silhouette(upright, camera, silhouette, options.tracker.cues, fit);
  }
  Start s;
  ShapeScales scales;
  if (options.tracker.fit_shape)
    scales = fit_shape(skeleton, options.tracker.body, first, camera, silhouette);
  s.body =
      std::make_unique<Body>(skeleton, options.tracker.body, first, options.tracker.floor, scales);
  s.x = s.body->dofs.state_of(first, s.body->dofs.clamp(State::Zero(s.body->dofs.size())));
  return s;
}

}  // namespace

TrackSummary run_monocular(const Dataset& dataset, const MonocularOptions& options, int max_frames,
                           const MonocularSink& sink) {
  if (options.camera < 0 || options.camera >= dataset.camera_count()) {
    throw Error("monocular tracker: camera " + std::to_string(options.camera) +
                " does not exist in " + dataset.root().string() + " (" +
                std::to_string(dataset.camera_count()) + " cameras)");
  }
  const SilhouetteExtractor silhouettes(dataset, options.silhouettes);
  std::vector<int> frames = dataset.frames("rgb");
  if (options.silhouettes == SilhouetteMethod::gt) {
    const std::vector<int> masks = dataset.frames("mask");
    if (masks != frames) {
      throw Error(dataset.root().string() + ": the rgb and mask frames of the cameras differ");
    }
  }
  if (max_frames >= 0 && static_cast<int>(frames.size()) > max_frames) frames.resize(max_frames);
  TrackSummary summary;
  if (frames.empty()) return summary;
  const auto t0 = std::chrono::steady_clock::now();
  const int cam = options.camera;
  cv::Mat image = dataset.rgb(cam, frames[0]);
  cv::Mat mask = silhouettes.extract(cam, frames[0]);
  Start start = start_body(dataset, options, frames[0], mask);
  const State x0 = start.x;
  MonocularTracker tracker(std::move(start.body), x0, dataset.cameras()[cam], image, mask,
                           options.tracker);
  const JointTrack truth = options.oracle ? dataset.ground_truth("--oracle") : JointTrack{};
  State oracle = x0;
  Progress progress("track (monocular)", static_cast<long>(frames.size()), options.quiet);
  for (size_t k = 0; k < frames.size(); ++k) {
    if (k > 0) {
      image = dataset.rgb(cam, frames[k]);
      mask = silhouettes.extract(cam, frames[k]);
    }
    if (options.oracle) {
      const std::vector<NamedPoint> joints = joints_at(truth, frames[k]);
      if (joints.empty()) {
        throw Error(dataset.ground_truth_path().string() + ": no row for frame " +
                    std::to_string(frames[k]) + " (needed by --oracle)");
      }
      oracle = fit_joints(tracker.body().dofs, joints, oracle);
    }
    const TrackedFrame t =
        tracker.track(image, mask, frames[k], options.oracle ? &oracle : nullptr);
    sink(frames[k], t, tracker);
    progress.advance();
  }
  progress.finish();
  summary.frames = static_cast<int>(frames.size());
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

TrackSummary track_monocular(const fs::path& dataset_path, const fs::path& out,
                             const MonocularOptions& options) {
  const Dataset dataset(dataset_path);
  const std::vector<int> all = dataset.frames("rgb");
  for (const int f : options.inspect) {
    if (std::find(all.begin(), all.end(), f) == all.end()) {
      throw Error("--inspect: frame " + std::to_string(f) + " is not in " + dataset_path.string());
    }
  }
  JointTrack track;
  track.joints = he15_joints();
  Motion motion;
  motion.fps = dataset.fps();
  std::vector<int> numbers;
  std::ostringstream frames_csv;
  frames_csv << "frame,region,edge_px,feet_px,evaluations,groups,simplex_groups,flips,reflected,"
                "hand_proposals,depth_proposals,limb_end_proposals,moved_parts,"
                "cues_ms,search_ms"
             << (options.oracle ? ",truth_region,truth_edge_px,truth_feet_px" : "") << "\n";
  std::optional<Skeleton> skeleton;
  std::string body_csv, classes_csv, shading_csv;
  const TrackSummary summary = run_monocular(
      dataset, options, options.max_frames,
      [&](int frame, const TrackedFrame& t, const MonocularTracker& tracker) {
        const Body& body = tracker.body();
        if (!skeleton) {
          skeleton = body.skeleton;
          std::ostringstream b;
          b << "joint,parent,length_m\n";
          for (int j = 1; j < body.skeleton.size(); ++j) {
            b << body.skeleton[j].name << ',' << body.skeleton[body.skeleton[j].parent].name << ','
              << body.skeleton.offset(j).norm() << '\n';
          }
          body_csv = b.str();
          // Which colour cells of which capsule (by the joint carrying it) each class holds, and
          // the class's mean colour and pixels on the first frame.
          std::ostringstream c;
          c << "class,mean_b,mean_g,mean_r,first_frame_pixels,cells\n";
          const ColourClasses& cls = tracker.classes();
          for (int k = 1; k <= cls.count(); ++k) {
            const Eigen::Vector3d& m = cls.class_colour()[k - 1];
            c << k << ',' << std::lround(m[0]) << ',' << std::lround(m[1]) << ','
              << std::lround(m[2]) << ',' << tracker.last_cues().class_area[k] << ',';
            for (size_t cell = 0; cell < cls.cell_class().size(); ++cell) {
              if (cls.cell_class()[cell] != k) continue;
              const Capsule& capsule = body.shape.capsules[cell / kCellsPerCapsule];
              c << body.skeleton[capsule.joint].name << '/' << cell % kCellsPerCapsule << ' ';
            }
            c << '\n';
          }
          classes_csv = c.str();
        }
        const LightFit& light = tracker.light_fit();
        if (shading_csv.empty() && light.lighting.known()) {
          // The light in world coordinates (towards it) and each class's grey line.
          const Eigen::Vector3d l = tracker.camera().R.transpose() * light.lighting.to_light;
          std::ostringstream c;
          c << "frame,light_x,light_y,light_z,rms_grey,pixels,class,albedo,offset\n";
          for (int k = 1; k <= kMaxColourClasses; ++k) {
            if (light.lighting.albedo[k] == 0 && light.lighting.offset[k] == 0) continue;
            c << frame << ',' << l.x() << ',' << l.y() << ',' << l.z() << ',' << light.rms_grey
              << ',' << light.pixels << ',' << k << ',' << light.lighting.albedo[k] << ','
              << light.lighting.offset[k] << '\n';
          }
          shading_csv = c.str();
        }
        const Pose pose = body.dofs.pose(t.output);
        const auto world = joint_positions(body.skeleton, pose);
        std::vector<Eigen::Vector3d> p;
        for (const std::string& name : track.joints)
          p.push_back(world[body.skeleton.require(name)]);
        track.add_frame(frame, std::move(p));
        motion.frames.push_back(pose);
        numbers.push_back(frame);
        std::string moved;
        for (int k = 0; k < kPartCount; ++k) moved += t.filter.moved[k] ? '1' : '0';
        char line[256];
        std::snprintf(line, sizeof line, "%d,%.6f,%.4f,%.4f,%d,%d,%d,%d,%d,%d,%d,%d,%s,%.3f,%.3f\n",
                      frame, t.score.region, t.score.edge, t.score.feet, t.evaluations,
                      t.filter.groups, t.filter.simplex_groups, t.filter.flips, t.filter.reflected,
                      t.filter.hand_proposals, t.filter.depth_proposals,
                      t.filter.limb_end_proposals, moved.c_str(), t.cues_ms, t.search_ms);
        frames_csv << line;
        if (options.oracle) {
          frames_csv.seekp(-1, std::ios_base::cur);
          std::snprintf(line, sizeof line, ",%.6f,%.4f,%.4f\n", t.start_score.region,
                        t.start_score.edge, t.start_score.feet);
          frames_csv << line;
        }
        if (std::find(options.inspect.begin(), options.inspect.end(), frame) !=
            options.inspect.end()) {
          char name[32];
          std::snprintf(name, sizeof name, "%06d.png", frame);
          const fs::path path = out / "diagnostics" / "inspect" / name;
          fs::create_directories(path.parent_path());
          AtomicFile file(path);
          cv::imwrite(file.temp_path().string(),
                      inspection_image(tracker.scorer(), tracker.classes(), tracker.last_cues(),
                                       t.estimate));
          file.commit();
        }
      });
  fs::create_directories(out / "diagnostics");
  write_joint_track(out / "joints3d.csv", track);
  if (skeleton) {
    write_bap(out / "motion.bap", bap_from_motion(*skeleton, motion, numbers, "simcap_monocular"));
    write_bvh(out / "motion.bvh", *skeleton, motion);
  }
  write_text_atomic(out / "diagnostics" / "frames.csv", frames_csv.str());
  write_text_atomic(out / "diagnostics" / "body.csv", body_csv);
  write_text_atomic(out / "diagnostics" / "colour_classes.csv", classes_csv);
  if (!shading_csv.empty()) write_text_atomic(out / "diagnostics" / "shading.csv", shading_csv);
  TrackSummary s = summary;
  s.track = out;
  return s;
}

}  // namespace simcap::tracker
