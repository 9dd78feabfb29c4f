#include "bench/ik_bench.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tracker/unzueta/ik_eval.h"

namespace simcap {
namespace {

// Thesis Table 10, median ms per frame averaged over its three clips (Pentium 4, 2.66 GHz).
constexpr double kThesisMs[] = {0.44, 0.89, 9.35};
constexpr const char* kMethods[] = {"sik", "ccd", "dls"};
// The performance budget for SIK (ARCHITECTURE.md).
constexpr double kSikBudgetMs = 0.05;

}  // namespace

void run_ik_benchmark(const IkBenchOptions& a, std::FILE* out) {
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
  std::fprintf(out, "clip: %s, %zu frames, median of %d runs\n", what.c_str(),
               clip->motion.frames.size(), a.repeat);
  std::fprintf(out, "%-6s %12s %10s %12s %12s %10s %12s\n", "method", "ms/frame", "x sik",
               "thesis ms", "thesis x sik", "pos_err", "orient_err");
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
    std::fprintf(out, "%-6s %12.5f %10.2f %12.2f %12.2f %10.4f %12.4f\n", kMethods[m], ms[m],
                 ms[m] / ms[0], kThesisMs[m], kThesisMs[m] / kThesisMs[0], r.position_error,
                 r.orientation_error);
  }
  std::fprintf(out, "SIK budget %.2f ms/frame: %s\n", kSikBudgetMs,
               ms[0] <= kSikBudgetMs ? "met" : "missed");
  std::fprintf(out, "ms_per_frame sik=%.5f ccd=%.5f dls=%.5f\n", ms[0], ms[1], ms[2]);
}

}  // namespace simcap
