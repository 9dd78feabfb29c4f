// simcap bench ik [BVH]: time per frame of SIK, CCD and DLS on the same clip, skeleton and
// limits, as ratios to SIK measured in the same process (Unzueta's Table 10, last rows).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "apps/simcap/bench_commands.h"
#include "apps/simcap/number_checks.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tracker/ik_eval.h"

namespace simcap::cli {
namespace {

struct BenchIkArgs {
  std::filesystem::path motion;
  int repeat = 3;
};

// Thesis Table 10, median ms per frame averaged over its three clips (Pentium 4, 2.66 GHz).
constexpr double kThesisMs[] = {0.44, 0.89, 9.35};
constexpr const char* kMethods[] = {"sik", "ccd", "dls"};
// The performance budget for SIK (ARCHITECTURE.md).
constexpr double kSikBudgetMs = 0.05;

int run_bench_ik(const BenchIkArgs& a) {
  std::optional<IkClip> clip;
  std::string what;
  if (a.motion.empty()) {
    // No clip given: simcap's procedural walk on the canonical humanoid, 10 s at 120 fps.
    Skeleton skeleton = build_humanoid();
    ProceduralSpec walk;
    walk.duration_s = 10.0;
    Motion motion = generate_procedural(walk, skeleton, 120.0);
    clip.emplace(IkClip{SikBody(std::move(skeleton)), std::move(motion)});
    what = "procedural walk_path on build_humanoid()";
  } else {
    clip.emplace(load_ik_clip(a.motion, true));
    what = a.motion.filename().string();
  }
  const std::vector<int> joints = table10_joints(clip->body);
  const double height = table10_height(clip->body);
  std::printf("clip: %s, %zu frames, median of %d runs\n", what.c_str(), clip->motion.frames.size(),
              a.repeat);
  std::printf("%-6s %12s %10s %12s %12s %10s %12s\n", "method", "ms/frame", "x sik", "thesis ms",
              "thesis x sik", "pos_err", "orient_err");
  double ms[3] = {0, 0, 0};
  for (int m = 0; m < 3; ++m) {
    const auto solver = make_ik_solver(kMethods[m], clip->body, {});
    std::vector<double> runs;
    IkEvalResult r;
    for (int i = 0; i < a.repeat; ++i) {
      r = evaluate_ik(*solver, clip->motion, joints, height);
      runs.push_back(r.ms_per_frame);
    }
    std::nth_element(runs.begin(), runs.begin() + runs.size() / 2, runs.end());
    ms[m] = runs[runs.size() / 2];
    std::printf("%-6s %12.5f %10.2f %12.2f %12.2f %10.4f %12.4f\n", kMethods[m], ms[m],
                ms[m] / ms[0], kThesisMs[m], kThesisMs[m] / kThesisMs[0], r.position_error,
                r.orientation_error);
  }
  std::printf("SIK budget %.2f ms/frame: %s\n", kSikBudgetMs,
              ms[0] <= kSikBudgetMs ? "met" : "missed");
  std::printf("ms_per_frame sik=%.5f ccd=%.5f dls=%.5f\n", ms[0], ms[1], ms[2]);
  return 0;
}

}  // namespace

void add_bench_ik(CLI::App& bench, Action& action) {
  auto* cmd = bench.add_subcommand("ik", "SIK, CCD and DLS time per frame");
  static BenchIkArgs args;
  cmd->add_option("motion", args.motion,
                  "BVH clip (default: a 10 s procedural walk on the canonical humanoid)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--repeat", args.repeat, "Runs per method; the median is reported")
      ->check(positive_number())
      ->capture_default_str();
  cmd->footer(
      "Examples:\n"
      "  simcap bench ik\n"
      "  simcap bench ik cmu_131_01_start_walk_stop.bvh --repeat 5\n"
      "Each method runs on the same skeleton, limits and pelvis estimate (weights 1,1,0); the\n"
      "time is the median solve time per frame. The last line is\n"
      "ms_per_frame sik=<x> ccd=<y> dls=<z>.");
  cmd->callback([&action] { action = [] { return run_bench_ik(args); }; });
}

}  // namespace simcap::cli
