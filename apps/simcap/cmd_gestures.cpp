// `simcap gestures`: Unzueta's gesture spotting and recognition scored on rendered corpora.
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "apps/simcap/commands.h"
#include "apps/simcap/gesture_summary.h"
#include "core/error.h"
#include "tracker/unzueta/gesture_job.h"

namespace simcap::cli {
namespace {

struct GesturesArgs {
  std::vector<std::filesystem::path> inputs;  // DATASET TRACK pairs
  std::filesystem::path out;
  tracker::GestureOptions options;
};

int run_gestures(const GesturesArgs& args) {
  if (args.inputs.size() < 4 || args.inputs.size() % 2 != 0) {
    throw Error("gestures: expected DATASET TRACK pairs, at least two (one per subject), got " +
                std::to_string(args.inputs.size()) + " folders");
  }
  std::vector<tracker::GestureSource> sources;
  for (size_t i = 0; i < args.inputs.size(); i += 2) {
    sources.push_back({args.inputs[i], args.inputs[i + 1]});
  }
  const tracker::GestureResults r = tracker::run_gestures(sources, args.out, args.options);
  std::printf("%s", gestures_summary_text(r, args.out).c_str());
  return 0;
}

}  // namespace

void add_gestures(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "gestures",
      "Spot and recognise gestures in tracked corpora (Unzueta 2009 ch. 5), leave-one-subject-out");
  static GesturesArgs args;
  cmd->add_option("inputs", args.inputs,
                  "DATASET TRACK pairs: a dataset with gt/gestures.csv and a track of it "
                  "(joints3d.csv; DATASET/gt itself scores the truth); one pair per subject")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", args.out, "Folder for gestures.json, spotted.csv and report.html")
      ->required();
  auto& o = args.options;
  cmd->add_option("--smooth", o.smooth_sigma,
                  "Gaussian smoothing of the tracked paths over time, sigma in frames (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 30.0));
  cmd->add_option("--history", o.spotting.history,
                  "Frames in the kinetic pseudo-energy history (Table 12)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  cmd->add_option("--threshold", o.spotting.threshold,
                  "Threshold on the mean pseudo-energy |v|^2/2 of a hand, (m/s)^2")
      ->capture_default_str()
      ->check(CLI::Range(1e-4, 100.0));
  cmd->add_option("--min-frames", o.spotting.min_frames,
                  "A stretch whose pseudo-energy history stays above the threshold for fewer "
                  "frames is dropped")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--drop-largest", o.spotting.drop_largest,
                  "The history's mean leaves out its N largest pseudo-energies (0: the thesis)")
      ->capture_default_str()
      ->check(CLI::Range(0, 99));
  cmd->add_option("--end-delay", o.spotting.delay_at_end,
                  "Where Algorithm 14's delay that moves a stretch's end back is measured: 'start' "
                  "(the thesis: the start's delay moves both ends) or 'end' (measured again where "
                  "the history falls below the threshold)")
      ->transform(
          CLI::CheckedTransformer(std::map<std::string, bool>{{"start", false}, {"end", true}}))
      ->default_str("end");
  cmd->add_option(
         "--velocity-median", o.spotting.velocity_median,
         "Each hand velocity coordinate is the median of this many frames before the "
         "pseudo-energy is taken, odd (1: the thesis); a tracked point's jump is no motion")
      ->capture_default_str()
      ->check(CLI::Range(1, 31))
      ->check(CLI::Validator(
          [](const std::string& v) {
            return std::stoi(v) % 2 == 1 ? std::string() : "expected an odd number, got " + v;
          },
          "ODD"));
  cmd->add_option("--path-speed", o.path_speed_fraction,
                  "The path recognised is the spotted stretch widened to where the hand's speed "
                  "falls below this fraction of its peak in the stretch (0: the thesis, the "
                  "stretch itself)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--states", o.states, "Spline-resampled states per gesture (Table 12)")
      ->capture_default_str()
      ->check(CLI::Range(2, 1000));
  cmd->add_option("-k", o.k, "Neighbours of the K-NN classifiers")
      ->capture_default_str()
      ->check(CLI::Range(1, 15));
  cmd->footer(
      "Each pair is one subject's corpus; each is recognised by classifiers (K-NN and an SVM,\n"
      "OpenCV ml) trained on the spotted gestures and held poses of the others. Writes\n"
      "OUT/gestures.json (spotting precision/recall/F1, confusion matrices, accuracies),\n"
      "OUT/spotted.csv and OUT/report.html (the scores, and per subject and hand the\n"
      "pseudo-energy against the threshold with the true and spotted gestures); the last line is "
      "spotting_f1=F recognition_accuracy=A.\n"
      "Examples:\n"
      "  simcap render scenes/gestures.yaml -o out/g1 --seed 1\n"
      "  simcap render scenes/gestures.yaml -o out/g2 --seed 2\n"
      "  simcap track out/g1 -o out/t1 --method sik --effectors depth --init auto\n"
      "  simcap track out/g2 -o out/t2 --method sik --effectors depth --init auto\n"
      "  simcap gestures out/g1 out/t1 out/g2 out/t2 -o out/gestures\n"
      "  simcap gestures out/g1 out/g1/gt out/g2 out/g2/gt -o out/gestures_truth");
  cmd->callback([&action] { action = [] { return run_gestures(args); }; });
}

}  // namespace simcap::cli
