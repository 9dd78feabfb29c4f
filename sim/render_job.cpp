#include "sim/render_job.h"

#include <OpenImageIO/imageio.h>
#include <assimp/version.h>
#include <embree3/rtcore.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_pipeline.h>
#include <oneapi/tbb/version.h>

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <opencv2/core/version.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/progress.h"
#include "core/stale_temporaries.h"
#include "scenes/scene.h"
#include "sim/calibration_error.h"
#include "sim/dataset_writer.h"
#include "sim/ground_truth.h"
#include "sim/render_setup.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;
using Json = nlohmann::ordered_json;

// Frames in flight between rendering, image writing and the truth tables; each holds its
// images (~11 MB for four VGA cameras), so this bounds memory.
constexpr int kFramesInFlight = 4;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::vector<std::string> camera_names(const Scene& scene) {
  std::vector<std::string> names;
  for (const Camera& c : scene.cameras) names.push_back(c.name);
  return names;
}

// Keeps the cameras named in `wanted`, in the rig's order.
void select_cameras(Scene& scene, const std::vector<std::string>& wanted) {
  const std::vector<std::string> all = camera_names(scene);
  for (size_t i = 0; i < wanted.size(); ++i) {
    if (std::find(all.begin(), all.end(), wanted[i]) == all.end()) {
      throw Error("--cameras: the scene has no camera '" + wanted[i] + "'; its cameras are " +
                  join(all));
    }
    if (std::find(wanted.begin(), wanted.begin() + i, wanted[i]) != wanted.begin() + i) {
      throw Error("--cameras: " + wanted[i] + " is listed twice");
    }
  }
  // Per-camera settings listed in rig order follow their cameras.
  std::vector<double> offsets;
  for (size_t c = 0; c < scene.timing.offset_ms.size(); ++c) {
    if (std::find(wanted.begin(), wanted.end(), all[c]) != wanted.end()) {
      offsets.push_back(scene.timing.offset_ms[c]);
    }
  }
  scene.timing.offset_ms = offsets;
  std::erase_if(scene.cameras, [&](const Camera& c) {
    return std::find(wanted.begin(), wanted.end(), c.name) == wanted.end();
  });
}

}  // namespace

Scene load_for_render(const fs::path& scene_file, const RenderOptions& options) {
  if (!fs::exists(scene_file)) throw Error(scene_file.string() + ": scene file not found");
  Scene scene = load_scene(scene_file, options.overrides);
  if (options.seed) scene.render.seed = *options.seed;
  resolve_seeded_choices(scene);
  if (!options.motion_override.empty()) {
    if (!fs::is_regular_file(options.motion_override)) {
      throw Error(options.motion_override.string() + ": motion file not found (--motion)");
    }
    if (scene.actors.empty()) throw Error("--motion: the scene has no actor to move");
    MotionSource source;
    if (options.motion_asf.empty()) {
      source.bvh = fs::absolute(options.motion_override);
    } else {
      source.amc = fs::absolute(options.motion_override);
      source.asf = fs::absolute(options.motion_asf);
    }
    scene.actors[0].motion = source;
  }
  if (options.frames == 0 || options.frames < -1) {
    throw Error("--frames: expected a positive number of frames, got " +
                std::to_string(options.frames));
  }
  if (options.frames > limits::kMaxFrames) {
    throw Error("--frames: " + std::to_string(options.frames) +
                " is more than simcap's largest frame count, " +
                std::to_string(limits::kMaxFrames));
  }
  if (options.frames > 0) scene.render.frame_count = options.frames;
  if (!options.cameras.empty()) select_cameras(scene, options.cameras);
  return scene;
}

namespace {

// A simcap dataset announces itself by a meta.json with simcap's version in it.
bool holds_dataset(const fs::path& dir) {
  try {
    const Json meta = Json::parse(read_text(dir / "meta.json"));
    return meta.contains("simcap_version");
  } catch (const std::exception&) {
    return false;
  }
}

// The cameras the meta.json of the dataset in `dir` lists.
std::vector<std::string> dataset_cameras(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& cam : Json::parse(read_text(dir / "meta.json")).value("cameras", Json::array()))
    names.push_back(cam.get<std::string>());
  return names;
}

void remove_dataset(const fs::path& dir) {
  std::vector<std::string> entries = {"scene.yaml", "parts.json", "calibration", "background",
                                      "gt"};
  for (const auto& cam : dataset_cameras(dir)) entries.push_back(cam);
  entries.push_back("meta.json");
  for (const auto& e : entries) {
    std::error_code ec;
    fs::remove_all(dir / e, ec);
    if (ec) throw Error((dir / e).string() + ": cannot remove: " + ec.message());
  }
}

// What a render killed before it wrote scene.yaml leaves: folders, temporaries and at most a
// meta.json saying "complete": false. --resume starts such a folder afresh.
bool only_a_started_render(const fs::path& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_directory() || is_temporary_file_name(entry.path())) continue;
    if (entry.path() != dir / "meta.json" || !holds_dataset(dir)) return false;
  }
  return !fs::exists(dir / "meta.json") ||
         !Json::parse(read_text(dir / "meta.json")).value("complete", true);
}

// Checks what is in `out_dir` against the options before anything is written.
void prepare_output(const fs::path& out_dir, const Scene& scene, const RenderOptions& options) {
  std::error_code ec;
  if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec)) {
    throw Error(out_dir.string() + ": output exists and is not a folder");
  }
  const bool empty = !fs::exists(out_dir, ec) || fs::is_empty(out_dir, ec) ||
                     (options.resume && only_a_started_render(out_dir));
  if (!empty && options.resume) {
    if (!holds_dataset(out_dir) || !fs::exists(out_dir / "scene.yaml")) {
      throw Error(out_dir.string() + ": --resume: the folder holds no simcap dataset");
    }
    const std::vector<std::string> existing = dataset_cameras(out_dir);
    if (existing != camera_names(scene)) {
      throw Error(out_dir.string() + ": --resume: the dataset there has the cameras " +
                  join(existing) + ", this render has " + join(camera_names(scene)) +
                  " (--cameras must select the same ones)");
    }
    // The same scene writes the same scene.yaml; only the frame count may grow.
    Scene candidate = scene;
    candidate.render.frame_count = load_scene(out_dir / "scene.yaml").render.frame_count;
    if (read_text(out_dir / "scene.yaml") != scene_to_yaml(candidate)) {
      throw Error(out_dir.string() +
                  ": --resume: the dataset there was rendered from a different scene "
                  "(compare its scene.yaml); render into a new folder or use --overwrite");
    }
  } else if (!empty && options.overwrite) {
    if (!holds_dataset(out_dir)) {
      throw Error(out_dir.string() +
                  ": --overwrite: the folder is not empty and holds no simcap dataset "
                  "(no meta.json); refusing to delete anything");
    }
    remove_dataset(out_dir);
  } else if (!empty) {
    throw Error(out_dir.string() +
                ": output folder is not empty; use --resume to continue the render there, "
                "--overwrite to replace it, or choose another folder");
  }
  fs::create_directories(out_dir, ec);
  if (ec) throw Error(out_dir.string() + ": cannot create the output folder: " + ec.message());
}

Json library_versions() {
  Json v;
  v["embree"] = RTC_VERSION_STRING;
  v["openimageio"] = OIIO_VERSION_STRING;
  v["assimp"] = std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) +
                "." + std::to_string(aiGetVersionPatch());
  v["opencv"] = CV_VERSION;
  v["eigen"] = std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
               "." + std::to_string(EIGEN_MINOR_VERSION);
  v["onetbb"] = TBB_runtime_version();
  v["nlohmann_json"] = std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                       std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                       std::to_string(NLOHMANN_JSON_VERSION_PATCH);
  return v;
}

// meta.json's "calibration_error": the error's settings and each camera's exact perturbation.
Json describe_calibration_error(const std::vector<Camera>& cameras, const CalibrationError& error) {
  Json j;
  j["rotation_deg"] = error.rotation_deg;
  j["translation_m"] = error.translation_m;
  j["focal_rel"] = error.focal_rel;
  j["principal_px"] = error.principal_px;
  j["seed"] = error.seed;
  j["meaning"] =
      "calibration/ holds each camera perturbed as listed; gt/calibration.yaml the cameras the "
      "images were rendered with. R_written = AngleAxis(rotation_deg, rotation_axis_camera) * "
      "R_true, centre_written = centre_true + centre_shift_m, fx and fy times focal_scale, "
      "(cx, cy) plus principal_shift_px; distortion unchanged";
  Json per_camera;
  for (const Camera& c : cameras) {
    const CameraPerturbation p = camera_perturbation(error, c.name);
    per_camera[c.name] = {
        {"rotation_axis_camera", {p.rotation_axis.x(), p.rotation_axis.y(), p.rotation_axis.z()}},
        {"rotation_deg", p.rotation_deg},
        {"centre_shift_m", {p.centre_shift_m.x(), p.centre_shift_m.y(), p.centre_shift_m.z()}},
        {"focal_scale", p.focal_scale},
        {"principal_shift_px", {p.principal_shift_px.x(), p.principal_shift_px.y()}}};
  }
  j["cameras"] = per_camera;
  return j;
}

// meta.json's "capture": when each camera captured and for how long, when any of it differs
// from every camera capturing every row at the frame's time in an instant.
Json describe_capture(const Scene& scene, const CaptureClock& clock) {
  Json c;
  Json offsets;
  for (size_t i = 0; i < scene.cameras.size(); ++i) {
    offsets[scene.cameras[i].name] = 1e3 * clock.offset_s(static_cast<int>(i));
  }
  c["offset_ms"] = offsets;
  c["readout_ms"] = 1e3 * clock.readout_s();
  c["shutter"] = scene.render.shutter;
  c["exposure_ms"] = 1e3 * clock.exposure_s();
  c["time"] =
      "row r of camera c in dataset frame i is captured, the middle of its exposure, at "
      "(first_frame + i) / fps + offset_c + readout * r / (height - 1); lights change between "
      "frames, each camera seeing them as at (first_frame + i) / fps + offset_c";
  c["joints2d"] =
      "each joint (and its depth) where it was when the row it lands on was captured: t = frame "
      "time + offset_c + readout * clamp(v, 0, height - 1) / (height - 1); visibility traces that "
      "pixel's ray at its row's time";
  c["joints3d"] = "at the frame's nominal time (first_frame + i) / fps, like angles.csv";
  c["blur"] =
      "with exposure_ms > 0, rgb averages samples_per_pixel samples, one in each of as many "
      "equal parts of each row's exposure (t -+ exposure / 2): the ray through the pixel centre "
      "at the exposure's middle t in the central part, rays jittered over the pixel and within "
      "their part in the others (the R3 sequence, shifted per pixel); depth, mask, parts and "
      "normal are that centre ray's, as the 2D truth";
  return c;
}

Json describe(const Scene& scene, const fs::path& scene_file, const std::vector<PosedActor>& actors,
              const CaptureClock& clock) {
  Json meta;
  meta["simcap_version"] = SIMCAP_VERSION;
  meta["libraries"] = library_versions();
  meta["scene_file"] = fs::absolute(scene_file).lexically_normal().string();
  meta["seed"] = scene.render.seed;
  meta["fps"] = scene.render.fps;
  meta["first_frame"] = scene.render.first_frame;
  meta["frame_count"] = scene.render.frame_count;
  meta["samples_per_pixel"] = scene.render.samples_per_pixel;
  meta["cameras"] = camera_names(scene);
  Json names = Json::array();
  for (const PosedActor& a : actors) names.push_back(a.name);
  meta["actors"] = names;
  meta["conventions"] = {
      {"frames", "dataset frame i shows scene time (first_frame + i) / fps"},
      {"rgb", "8-bit sRGB PNG, Lambert shading in linear light"},
      {"depth",
       "float32 EXR, z-depth in metres (camera-frame z of the "
       "surface, not the distance along the ray); +inf where the ray hits nothing"},
      {"mask", actors.size() == 1 ? "8-bit PNG, 255 = the actor, 0 = anything else"
                                  : "8-bit PNG, 1 + actor index (order of 'actors'), 0 = no actor"},
      {"parts", "8-bit PNG, see parts.json"},
      {"joints",
       "H-Anim joint centres (end sites excluded); actors after the first are "
       "prefixed '<actor>/'"},
      {"visibility",
       "ray through the joint's pixel centre; occluded when a surface lies more "
       "than visibility_tolerance_m (z-depth) in front of the joint"},
      {"visibility_tolerance_m", kVisibilityTolerance},
      {"angles",
       "local joint rotation relative to the neutral pose in the parent's frame, "
       "unit quaternion with qw >= 0"}};
  if (!clock.still()) meta["capture"] = describe_capture(scene, clock);
  if (scene.timing.auto_exposure) {
    meta["auto_exposure"] =
        "each image's colour is scaled by the mean linear luminance of its camera's background "
        "plate over its own before encoding";
  }
  if (scene.calibration_error.any()) {
    meta["calibration_error"] = describe_calibration_error(scene.cameras, scene.calibration_error);
  }
  return meta;
}

}  // namespace

RenderSummary render_dataset(const fs::path& scene_file, const fs::path& out_dir,
                             const RenderOptions& options) {
  const auto start = Clock::now();
  Scene scene = load_for_render(scene_file, options);
  RenderSetup setup(scene);
  const int frames =
      scene.render.frame_count > 0 ? scene.render.frame_count : setup.actors().frames_available();
  scene.render.frame_count = frames;
  const auto chunk = options.image_frames;
  if (chunk && !(0 <= chunk->first && chunk->first < chunk->end && chunk->end <= frames)) {
    throw Error("image frames [" + std::to_string(chunk->first) + ", " +
                std::to_string(chunk->end) + ") are not a range of the " + std::to_string(frames) +
                " frames");
  }
  prepare_output(out_dir, scene, options);

  const auto& cameras = setup.cameras();
  DatasetWriter writer(out_dir, camera_names(scene), scene.render.normals);
  remove_stale_temporaries(out_dir);
  Json meta = describe(scene, scene_file, setup.actors().posed(), setup.clock());
  meta["complete"] = false;
  write_text_atomic(out_dir / "meta.json", meta.dump(2) + "\n");
  writer.write_fixed_files(scene, *setup.actors().posed().at(0).skeleton);
  writer.write_gestures(setup.actors().labels(frames), setup.actors().posed());
  if (!chunk && !(options.resume && writer.backgrounds_complete())) {
    writer.write_backgrounds(setup.render_background());
  }
  if (!chunk) writer.open_truth(setup.actors().posed(), scene.cameras);
  const int actor_count = static_cast<int>(setup.actors().posed().size());

  struct FrameWork {
    int frame = 0;
    FrameTruth truth;
    std::vector<RenderedView> views;          // empty when the frame's files already exist
    std::vector<std::vector<MaskBox>> boxes;  // [camera][actor], for the COCO annotations
  };
  using Work = std::shared_ptr<FrameWork>;
  // Image buffers of written frames are reused: fresh ones would cost page faults every frame.
  std::vector<std::vector<RenderedView>> spare_views;
  std::mutex spare_mutex;
  const int first = chunk ? chunk->first : 0, end = chunk ? chunk->end : frames;
  Progress progress("render", end - first, options.quiet);
  int next = first, rendered = 0;
  double render_seconds = 0;
  std::atomic<std::int64_t> write_ns{0};
  // Frames go through three stages, pipelined so that image encoding overlaps rendering: pose,
  // ground truth and render (in order: they share the Embree scene); write the images (any
  // order, several at once); append the truth rows (in order).
  auto render_frame = [&](tbb::flow_control& fc) -> Work {
    if (next == end) {
      fc.stop();
      return nullptr;
    }
    const auto t0 = Clock::now();
    auto w = std::make_shared<FrameWork>();
    w->frame = next++;
    if (options.resume && writer.frame_complete(w->frame)) {
      w->truth = setup.capture(w->frame, nullptr);
    } else {
      {
        std::lock_guard lock(spare_mutex);
        if (!spare_views.empty()) {
          w->views = std::move(spare_views.back());
          spare_views.pop_back();
        }
      }
      w->truth = setup.capture(w->frame, &w->views);
      ++rendered;
    }
    render_seconds += seconds_since(t0);
    return w;
  };
  auto write_images = [&](Work w) {
    for (size_t c = 0; c < cameras.size() && !chunk; ++c) {
      const cv::Mat mask =
          w->views.empty() ? read_image(writer.image_path(static_cast<int>(c), "mask", w->frame))
                           : w->views[c].mask;
      w->boxes.push_back(mask_boxes(mask, actor_count));
    }
    if (w->views.empty()) return w;
    const auto t0 = Clock::now();
    writer.write_frame(w->frame, w->views);
    write_ns += std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count();
    std::lock_guard lock(spare_mutex);
    spare_views.push_back(std::move(w->views));
    return w;
  };
  auto write_truth = [&](Work w) {
    if (!chunk) writer.append_truth(w->truth, w->boxes);
    progress.advance();
  };
  tbb::parallel_pipeline(
      kFramesInFlight,
      tbb::make_filter<void, Work>(tbb::filter_mode::serial_in_order, render_frame) &
          tbb::make_filter<Work, Work>(tbb::filter_mode::parallel, write_images) &
          tbb::make_filter<Work, void>(tbb::filter_mode::serial_in_order, write_truth));
  if (!chunk) writer.commit_truth();
  progress.finish();

  RenderSummary summary;
  summary.frames = end - first;
  summary.cameras = static_cast<int>(cameras.size());
  summary.seconds = seconds_since(start);
  summary.write_seconds = 1e-9 * static_cast<double>(write_ns.load());
  summary.dataset = out_dir;
  meta["complete"] = !chunk;
  meta["timings"] = {{"total_s", summary.seconds},
                     {"render_s", render_seconds},
                     {"write_thread_s", summary.write_seconds},
                     {"threads", tbb::info::default_concurrency()},
                     {"frames_rendered", rendered},
                     {"frames_resumed", summary.frames - rendered},
                     {"frames_per_s", summary.frames / summary.seconds}};
  write_text_atomic(out_dir / "meta.json", meta.dump(2) + "\n");
  return summary;
}

}  // namespace simcap
