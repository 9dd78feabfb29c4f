#include "apps/simcap/track_cli.h"

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "apps/simcap/choice_option.h"
#include "apps/simcap/number_checks.h"
#include "apps/simcap/sik_cue_options.h"
#include "core/error.h"
#include "core/literal_text.h"
#include "tracker/registry.h"

namespace simcap::cli {

namespace {

// Sweep keys and the options they set (sweep files name the voxel and noise with their unit).
constexpr std::array<std::pair<std::string_view, std::string_view>, 38> kSweepKeys{{
    {"method", "--method"},
    {"actor", "--actor"},
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
    {"pelvis_travel", "--pelvis-travel"},
    {"spine_bend", "--spine-bend"},
    {"seed", "--seed"},
    {"body", "--body"},
    {"search", "--search"},
    {"particles", "--particles"},
    {"heuristics", "--heuristics"},
    {"smoothing", "--smoothing"},
    {"region_combine", "--region-combine"},
    {"work_height", "--work-height"},
    {"diffusion", "--diffusion"},
    {"feet_sigma", "--feet-sigma"},
    {"top_sigma", "--top-sigma"},
    {"mirror_groups", "--mirror-groups"},
    {"hand_depths", "--hand-depths"},
    {"depth_groups", "--depth-groups"},
    {"limb_end_depths", "--limb-end-depths"},
    {"limb_end_legs", "--limb-end-legs"},
    {"shading_sigma", "--shading-sigma"},
    {"floor", "--floor"},
    {"smooth", "--smooth"},
    {"cutoff_hz", "--cutoff"},
    {"max_error_px", "--max-error"},
    {"swaps", "--swaps"},
    {"bones", "--bones"},
}};

// "h1,h3", "all" or "none" -> the particle filter's switches; an error message otherwise.
std::string parse_heuristics(const std::string& text, tracker::gomez::FilterOptions* f) {
  bool on[5] = {false, false, false, false, false};
  if (text == "all") {
    for (bool& b : on) b = true;
  } else if (text != "none") {
    size_t start = 0;
    while (start <= text.size()) {
      const size_t end = std::min(text.find(',', start), text.size());
      const std::string word = text.substr(start, end - start);
      if (word.size() != 2 || word[0] != 'h' || word[1] < '1' || word[1] > '5') {
        return "unknown heuristic '" + word + "' (expected h1 to h5, all or none)";
      }
      on[word[1] - '1'] = true;
      start = end + 1;
    }
  }
  if (f) {
    f->h1_resampling = on[0];
    f->h2_partitioned = on[1];
    f->h3_simplex = on[2];
    f->h4_flipping = on[3];
    f->h5_end_effector = on[4];
  }
  return {};
}

std::string heuristics_text(const tracker::gomez::FilterOptions& f) {
  const bool on[5] = {f.h1_resampling, f.h2_partitioned, f.h3_simplex, f.h4_flipping,
                      f.h5_end_effector};
  std::string s;
  for (int i = 0; i < 5; ++i) {
    if (on[i]) s += (s.empty() ? "h" : ",h") + std::to_string(i + 1);
  }
  return s.empty() ? "none" : s == "h1,h2,h3,h4,h5" ? "all" : s;
}

template <typename Table>
std::vector<std::string> choices_of(const Table& table) {
  std::vector<std::string> names;
  for (const auto& [name, value] : table) names.emplace_back(name);
  return names;
}

using MethodOptionList = std::pair<std::vector<const char*>, std::vector<tracker::TrackMethod>>;

// The options only some methods read; the rest (--actor, --silhouettes, --init, --export,
// --frames, ...) every method does. Each such option is in the help's group of its methods
// ("sik options"), which also tells it from a command's own option of the same name (loop's
// --seed is the render's).
const std::vector<MethodOptionList> kMethodOptions = {
    {{"--voxel", "--joints", "--appearance", "--filter", "--traversal", "--occlusion", "--limits"},
     {tracker::TrackMethod::moschini}},
    {{"--oracle", "--inspect"}, {tracker::TrackMethod::moschini, tracker::TrackMethod::monocular}},
    {{"--effectors", "--camera", "--surface-quantile", "--occlusion-quantile",
      "--surface-thickness", "--consensus-px", "--reseed", "--view-swaps", "--pair-consensus",
      "--borrow-colours", "--refind-reach", "--refind-patience", "--middle-targets",
      "--pelvis-travel", "--spine-bend", "--sik-noise"},
     {tracker::TrackMethod::sik}},
    {{"--body", "--floor", "--search", "--particles", "--heuristics", "--smoothing",
      "--region-combine", "--work-height", "--diffusion", "--feet-sigma", "--top-sigma",
      "--mirror-groups", "--hand-depths", "--limb-end-depths", "--limb-end-legs", "--depth-groups",
      "--shading-sigma"},
     {tracker::TrackMethod::monocular}},
    {{"--detections", "--layout", "--smooth", "--cutoff", "--max-error", "--bones", "--swaps"},
     {tracker::TrackMethod::triangulate}},
    {{"--seed"}, {tracker::TrackMethod::sik, tracker::TrackMethod::monocular}},
};

std::string method_names(const std::vector<tracker::TrackMethod>& methods) {
  std::string names;
  for (tracker::TrackMethod m : methods) {
    names += (names.empty() ? "" : " or ") + std::string(name_of(tracker::kTrackMethods, m));
  }
  return names;
}

std::string method_help() {
  std::string help = "Tracker:";
  for (const tracker::TrackerFamily& f : tracker::tracker_families()) {
    help += std::string(help.back() == ':' ? " " : "; ") +
            std::string(name_of(tracker::kTrackMethods, f.method)) + " (" + std::string(f.summary) +
            ")";
  }
  return help;
}

void declare_track_options(CLI::App* cmd, tracker::TrackOptions& o, TrackOptionScope scope) {
  using namespace tracker;
  add_choice(cmd, "--method", o.method, kTrackMethods, method_help());
  cmd->add_option("--actor", o.actor,
                  "The person to track in a dataset of several (scene.yaml's actor name; "
                  "default: the first actor); moschini tracks any, sik and monocular the first. "
                  "The track records it in actor.txt and validate scores that actor");
  add_choice(cmd, "--silhouettes", o.silhouettes, kSilhouetteMethods,
             "Silhouettes (moschini, monocular; sik from pixels, for the pelvis): gt (the "
             "dataset's masks), bgsub (Gaussian background model), mog2 (OpenCV MOG2)");
  add_choice(cmd, "--init", o.init, kInitMethods,
             "First pose: gt (ground truth of the first frame; sik from pixels: the part labels "
             "and the truth's body) or auto (moschini: the hull of a person standing upright; "
             "with others in view and bgsub/mog2, the --actor's mask on the first frames points "
             "at whom to start on; "
             "monocular: an upright person facing the camera; sik: the calibration posture, hands "
             "raised beside the head, facing the camera)");
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
                  "limits of the tracked actor, else that file")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--oracle", o.oracle,
                "moschini, monocular: start every frame from its ground-truth pose (a diagnostic: "
                "the error left is the body model's and the cues', not the search's)");
  add_choice(cmd, "--effectors", o.sik.effectors, kEffectorSources,
             "sik: where the end-effectors come from: gt (the ground truth), depth (tracked in "
             "one camera, lifted by its depth map), mono (one camera, pseudo-3D), multiview (every "
             "camera, triangulated)");
  cmd->add_option("--camera", o.sik.camera,
                  "sik --effectors depth|mono: index of the camera (calibration order); "
                  "multiview: the camera whose calibration posture starts the others")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--surface-quantile", o.sik.surface_quantile,
                  "sik --effectors depth: quantile of the depths under a tracked part read as its "
                  "surface (0: the nearest, 0.5: the median)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--occlusion-quantile", o.sik.occlusion_quantile,
                  "sik --effectors depth: quantile of the depths under a tracked part that orders "
                  "overlapping parts for the self-occlusion rule (0.5: the median)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--surface-thickness", o.sik.surface_thickness,
                  "sik --effectors depth: a part's surface lies at most this far (metres) behind "
                  "its nearest pixels (0: off)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--consensus-px", o.sik.multiview_consensus_px,
                  "sik --effectors multiview: triangulate each part from the cameras whose tracks "
                  "agree within this many pixels (RANSAC over camera pairs; 0: every tracking "
                  "camera in one DLT)")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  add_choice(cmd, "--reseed", o.sik.multiview_reseed, kOnOff,
             "sik --effectors multiview: on (a camera whose track of a part disagrees with the "
             "cameras that agree, or that lost it, is moved onto their point) or off");
  add_choice(cmd, "--view-swaps", o.sik.multiview_swaps, kOnOff,
             "sik --effectors multiview: on (a camera whose left and right hand, or foot, tracks "
             "each follow the other limb, where two other cameras agree on both, has them "
             "exchanged; needs --consensus-px > 0) or off");
  add_choice(cmd, "--pair-consensus", o.sik.multiview_pairs, kOnOff,
             "sik --effectors multiview: on (when both hands', or feet's, triangulated points "
             "fall on one limb, the cameras whose tracks agree elsewhere give one of them, and a "
             "part no two cameras agree on is not placed from a track on the other one's point; "
             "needs --consensus-px > 0) or off");
  add_choice(cmd, "--borrow-colours", o.sik.multiview_borrow_colours, kOnOff,
             "sik --effectors multiview --reseed on: on (a camera whose part showed none of its "
             "colours in the first frame takes them from a camera that agrees on it, so the "
             "re-seeding can start it there) or off");
  cmd->add_option_function<double>(
         "--refind-reach",
         [&o](double reach) {
           for (tracker::Effector e :
                {tracker::Effector::left_hand, tracker::Effector::right_hand}) {
             o.sik.tracking.refind_reach[tracker::index_of(e)] = reach;
           }
         },
         "sik --effectors depth|mono|multiview: re-find a hand lost for --refind-patience frames "
         "at the far end of its skin blob within this reach of its shoulder, a fraction of the "
         "person's height (0.44: shoulder to fingertip; default 0: off)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--refind-patience", o.sik.tracking.refind_patience,
                  "sik: frames in a row a hand is not tracked before --refind-reach searches "
                  "for it")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_flag("--middle-targets", o.sik.middle_targets,
                "sik --effectors gt: also give SIK the truth's elbows and knees (each limb swivels "
                "toward them)");
  add_sik_cue_options(cmd, o.sik.solver.pelvis_weights.travel, o.sik.solver.spine_bend, "sik: ");
  cmd->add_option("--sik-noise", o.sik.noise_sigma_m,
                  "sik: standard deviation of the noise added to the end-effectors, metres")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
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
         "Also write the tracked motion as TRACK/motion.bvh, motion.x3d (X3D H-Anim "
         "HAnimMotion) and/or motion.bap (MPEG-4 BAPs), comma-separated: " +
             choices_text(kMotionExports) +
             "; simcap's humanoid sized to the track (monocular writes its own body's "
             "motion.bvh and motion.bap)")
      ->delimiter(',')
      ->check(CLI::IsMember(choices_of(kMotionExports)));
  gomez::MonocularSettings& m = o.monocular.tracker;
  add_choice(cmd, "--body", m.body, gomez::kBodyKinds,
             "monocular: the tracked body, full (root, trunk, neck, arms, legs) or upper (the "
             "thesis's 20 angles of trunk, neck and arms; root and legs keep the first pose)");
  add_choice(cmd, "--floor", m.floor, kOnOff,
             "monocular: on (the full body's lowest sole stays on the floor y = 0: the root's "
             "height follows the legs) or off (the root's height is free)");
  add_choice(cmd, "--search", m.search, gomez::kSearches,
             "monocular: particles (the particle filter of thesis ch. 4) or simplex (ch. 3: "
             "Nelder-Mead from the previous pose, regions then edges)");
  cmd->add_option("--particles", m.filter.particles, "monocular: particles of the filter")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option_function<std::string>(
         "--heuristics", [&m](const std::string& text) { parse_heuristics(text, &m.filter); },
         "monocular: the particle filter's heuristics that are on, comma-separated: h1 "
         "(deterministic resampling), h2 (partitioned diffusion), h3 (Nelder-Mead children), h4 "
         "(kinematic flipping), h5 (wrists as end-effectors); or all, none")
      ->check(
          CLI::Validator([](std::string& text) { return parse_heuristics(text, nullptr); }, "LIST"))
      ->default_str(heuristics_text(m.filter));
  cmd->add_option("--smoothing", m.smoothing,
                  "monocular: output smoothing a of the angles, theta* = a theta*_prev + (1 - a) "
                  "theta (thesis: 0.6; 0: off)")
      ->check(CLI::Range(0.0, 0.99))
      ->capture_default_str();
  add_choice(cmd, "--region-combine", m.score.combine, gomez::kRegionCombines,
             "monocular: how the colour classes' non-overlap ratios add up: root_sum (the "
             "thesis's printed eq. 2.5), mean, or pixels (all classes' pixels together)");
  cmd->add_option("--work-height", m.cues.work_height,
                  "monocular: the person's height in pixels at the working resolution")
      ->check(CLI::Range(24, 2000))
      ->capture_default_str();
  cmd->add_option("--diffusion", m.filter.diffusion,
                  "monocular: scale S of the particles' random diffusion (eq. 4.13)")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--feet-sigma", m.score.sigma_feet_px,
                  "monocular: spread in working pixels of the feet prior (the body's lowest "
                  "extent against the silhouette's; the floor fixes the depth), 0: off")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--top-sigma", m.score.sigma_top_px,
                  "monocular: spread in working pixels of the top prior (the body's highest "
                  "extent against the silhouette's), 0: off")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--mirror-groups", m.filter.mirror_groups,
                  "monocular: how many particle groups, largest first, have their best pose "
                  "tested reflected front to back across the camera ray (full body), 0: off")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--hand-depths", m.filter.hand_depths,
                  "monocular: depths along the camera ray at which an arm is proposed reaching "
                  "a hand-coloured image region no hand of the best pose explains (H5 from the "
                  "image), 0: off")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  cmd->add_option("--limb-end-depths", m.filter.limb_end_depths,
                  "monocular: proposals per geodesic extremity of the silhouette (seen from the "
                  "trunk) that no hand, foot, elbow, knee or head of the best pose explains: the "
                  "nearest free hand or foot, whatever its colour, reaching it at its present "
                  "depth, then at N-1 depths spread along its camera ray; 0: off")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  add_choice(cmd, "--limb-end-legs", m.filter.limb_end_legs, kOnOff,
             "monocular: with --limb-end-depths, the feet are proposed reaching the silhouette's "
             "extremities too (on), or only explain them (off)");
  cmd->add_option("--depth-groups", m.filter.depth_groups,
                  "monocular: how many particle groups, largest first, have their best pose "
                  "tested slid in depth to meet the silhouette's feet and top rows (full body), "
                  "0: off")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--shading-sigma", m.score.sigma_shade_grey,
                  "monocular: spread in grey levels of the arm bones' shading term, 0: off. Each "
                  "upper arm's and forearm's mean grey against a Lambert cylinder's under a "
                  "directional light, penalised where its depth flip explains it better; the "
                  "light and each colour class's grey are fitted on the first frame with the "
                  "start pose (--init gt: the truth's; auto: the upright start)")
      ->check(CLI::Range(0.0, 255.0))
      ->capture_default_str();
  TriangulateOptions& t = o.triangulate;
  cmd->add_option("--detections", t.detections,
                  "triangulate: the 2D keypoints of every camera: COCO keypoint results JSON "
                  "(image_id = 1 + frame x cameras + camera, or file_name camNN/rgb/FRAME.png), "
                  "an OpenPose output folder (one folder per camera) or a CSV "
                  "(frame,camera,person,keypoint,x,y,score)");
  cmd->add_option_function<std::string>(
         "--layout",
         [&t](const std::string& word) {
           for (const auto& [name, value] : kKeypointLayouts) {
             if (word == name) t.layout = value;
           }
         },
         "triangulate: the detections' keypoint layout, " + choices_text(kKeypointLayouts) +
             " (default: from the keypoint count; 17 is read as coco17)")
      ->check(CLI::IsMember(choices_of(kKeypointLayouts)));
  add_choice(cmd, "--smooth", t.filter, kTemporalFilters,
             "triangulate: none, butterworth (zero-phase low-pass of every keypoint over "
             "time, Pose2Sim's filter) or kalman (constant-velocity Kalman/RTS smoother, "
             "its noise from the triangulation and its process noise by maximum likelihood)");
  cmd->add_option("--cutoff", t.cutoff_hz, "triangulate --smooth butterworth: cut-off, Hz")
      ->check(CLI::Range(0.1, 1000.0))
      ->capture_default_str();
  cmd->add_option("--max-error", t.triangulation.point.max_error_px,
                  "triangulate: a keypoint's views are excluded, worst first, while one "
                  "reprojects farther than this, pixels (never below two views)")
      ->check(CLI::Range(0.5, 1000.0))
      ->capture_default_str();
  add_choice(cmd, "--bones", t.bone_lengths, kOnOff,
             "triangulate: on (every frame's keypoints moved onto the take's median bone "
             "lengths: thighs, shanks, upper arms, forearms, pelvis) or off");
  add_choice(cmd, "--swaps", t.triangulation.repair_swaps, kOnOff,
             "triangulate: on (a view whose left/right labels of a pair triangulate clearly "
             "better exchanged is repaired) or off");
  if (scope == TrackOptionScope::loop) return;
  cmd->add_option("--inspect", o.inspect,
                  "Frames to lay open, comma-separated, in diagnostics/inspect/: moschini, per "
                  "camera an image with the silhouette's edge, centerline, capsule outlines and "
                  "sticks drawn, and the hull's voxels (FRAME/); monocular, the working crop, its "
                  "colour classes, the model's classes and contour, and the edge distance map "
                  "(FRAME.png)")
      ->delimiter(',')
      ->check(non_negative_number());
  cmd->add_option("--seed", o.seed, "sik: seed of that noise; monocular: seed of the particles")
      ->capture_default_str()
      ->check(non_negative_number());
  cmd->add_option("--frames", o.max_frames, "Track the first N frames only (default: all)")
      ->check(positive_number());
  cmd->add_flag("-q,--quiet", o.quiet, "No progress on stderr");
}

}  // namespace

void add_track_options(CLI::App* cmd, tracker::TrackOptions& o, TrackOptionScope scope) {
  const size_t earlier_options = cmd->get_options().size();
  declare_track_options(cmd, o, scope);
  const std::vector<CLI::Option*> declared = cmd->get_options();
  for (size_t i = earlier_options; i < declared.size(); ++i) {
    CLI::Option* option = declared[i];
    for (const auto& [flags, readers] : kMethodOptions) {
      for (const char* flag : flags) {
        if (option->check_name(flag)) option->group(method_names(readers) + " options");
      }
    }
  }
}

void refuse_other_methods_options(CLI::App* cmd, const tracker::TrackOptions& options,
                                  std::function<int()> cameras) {
  cmd->parse_complete_callback([cmd, &options, cameras] {
    using tracker::TrackMethod;
    // The automatic method becomes moschini or monocular once the cameras are counted (only
    // when an option needs it: the dataset is the track's to check).
    int count = -1;
    std::vector<TrackMethod> chosen;
    for (const auto& [flags, readers] : kMethodOptions) {
      for (const char* flag : flags) {
        const CLI::Option* given = cmd->get_option_no_throw(flag);
        if (given == nullptr || given->count() == 0 ||
            given->get_group() != method_names(readers) + " options") {
          continue;
        }
        if (count < 0) {
          count = options.method == TrackMethod::automatic && cameras ? cameras() : 0;
          chosen = options.method != TrackMethod::automatic ? std::vector{options.method}
                   : count > 0 ? std::vector{tracker::resolve_method(options.method, count)}
                               : std::vector{TrackMethod::moschini, TrackMethod::monocular};
        }
        const bool read = std::any_of(chosen.begin(), chosen.end(), [&](TrackMethod m) {
          return std::find(readers.begin(), readers.end(), m) != readers.end();
        });
        if (read) continue;
        const std::string wanted = method_names(readers);
        throw CLI::ValidationError(
            flag,
            "only --method " + wanted + " reads it, and the method is " +
                std::string(name_of(tracker::kTrackMethods, options.method)) +
                (options.method != TrackMethod::automatic ? ""
                 : count > 0 ? " (" + method_names(chosen) + " for the dataset's " +
                                   std::to_string(count) + " camera" + (count == 1 ? "" : "s") + ")"
                             : " (moschini with 2+ cameras, monocular with one)") +
                "; add --method " + wanted + ", or leave " + flag + " out");
      }
    }
  });
}

void apply_sweep_track_options(const std::vector<std::pair<std::string, std::string>>& keys,
                               const std::vector<int>& lines,
                               const std::filesystem::path& sweep_file,
                               tracker::TrackOptions& options) {
  CLI::App parser;
  add_track_options(&parser, options, TrackOptionScope::track);
  for (size_t i = 0; i < keys.size(); ++i) {
    const auto& [key, value] = keys[i];
    const int line = i < lines.size() ? lines[i] : 0;
    std::string_view flag;
    std::string known;
    for (const auto& [k, f] : kSweepKeys) {
      if (k == key) flag = f;
      known += (known.empty() ? "" : ", ") + std::string(k);
    }
    if (flag.empty()) {
      throw_input_error(sweep_file, line, "track." + key,
                        "unknown tracker option; expected one of " + known);
    }
    try {
      // CLI11 takes the arguments in reverse order.
      parser.parse(std::vector<std::string>{value, std::string(flag)});
    } catch (const CLI::ParseError& e) {
      throw_input_error(sweep_file, line, "track." + key, e.what());
    }
  }
}

std::string track_options_text(const tracker::TrackOptions& o) {
  using namespace tracker;
  std::string s(name_of(kTrackMethods, o.method));
  if (o.method != TrackMethod::sik) {
    s += ", silhouettes " + std::string(name_of(kSilhouetteMethods, o.silhouettes));
  } else {
    s += ", effectors " + std::string(name_of(kEffectorSources, o.sik.effectors));
  }
  if (o.method == TrackMethod::triangulate) {
    const TriangulateOptions& t = o.triangulate;
    s += ", smooth " + std::string(name_of(kTemporalFilters, t.filter)) + ", max error " +
         shortest_text(t.triangulation.point.max_error_px) + " px";
  }
  if (o.method == TrackMethod::monocular) {
    const gomez::MonocularSettings& m = o.monocular.tracker;
    s += ", body " + std::string(name_of(gomez::kBodyKinds, m.body)) + ", " +
         (m.search == gomez::Search::particles
              ? std::to_string(m.filter.particles) + " particles, heuristics " +
                    heuristics_text(m.filter)
              : std::string("simplex"));
  }
  s += ", init " + std::string(name_of(kInitMethods, o.init));
  return o.actor.empty() ? s : s + ", actor " + o.actor;
}

}  // namespace simcap::cli
