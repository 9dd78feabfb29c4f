// simcap ik-eval MOTION.bvh: Unzueta's Table 10 for one solver on one clip (see tracker/ik_eval.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/simcap/commands.h"
#include "apps/simcap/number_checks.h"
#include "core/atomic_file.h"
#include "core/csv.h"
#include "tracker/unzueta/ik_eval.h"

namespace simcap::cli {
namespace {

struct IkEvalArgs {
  std::filesystem::path motion, out;
  std::string method = "sik";
  std::vector<double> pelvis_weights = {1.0, 1.0, 0.0};
  double damping = 0.75;
  bool no_limits = false;
  bool anatomical_hinges = false;
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

int run_ik_eval(const IkEvalArgs& a) {
  const IkClip clip = load_ik_clip(a.motion, !a.anatomical_hinges, a.frames);
  IkSolverSettings settings;
  settings.pelvis_weights = {a.pelvis_weights[0], a.pelvis_weights[1], a.pelvis_weights[2]};
  settings.limits = !a.no_limits;
  settings.dls_damping = a.damping;
  const auto solver = make_ik_solver(a.method, clip.body, settings);
  const std::vector<int> joints = table10_joints(clip.body);
  const IkEvalResult r = evaluate_ik(*solver, clip.motion, joints, table10_height(clip.body));
  const Skeleton& sk = clip.body.skeleton();

  CsvWriter frames(a.out / "frame_errors.csv", {"frame", "position_error", "orientation_error"});
  CsvWriter per_joint(a.out / "joint_errors.csv",
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
                            {"method", a.method},
                            {"frames", r.frame_position.size()},
                            {"fps", clip.motion.fps},
                            {"height_m", r.height},
                            {"pelvis_weights", a.pelvis_weights},
                            {"limits", !a.no_limits},
                            {"hinge_axes", a.anatomical_hinges ? "anatomical" : "from the clip"},
                            {"position_error", r.position_error},
                            {"orientation_error", r.orientation_error},
                            {"ms_per_frame", r.ms_per_frame}};
  if (a.method == "dls") summary["dls_damping_m"] = a.damping;
  std::printf("%s on %s: %zu frames at %.0f fps, %zu joints, height %.3f m\n", a.method.c_str(),
              a.motion.filename().c_str(), r.frame_position.size(), clip.motion.fps, joints.size(),
              r.height);
  std::printf("%-22s %12s %16s\n", "joint", "mean pos (m)", "mean orient (rad)");
  for (size_t k = 0; k < joints.size(); ++k) {
    double p = 0.0, o = 0.0;
    for (size_t f = 0; f < r.joint_position.size(); ++f) {
      p += r.joint_position[f][k];
      o += r.joint_orientation[f][k];
    }
    p /= r.joint_position.size();
    o /= r.joint_position.size();
    summary["joints"][sk[joints[k]].name] = {{"position_m", p}, {"orientation_rad", o}};
    std::printf("%-22s %12.4f %16.4f\n", sk[joints[k]].name.c_str(), p, o);
  }
  summary["worst_seconds"] = worst_seconds(r, clip.motion.fps, 3);
  for (const auto& w : summary["worst_seconds"]) {
    std::printf("worst second: frames %d-%d, position error %.4f\n", w["first_frame"].get<int>(),
                w["last_frame"].get<int>(), w["position_error"].get<double>());
  }
  frames.commit();
  per_joint.commit();
  write_text_atomic(a.out / "summary.json", summary.dump(2) + "\n");
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
                  "Folder for frame_errors.csv, joint_errors.csv and "
                  "summary.json")
      ->required();
  cmd->add_option("--method", args.method, "Solver: sik, ccd or dls")
      ->check(CLI::IsMember({"sik", "ccd", "dls"}))
      ->capture_default_str();
  cmd->add_option("--pelvis-weights", args.pelvis_weights,
                  "Weights of the wrist, ankle and previous-frame vectors in the pelvis X axis "
                  "(thesis: 1,1,0 for Boxing and Jump Kick; 0.1,0.1,1 for Playground)")
      ->expected(3)
      ->delimiter(',')
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_option("--damping", args.damping,
                  "DLS damping factor in metres (the thesis' 75, read as centimetres)")
      ->check(positive_number())
      ->capture_default_str();
  cmd->add_flag("--no-limits", args.no_limits, "Do not apply the biomechanical joint limits");
  cmd->add_flag("--anatomical-hinges", args.anatomical_hinges,
                "Use anatomical elbow and knee axes instead of the clip's own");
  cmd->add_option("--frames", args.frames, "Evaluate only the first N frames (default: all)")
      ->check(non_negative_number());
  cmd->footer(
      "Examples:\n"
      "  simcap ik-eval cmu_131_01_start_walk_stop.bvh --method sik -o out/ik/sik_walk\n"
      "  simcap ik-eval cmu_131_03_start_hop_stop.bvh --method dls --damping 0.075 -o out/ik/dls\n"
      "Feeds the clip's pelvis, skull base, wrists and ankles frame by frame to the solver on the\n"
      "clip's own skeleton and scores 22 joints (all but those below wrists and ankles; CMU's two\n"
      "pelvis bones once). pos_err = RMS over frames of (sum of joint position errors) /\n"
      "(height x joints), height = calf + thigh + pelvis + torso + neck; orient_err = RMS over\n"
      "frames of (sum of |log(R_true^-1 R)| relative to the parent) / joints; ms_per_frame = "
      "median\n"
      "solve time. The last line is pos_err=<x> orient_err=<y> ms_per_frame=<z>.");
  cmd->callback([&action] { action = [] { return run_ik_eval(args); }; });
}

}  // namespace simcap::cli
