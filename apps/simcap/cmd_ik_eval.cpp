// simcap ik-eval MOTION.bvh: Unzueta's Table 10 for one solver on one clip (see tracker/ik_eval.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/simcap/commands.h"
#include "apps/simcap/number_checks.h"
#include "apps/simcap/sik_cue_options.h"
#include "core/atomic_file.h"
#include "core/csv.h"
#include "tracker/unzueta/ik_eval.h"

namespace simcap::cli {
namespace {

struct IkEvalArgs {
  std::filesystem::path motion, out;
  std::string method = "sik";
  std::vector<double> pelvis_weights = {1.0, 1.0, 0.0};
  double pelvis_travel = kSikPelvisTravel;
  double damping = 0.75;
  bool no_limits = false;
  bool anatomical_hinges = false;
  bool known_orientations = false;
  bool middle_targets = false;
  std::string swivel = "neutral";
  SikSpineBend spine_bend = SikSpineBend::lean;
  int frames = 0;
};

// The `count` one-second windows with the largest RMS normalised position error.
nlohmann::json worst_seconds(const IkEvalResult& r, double fps, int count) {
  const int window = std::max(1, static_cast<int>(std::lround(fps)));
  std::vector<std::pair<double, int>> windows;
  for (size_t start = 0; start < r.frame_position.size(); start += window) {
    const size_t end = std::min(r.frame_position.size(), start + window);
    double s = 0.0;
    for (size_t f = start; f < end; ++f) s += r.frame_position[f] * r.frame_position[f];
    windows.push_back({std::sqrt(s / (end - start)), static_cast<int>(start)});
  }
  std::sort(windows.rbegin(), windows.rend());
  nlohmann::json out = nlohmann::json::array();
  for (int i = 0; i < std::min<int>(count, windows.size()); ++i) {
    const int start = windows[i].second;
    const int end = std::min<int>(r.frame_position.size(), start + window) - 1;
    out.push_back(
        {{"first_frame", start}, {"last_frame", end}, {"position_error", windows[i].first}});
  }
  return out;
}

// Evaluates one solver on the clip and writes its files to `out`; prints the per-joint table
// when `verbose`.
IkEvalResult evaluate_solver(const IkEvalArgs& a, const IkClip& clip, const std::string& method,
                             const std::filesystem::path& out, bool verbose) {
  IkSolverSettings settings;
  settings.pelvis_weights = {a.pelvis_weights[0], a.pelvis_weights[1], a.pelvis_weights[2],
                             a.pelvis_travel};
  settings.limits = !a.no_limits;
  settings.dls_damping = a.damping;
  settings.sik_swivel = a.swivel == "reference"        ? SikSwivel::reference
                        : a.swivel == "least-rotation" ? SikSwivel::least_rotation
                                                       : SikSwivel::neutral;
  settings.spine_bend = a.spine_bend;
  const auto solver = make_ik_solver(method, clip.body, settings);
  const std::vector<int> joints = table10_joints(clip.body);
  const IkEvalResult r =
      evaluate_ik(*solver, clip.motion, joints, table10_height(clip.body),
                  {.known_orientations = a.known_orientations, .middle_targets = a.middle_targets});
  const Skeleton& sk = clip.body.skeleton();

  CsvWriter frames(out / "frame_errors.csv", {"frame", "position_error", "orientation_error"});
  CsvWriter per_joint(out / "joint_errors.csv",
                      {"frame", "joint", "position_error_m", "orientation_error_rad"});
  char line[200];
  for (size_t f = 0; f < r.frame_position.size(); ++f) {
    std::snprintf(line, sizeof line, "%zu,%.7f,%.7f\n", f, r.frame_position[f],
                  r.frame_orientation[f]);
    frames.out() << line;
    for (size_t k = 0; k < joints.size(); ++k) {
      std::snprintf(line, sizeof line, "%zu,%s,%.7f,%.7f\n", f, sk[joints[k]].name.c_str(),
                    r.joint_position[f][k], r.joint_orientation[f][k]);
      per_joint.out() << line;
    }
  }

  nlohmann::json summary = {{"motion", a.motion.string()},
                            {"method", method},
                            {"frames", r.frame_position.size()},
                            {"fps", clip.motion.fps},
                            {"height_m", r.height},
                            {"pelvis_weights", a.pelvis_weights},
                            {"pelvis_travel", a.pelvis_travel},  // sik's and tgbsik's
                            {"limits", !a.no_limits},
                            {"hinge_axes", a.anatomical_hinges ? "anatomical" : "from the clip"},
                            {"known_orientations", a.known_orientations},
                            {"middle_targets", a.middle_targets},
                            {"sik_swivel", a.swivel},
                            {"spine_bend", name_of(kSikSpineBends, a.spine_bend)},
                            {"position_error", r.position_error},
                            {"orientation_error", r.orientation_error},
                            {"ms_per_frame", r.ms_per_frame}};
  if (method.starts_with("dls")) summary["dls_damping_m"] = a.damping;
  if (verbose) {
    std::printf("%s on %s: %zu frames at %.0f fps, %zu joints, height %.3f m\n", method.c_str(),
                a.motion.filename().c_str(), r.frame_position.size(), clip.motion.fps,
                joints.size(), r.height);
    std::printf("%-22s %12s %16s\n", "joint", "mean pos (m)", "mean orient (rad)");
  }
  for (size_t k = 0; k < joints.size(); ++k) {
    double p = 0.0, o = 0.0;
    for (size_t f = 0; f < r.joint_position.size(); ++f) {
      p += r.joint_position[f][k];
      o += r.joint_orientation[f][k];
    }
    p /= r.joint_position.size();
    o /= r.joint_position.size();
    summary["joints"][sk[joints[k]].name] = {{"position_m", p}, {"orientation_rad", o}};
    if (verbose) std::printf("%-22s %12.4f %16.4f\n", sk[joints[k]].name.c_str(), p, o);
  }
  summary["worst_seconds"] = worst_seconds(r, clip.motion.fps, 3);
  if (verbose) {
    for (const auto& w : summary["worst_seconds"]) {
      std::printf("worst second: frames %d-%d, position error %.4f\n", w["first_frame"].get<int>(),
                  w["last_frame"].get<int>(), w["position_error"].get<double>());
    }
  }
  frames.commit();
  per_joint.commit();
  write_text_atomic(out / "summary.json", summary.dump(2) + "\n");
  return r;
}

// Every solver on the clip, one row each beside the thesis' Table 10 averages.
int run_all(const IkEvalArgs& a, const IkClip& clip) {
  std::printf(
      "Table 10 on %s: %zu frames at %.0f fps (thesis: averages over Boxing, Jump Kick "
      "and Playground, Pentium 4)\n",
      a.motion.filename().c_str(), clip.motion.frames.size(), clip.motion.fps);
  std::printf("%-8s %9s %11s %10s %12s %14s %13s\n", "method", "pos_err", "orient_err", "ms/frame",
              "thesis pos", "thesis orient", "thesis ms");
  CsvWriter table(a.out / "table10.csv",
                  {"method", "position_error", "orientation_error", "ms_per_frame",
                   "thesis_position_error", "thesis_orientation_error", "thesis_ms_per_frame"});
  std::string best;
  double best_position = 0.0;
  char line[300];
  for (const Table10Column& thesis : thesis_table10()) {
    const IkEvalResult r =
        evaluate_solver(a, clip, thesis.method, a.out / thesis.method, /*verbose=*/false);
    std::printf("%-8s %9.4f %11.4f %10.4f %12.4f %14.4f %13.2f\n", thesis.method.c_str(),
                r.position_error, r.orientation_error, r.ms_per_frame, thesis.position_error,
                thesis.orientation_error, thesis.ms_per_frame);
    std::snprintf(line, sizeof line, "%s,%.7f,%.7f,%.5f,%.4f,%.4f,%.2f\n", thesis.method.c_str(),
                  r.position_error, r.orientation_error, r.ms_per_frame, thesis.position_error,
                  thesis.orientation_error, thesis.ms_per_frame);
    table.out() << line;
    if (best.empty() || r.position_error < best_position) {
      best = thesis.method;
      best_position = r.position_error;
    }
  }
  table.commit();
  std::printf("solvers=%zu best_pos=%s best_pos_err=%.4f\n", ik_solver_names().size(), best.c_str(),
              best_position);
  return 0;
}

int run_ik_eval(const IkEvalArgs& a) {
  const IkClip clip = load_ik_clip(a.motion, !a.anatomical_hinges, a.frames);
  if (a.method == "all") return run_all(a, clip);
  const IkEvalResult r = evaluate_solver(a, clip, a.method, a.out, /*verbose=*/true);
  std::printf("pos_err=%.4f orient_err=%.4f ms_per_frame=%.5f\n", r.position_error,
              r.orientation_error, r.ms_per_frame);
  return 0;
}

}  // namespace

void add_ik_eval(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "ik-eval", "Evaluate an inverse-kinematics solver on a motion clip (Unzueta's Table 10)");
  static IkEvalArgs args;
  cmd->add_option("motion", args.motion, "BVH motion clip (its true joints are the reference)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args.out,
                  "Folder for frame_errors.csv, joint_errors.csv and summary.json (with "
                  "--method all: table10.csv and one such folder per solver)")
      ->required();
  std::vector<std::string> methods = ik_solver_names();
  methods.push_back("all");
  cmd->add_option(
         "--method,--solver", args.method,
         "Solver: sik, ccd, pinv (pseudoinverse), dls, dls-svd, sdls (selectively "
         "damped least squares), pik (Baerlocher & Boulic's prioritized IK), tgbsik (SIK with the "
         "swivel of least shoulder and hip "
         "rotation), kma (CCD spine from the standing pose, TGB limbs with zero swivel), or "
         "all (Table 10 side by side, one subfolder each)")
      ->check(CLI::IsMember(methods))
      ->capture_default_str();
  cmd->add_option("--pelvis-weights", args.pelvis_weights,
                  "Weights of the wrist, ankle and previous-frame vectors in the pelvis X axis "
                  "(thesis: 1,1,0 for Boxing and Jump Kick; 0.1,0.1,1 for Playground)")
      ->expected(3)
      ->delimiter(',')
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_option("--damping", args.damping,
                  "DLS and DLS-SVD damping factor in metres (the thesis' 75, read as "
                  "centimetres)")
      ->check(positive_number())
      ->capture_default_str();
  cmd->add_flag("--no-limits", args.no_limits, "Do not apply the biomechanical joint limits");
  cmd->add_flag("--anatomical-hinges", args.anatomical_hinges,
                "Use anatomical elbow and knee axes instead of the clip's own");
  cmd->add_flag("--known-orientations", args.known_orientations,
                "Also give the true pelvis and head orientations (SIK: Alg. 10-11 spine twist; "
                "not Table 10's setting; the baselines ignore them)");
  cmd->add_flag("--middle-targets", args.middle_targets,
                "Also give the true elbows and knees (SIK swivels each limb toward them; not "
                "Table 10's setting; the baselines ignore them)");
  cmd->add_option("--swivel", args.swivel,
                  "sik: the limbs' swivel: neutral (Alg. 13, from the stretched limb), "
                  "least-rotation (TGBSIK's), reference (KMA's: elbows toward the pelvis' -Y, "
                  "knees toward its +Z)")
      ->check(CLI::IsMember({"neutral", "least-rotation", "reference"}))
      ->capture_default_str();
  add_sik_cue_options(cmd, args.pelvis_travel, args.spine_bend, "sik, tgbsik: ");
  cmd->add_option("--frames", args.frames, "Evaluate only the first N frames (default: all)")
      ->check(positive_number());
  cmd->footer(
      "Examples:\n"
      "  simcap ik-eval models/assets/cmu_131_01_start_walk_stop.bvh --method sik -o "
      "out/ik/sik_walk\n"
      "  simcap ik-eval models/assets/cmu_131_03_start_hop_stop.bvh --method dls --damping 0.075 "
      "-o out/ik/dls\n"
      "  simcap ik-eval models/assets/cmu_131_03_start_hop_stop.bvh --method all -o "
      "out/ik/table10\n"
      "  simcap ik-eval models/assets/cmu_131_01_start_walk_stop.bvh --method sik "
      "--middle-targets -o out/ik/mid\n"
      "  simcap ik-eval models/assets/cmu_131_01_start_walk_stop.bvh --method sik "
      "--pelvis-travel 0 --spine-bend thesis -o out/ik/thesis_sik   (the thesis' SIK)\n"
      "Feeds the clip's pelvis, skull base, wrists and ankles frame by frame to the solver on the\n"
      "clip's own skeleton and scores 22 joints (all but those below wrists and ankles; CMU's two\n"
      "pelvis bones once). pos_err = RMS over frames of (sum of joint position errors) /\n"
      "(height x joints), height = calf + thigh + pelvis + torso + neck; orient_err = RMS over\n"
      "frames of (sum of |log(R_true^-1 R)| relative to the parent) / joints; ms_per_frame = "
      "median\n"
      "solve time. The last line is pos_err=<x> orient_err=<y> ms_per_frame=<z>; with --method "
      "all\n"
      "it is solvers=<n> best_pos=<method> best_pos_err=<x> after one row per solver.");
  cmd->callback([&action] { action = [] { return run_ik_eval(args); }; });
}

}  // namespace simcap::cli
