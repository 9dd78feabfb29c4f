#include "apps/simcap/track_cli.h"

#include <array>

#include "apps/simcap/choice_option.h"
#include "apps/simcap/number_checks.h"
#include "core/error.h"
#include "tracker/registry.h"

namespace simcap::cli {

namespace {

// Sweep keys and the options they set (sweep files name the voxel and noise with their unit).
constexpr std::array<std::pair<std::string_view, std::string_view>, 13> kSweepKeys{{
    {"method", "--method"},
    {"silhouettes", "--silhouettes"},
    {"init", "--init"},
    {"appearance", "--appearance"},
    {"filter", "--filter"},
    {"joints", "--joints"},
    {"traversal", "--traversal"},
    {"occlusion", "--occlusion"},
    {"voxel_m", "--voxel"},
    {"effectors", "--effectors"},
    {"camera", "--camera"},
    {"sik_noise_m", "--sik-noise"},
    {"seed", "--seed"},
}};

std::string method_help() {
  std::string help = "Tracker:";
  for (const tracker::TrackerFamily& f : tracker::tracker_families()) {
    help += std::string(help.back() == ':' ? " " : "; ") +
            std::string(name_of(tracker::kTrackMethods, f.method)) + " (" + std::string(f.summary) +
            ")";
  }
  return help;
}

}  // namespace

void add_track_options(CLI::App* cmd, tracker::TrackOptions& o, TrackOptionScope scope) {
  using namespace tracker;
  add_choice(cmd, "--method", o.method, kTrackMethods, method_help());
  add_choice(cmd, "--silhouettes", o.silhouettes, kSilhouetteMethods,
             "Silhouettes (moschini; sik from pixels, for the pelvis): gt (the dataset's masks), "
             "bgsub (Gaussian background model), mog2 (OpenCV MOG2)");
  add_choice(cmd, "--init", o.init, kInitMethods,
             "First pose: gt (ground truth of the first frame; sik from pixels: the part labels "
             "and the truth's body) or auto (moschini: the hull of a person standing upright; "
             "sik: the calibration posture, hands raised beside the head, facing the camera)");
  cmd->add_option("--voxel", o.moschini.voxel_m, "moschini: visual hull voxel size, metres")
      ->check(CLI::Range(0.005, 0.2))
      ->capture_default_str();
  add_choice(cmd, "--joints", o.moschini.joints, kJointSets,
             "moschini: joint set, moschini (Table 5.1, 23-parameter EKF) or urdf (adds hip "
             "twists, a spine joint, wrists and ankles)");
  add_choice(cmd, "--appearance", o.moschini.appearance, kOnOff,
             "moschini: learn the parts' colours on the first frame so that a silhouette pixel "
             "only meets the parts it may show (an arm in front of the torso)");
  add_choice(cmd, "--filter", o.moschini.filter, kMotionFilters,
             "moschini: none (each frame's fit is the estimate) or ekf (Moschini's EKF smooths "
             "the fits; it lags a moving body)");
  add_choice(cmd, "--traversal", o.moschini.traversal, kOnOff,
             "moschini: on (each frame also tries Moschini's hierarchical ICP traversal and keeps "
             "the better fit) or off (the joint refinement from the previous pose)");
  add_choice(cmd, "--occlusion", o.moschini.occlusion, kOnOff,
             "moschini: on (learn where scene objects hide the person from a camera, which then "
             "abstains there from carving the hull) or off (every camera carves everywhere)");
  cmd->add_option("--limits", o.moschini.limits,
                  "moschini: joint limits of the urdf joint set from this URDF (an edited copy of "
                  "models/assets/humanoid_limits.urdf); default: the dataset scene's "
                  "actors[0].limits, else that file")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--oracle", o.moschini.oracle,
                "moschini: start every frame from its ground-truth pose (a diagnostic: the error "
                "left is the body model's and the cues', not the search's)");
  add_choice(cmd, "--effectors", o.sik.effectors, kEffectorSources,
             "sik: where the end-effectors come from: gt (the ground truth), depth (tracked in "
             "one camera, lifted by its depth map), mono (one camera, pseudo-3D), multiview (every "
             "camera, triangulated)");
  cmd->add_option("--camera", o.sik.camera,
                  "sik --effectors depth|mono: index of the camera (calibration order); "
                  "multiview: the camera whose calibration posture starts the others")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--sik-noise", o.sik.noise_sigma_m,
                  "sik: standard deviation of the noise added to the end-effectors, metres")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  std::vector<std::string> export_names;
  for (const auto& [name, value] : kMotionExports) export_names.emplace_back(name);
  cmd->add_option_function<std::vector<std::string>>(
         "--export",
         [&o](const std::vector<std::string>& words) {
           o.exports.clear();
           for (const std::string& w : words) {
             for (const auto& [name, value] : kMotionExports) {
               if (w == name) o.exports.push_back(value);
             }
           }
         },
         "Also write the tracked motion as TRACK/motion.bvh and/or motion.x3d (X3D H-Anim "
         "HAnimMotion), comma-separated: " +
             choices_text(kMotionExports) + "; simcap's humanoid sized to the track")
      ->delimiter(',')
      ->check(CLI::IsMember(export_names));
  if (scope == TrackOptionScope::loop) return;
  cmd->add_option("--inspect", o.moschini.inspect,
                  "moschini: frames to lay open, comma-separated: per camera an image with the "
                  "silhouette's edge, centerline, capsule outlines and sticks drawn, and the "
                  "hull's voxels (diagnostics/inspect/FRAME/)")
      ->delimiter(',')
      ->check(non_negative_number());
  cmd->add_option("--seed", o.sik.seed, "sik: seed of that noise")->capture_default_str();
  cmd->add_flag("-q,--quiet", o.quiet, "No progress on stderr");
}

void apply_sweep_track_options(const std::vector<std::pair<std::string, std::string>>& keys,
                               const std::filesystem::path& sweep_file,
                               tracker::TrackOptions& options) {
  CLI::App parser;
  add_track_options(&parser, options, TrackOptionScope::track);
  for (const auto& [key, value] : keys) {
    std::string_view flag;
    std::string known;
    for (const auto& [k, f] : kSweepKeys) {
      if (k == key) flag = f;
      known += (known.empty() ? "" : ", ") + std::string(k);
    }
    if (flag.empty()) {
      throw_input_error(sweep_file, 0, "track." + key,
                        "unknown tracker option; expected one of " + known);
    }
    try {
      // CLI11 takes the arguments in reverse order.
      parser.parse(std::vector<std::string>{value, std::string(flag)});
    } catch (const CLI::ParseError& e) {
      throw_input_error(sweep_file, 0, "track." + key, e.what());
    }
  }
}

std::string track_options_text(const tracker::TrackOptions& o) {
  using namespace tracker;
  std::string s(name_of(kTrackMethods, o.method));
  if (o.method == TrackMethod::moschini) {
    s += ", silhouettes " + std::string(name_of(kSilhouetteMethods, o.silhouettes));
  } else {
    s += ", effectors " + std::string(name_of(kEffectorSources, o.sik.effectors));
  }
  return s + ", init " + std::string(name_of(kInitMethods, o.init));
}

}  // namespace simcap::cli
