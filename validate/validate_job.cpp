#include "validate/validate_job.h"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/atomic_file.h"
#include "core/calibration.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/progress.h"
#include "core/stale_temporaries.h"
#include "validate/metrics_json.h"
#include "validate/overlay.h"
#include "validate/report_folder.h"
#include "validate/report_html.h"
#include "validate/validation_inputs.h"
#include "validate/video.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

constexpr int kJpegQuality = 85;

std::string mm_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f mm", v);
  return buf;
}

// The dataset's RGB frame, checked against the calibration's image size.
cv::Mat read_rgb(const fs::path& dataset, const Camera& camera, int frame) {
  const fs::path file = rgb_frame_path(dataset, camera.name, frame);
  if (!fs::is_regular_file(file)) {
    throw_input_error(file, 0, "",
                      "missing; expected the dataset's RGB frame for the overlays (run validate "
                      "with --no-media to skip them)");
  }
  cv::Mat img = read_image(file);
  if (img.type() != CV_8UC3 || img.cols != camera.width || img.rows != camera.height) {
    throw_input_error(file, 0, "",
                      "expected an 8-bit RGB image of " + std::to_string(camera.width) + "x" +
                          std::to_string(camera.height) + " (the calibration's size)");
  }
  return img;
}

struct PickedFrame {
  size_t index;
  std::string reason;
};

// The worst frame and evenly spaced others, in frame order.
std::vector<PickedFrame> pick_frames(const Evaluation& ev, int count) {
  const size_t n = ev.per_frame.size();
  const auto worst =
      static_cast<size_t>(std::max_element(ev.per_frame.begin(), ev.per_frame.end(),
                                           [](const FrameScore& a, const FrameScore& b) {
                                             return a.mpjpe_mm < b.mpjpe_mm;
                                           }) -
                          ev.per_frame.begin());
  std::vector<PickedFrame> picked = {
      {worst, "largest MPJPE, " + mm_text(ev.per_frame[worst].mpjpe_mm)}};
  const int others = std::max(0, count - 1);
  for (int k = 0; k < others; ++k) {
    const size_t i = static_cast<size_t>(k) * n / static_cast<size_t>(others);
    const bool taken = std::any_of(picked.begin(), picked.end(),
                                   [i](const PickedFrame& p) { return p.index == i; });
    if (!taken) picked.push_back({i, "MPJPE " + mm_text(ev.per_frame[i].mpjpe_mm)});
  }
  std::sort(picked.begin(), picked.end(),
            [](const PickedFrame& a, const PickedFrame& b) { return a.index < b.index; });
  return picked;
}

std::vector<unsigned char> jpeg(const cv::Mat& rgb) {
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<unsigned char> bytes;
  cv::imencode(".jpg", bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, kJpegQuality});
  return bytes;
}

std::string caption(const Evaluation& ev, size_t f, const std::string& camera) {
  return camera + "  frame " + std::to_string(ev.frames[f]) + "  MPJPE " +
         mm_text(ev.per_frame[f].mpjpe_mm) + "  (green: truth, red: tracked)";
}

void add_overlays(const ValidationInputs& in, const Evaluation& ev,
                  const std::vector<std::pair<int, int>>& bones, const ValidateOptions& options,
                  ReportContent& content, Progress& progress) {
  for (const auto& p : pick_frames(ev, options.overlay_frames)) {
    for (const Camera& cam : in.cameras) {
      const cv::Mat img = draw_overlay(
          read_rgb(in.dataset, cam, ev.frames[p.index]), cam, in.evaluation.truth[p.index],
          in.evaluation.estimate[p.index], bones, caption(ev, p.index, cam.name));
      content.overlays.push_back({ev.frames[p.index], cam.name, p.reason, jpeg(img)});
      progress.advance();
    }
  }
}

// Writes the overlay video of one camera; returns its path, or an empty path and a note.
fs::path write_video(const ValidationInputs& in, const Evaluation& ev, const Camera& cam,
                     const std::vector<std::pair<int, int>>& bones, const ValidateOptions& options,
                     const fs::path& out, std::string& note, Progress& progress) {
  const size_t frames = std::min(ev.frames.size(), static_cast<size_t>(options.video_max_frames));
  const fs::path file = out / ("overlay_" + cam.name + ".mp4");
  Mp4Writer video(file, in.fps, cv::Size(cam.width, cam.height));
  if (!video.is_open()) {
    note = "No video: " + video.problem() + ".";
    progress.advance(static_cast<long>(frames));
    return {};
  }
  for (size_t f = 0; f < frames; ++f) {
    video.write(draw_overlay(read_rgb(in.dataset, cam, ev.frames[f]), cam, in.evaluation.truth[f],
                             in.evaluation.estimate[f], bones, caption(ev, f, cam.name)));
    progress.advance();
  }
  video.commit();
  note = "Camera " + cam.name + ", frames " + std::to_string(ev.frames.front()) + " to " +
         std::to_string(ev.frames[frames - 1]) + " (" + video.codec() + " MP4).";
  return file;
}

// The camera --video-camera names; an Error that says it was that option's value otherwise.
const Camera& video_camera_of(const ValidationInputs& in, const std::string& name) {
  try {
    return find_camera(in.cameras, name, in.dataset / "calibration" / "opencv.yaml");
  } catch (const Error& e) {
    throw Error(std::string("--video-camera: ") + e.what());
  }
}

}  // namespace

fs::path rgb_frame_path(const fs::path& dataset, const std::string& camera, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.png", frame);
  return dataset / camera / "rgb" / name;
}

ValidateSummary validate_dataset(const fs::path& dataset, const fs::path& track,
                                 const fs::path& out, const ValidateOptions& options) {
  check_report_folder(out);
  const ValidationInputs in = load_validation_inputs(dataset, track);
  // A run killed before left temporaries; this run's report is exactly its own files.
  remove_stale_temporaries(out);
  EvaluationOptions eval_options;
  eval_options.failure_threshold_mm = options.failure_threshold_mm;
  ValidateSummary summary;
  summary.evaluation = evaluate(in.evaluation, eval_options);
  const Evaluation& ev = summary.evaluation;
  std::vector<std::string> camera_names;
  for (const Camera& c : in.cameras) camera_names.push_back(c.name);
  summary.effectors = score_effector_tracks(dataset, track, ev.frames, camera_names);

  ReportContent content{dataset.string(), track.string(), {}, {}, {}};
  if (options.media) {
    const Camera& video_camera = options.video_camera.empty()
                                     ? in.cameras.front()
                                     : video_camera_of(in, options.video_camera);
    const auto bones = stick_figure_bones(ev.joints);
    const long overlay_count =
        static_cast<long>(pick_frames(ev, options.overlay_frames).size() * in.cameras.size());
    const long video_count =
        std::min(static_cast<long>(ev.frames.size()), static_cast<long>(options.video_max_frames));
    Progress progress("validate: overlays and video", overlay_count + video_count, options.quiet);
    add_overlays(in, ev, bones, options, content, progress);
    summary.video =
        write_video(in, ev, video_camera, bones, options, out, content.video_note, progress);
    if (!summary.video.empty()) content.video_file = summary.video.filename().string();
  } else {
    content.video_note = "No video: validate ran with --no-media.";
  }
  summary.video_note = content.video_note;

  nlohmann::ordered_json json = metrics_to_json(ev, dataset.string(), track.string());
  json["effectors2d"] = effector_scores_json(summary.effectors);
  json["media"] = {
      {"overlay_frames", nlohmann::ordered_json::array()},
      {"video", content.video_file.empty() ? nlohmann::ordered_json(nullptr)
                                           : nlohmann::ordered_json(content.video_file)},
      {"video_note", content.video_note}};
  for (const auto& o : content.overlays) {
    auto& frames = json["media"]["overlay_frames"];
    if (frames.empty() || frames.back() != o.frame) frames.push_back(o.frame);
  }
  summary.metrics_json = out / "metrics.json";
  summary.report_html = out / "report.html";
  write_text_atomic(summary.metrics_json, json.dump(2) + "\n");
  write_text_atomic(summary.report_html, report_html(ev, content));
  return summary;
}

}  // namespace simcap
