// simcap detections DATASET -o det.json: a dataset's ground-truth keypoints in a detector's
// layout, with seeded Gaussian pixel noise, written as COCO keypoint results.
#include <cstdio>
#include <memory>

#include "apps/simcap/choice_option.h"
#include "apps/simcap/commands.h"
#include "apps/simcap/number_checks.h"
#include "validate/noisy_detections.h"

namespace simcap::cli {

void add_detections(CLI::App& app, Action& action) {
  struct Options {
    std::string dataset, output;
    KeypointLayoutId layout = KeypointLayoutId::coco17;
    TruthNoise noise;
    bool quiet = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "detections",
      "Write a dataset's true 2D keypoints plus Gaussian pixel noise as a detector's output");
  cmd->add_option("dataset", o->dataset, "Dataset folder (simcap render's output)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", o->output, "COCO keypoint results file to write (.json)")
      ->required();
  add_choice(cmd, "--layout", o->layout, kKeypointLayouts, "Keypoint layout of the detections");
  cmd->add_option("--noise-px", o->noise.sigma_px,
                  "Standard deviation of the noise added to each pixel coordinate")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--seed", o->noise.seed, "Seed of the noise")
      ->capture_default_str()
      ->check(non_negative_number());
  cmd->add_flag("-q,--quiet", o->quiet, "No summary on stderr");
  cmd->footer(
      "Every actor with pixels in an image is one person (score 1); each keypoint with ground\n"
      "truth that is in the image is detected at its true pixel plus N(0, noise^2) in x and y;\n"
      "the others (out of frame, or without ground truth in simcap: see validate/README.md)\n"
      "are written as not detected (0, 0, 0). Same dataset and seed => the same file.\n"
      "Examples:\n"
      "  simcap detections out/studio4 -o out/studio4_det.json --noise-px 2 --seed 1\n"
      "  simcap detections out/studio4 -o bp.json --layout blazepose33\n"
      "  simcap validate out/studio4 --detections out/studio4_det.json -o out/det_report");
  cmd->callback([&action, o] {
    action = [o] {
      const KeypointTruth truth = read_keypoint_truth(o->dataset, o->layout);
      const Detections d = detections_from_truth(truth, o->noise);
      write_coco_results(d, o->output);
      if (!o->quiet) {
        std::fprintf(stderr, "wrote %s: %d people in %d frames x %zu cameras (%s, noise %g px)\n",
                     o->output.c_str(), d.people(), d.frames(), d.cameras().size(),
                     std::string(name_of(kKeypointLayouts, o->layout)).c_str(), o->noise.sigma_px);
      }
      return 0;
    };
  });
}

}  // namespace simcap::cli
