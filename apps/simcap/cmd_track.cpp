// simcap track DATASET -o TRACK: run a tracker over a rendered (or real) dataset.
#include <cstdio>
#include <filesystem>

#include "apps/simcap/commands.h"
#include "apps/simcap/track_cli.h"
#include "core/calibration.h"
#include "core/error.h"
#include "tracker/registry.h"

namespace simcap::cli {

namespace fs = std::filesystem;

void add_track(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("track", "Run a tracker on a dataset and write its joints3d.csv");
  auto options = std::make_shared<tracker::TrackOptions>();
  auto dataset = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("DATASET", *dataset, "Dataset folder written by simcap render")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", *out, "Track folder to write (joints3d.csv, diagnostics/)")
      ->required();
  add_track_options(cmd, *options, TrackOptionScope::track);
  refuse_other_methods_options(cmd, *options, [dataset] {
    try {
      return static_cast<int>(
          read_opencv_calibration(fs::path(*dataset) / "calibration" / "opencv.yaml").size());
    } catch (const Error&) {
      return 0;  // the track itself says what is wrong with the dataset
    }
  });
  cmd->footer(
      "Examples:\n"
      "  simcap track out/studio4 -o out/track\n"
      "  simcap track out/studio4 -o out/track_bg --silhouettes bgsub --init auto\n"
      "  simcap track out/studio4 -o out/track_masks --appearance off\n"
      "  simcap track out/studio4 -o out/track_thesis --joints moschini --traversal on "
      "--filter ekf --appearance off\n"
      "  simcap track out/studio4 -o out/track_oracle --oracle\n"
      "  simcap track out/studio4 -o out/track --inspect 0,100\n"
      "  simcap track out/studio4 -o out/track_sik --method sik --sik-noise 0.02\n"
      "  simcap track out/studio4 -o out/track_sik_px --method sik --effectors multiview\n"
      "  simcap track out/gestures -o out/track_depth --method sik --effectors depth --init auto\n"
      "  simcap track out/monocular -o out/track_mono --method monocular --particles 200\n"
      "  simcap track out/studio4 -o out/track --export bvh,x3d,bap\n"
      "  simcap track out/studio4 -o out/tri --method triangulate --detections det.json\n"
      "  simcap track out/studio4 -o out/first30 --frames 30\n"
      "Writes TRACK/joints3d.csv (frame,joint,x,y,z; the HE15 joints in H-Anim names) and\n"
      "TRACK/diagnostics/ (moschini: centerline.csv, timings.csv, reinitializations.csv,\n"
      "body_dimensions.csv, for subtracted silhouettes silhouette_iou.csv, and with --inspect\n"
      "inspect/FRAME/camNN.png and hull.csv; triangulate: people.csv, keypoints.csv, swaps.csv;\n"
      "each family's notes list its own). TRACK is written\n"
      "whole or not at all: a run that fails leaves a previous TRACK as it was.");
  cmd->callback([&action, options, dataset, out] {
    action = [options, dataset, out] {
      const TrackSummary s = tracker::track_dataset(*dataset, *out, *options);
      if (!options->quiet) {
        std::fprintf(stderr,
                     "tracked %d frames in %.2f s (%.1f frames/s), %d re-initializations -> %s\n",
                     s.frames, s.seconds, s.frames / std::max(s.seconds, 1e-9), s.reinitializations,
                     s.track.string().c_str());
      }
      std::fputs(without_person_warning(s).c_str(), stderr);
      return 0;
    };
  });
}

}  // namespace simcap::cli
