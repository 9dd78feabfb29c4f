// simcap track DATASET -o TRACK: run a tracker over a rendered (or real) dataset.
#include <cstdio>

#include "apps/simcap/commands.h"
#include "apps/simcap/number_checks.h"
#include "tracker/track_job.h"

namespace simcap::cli {

void add_track(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("track", "Run a tracker on a dataset and write its joints3d.csv");
  auto options = std::make_shared<TrackOptions>();
  auto dataset = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("DATASET", *dataset, "Dataset folder written by simcap render")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", *out, "Track folder to write (joints3d.csv, diagnostics/)")
      ->required();
  cmd->add_option("--method", options->method,
                  "Tracker: moschini (multi-camera hull, articulated ICP, EKF) or sik (sequential "
                  "inverse kinematics on the ground truth's end-effectors)")
      ->check(CLI::IsMember({"moschini", "sik"}))
      ->capture_default_str();
  cmd->add_option("--silhouettes", options->silhouettes,
                  "Silhouettes: gt (the dataset's masks), bgsub (Gaussian background model), "
                  "mog2 (OpenCV MOG2)")
      ->check(CLI::IsMember({"gt", "bgsub", "mog2"}))
      ->capture_default_str();
  cmd->add_option("--init", options->init,
                  "First pose: gt (ground truth of the first frame) or auto (the hull of a "
                  "person standing upright)")
      ->check(CLI::IsMember({"gt", "auto"}))
      ->capture_default_str();
  cmd->add_option("--voxel", options->voxel_m, "Visual hull voxel size, metres")
      ->check(CLI::Range(0.005, 0.2))
      ->capture_default_str();
  cmd->add_option("--joints", options->joints,
                  "moschini: joint set, moschini (Table 5.1, 23-parameter EKF) or urdf (adds hip "
                  "twists, a spine joint, wrists and ankles)")
      ->check(CLI::IsMember({"moschini", "urdf"}))
      ->capture_default_str();
  cmd->add_option("--appearance", options->appearance,
                  "moschini: learn the parts' colours on the first frame so that a silhouette "
                  "pixel only meets the parts it may show (an arm in front of the torso)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_option("--filter", options->filter,
                  "moschini: none (each frame's fit is the estimate) or ekf (Moschini's EKF "
                  "smooths the fits; it lags a moving body)")
      ->check(CLI::IsMember({"none", "ekf"}))
      ->capture_default_str();
  cmd->add_option("--traversal", options->traversal,
                  "moschini: on (each frame also tries Moschini's hierarchical ICP traversal and "
                  "keeps the better fit) or off (the joint refinement from the previous pose)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cmd->add_flag("--oracle", options->oracle,
                "moschini: start every frame from its ground-truth pose (a diagnostic: the error "
                "left is the body model's and the cues', not the search's)");
  cmd->add_option("--inspect", options->inspect,
                  "moschini: frames to lay open, comma-separated: per camera an image with the "
                  "silhouette's edge, centerline, capsule outlines and sticks drawn, and the "
                  "hull's voxels (diagnostics/inspect/FRAME/)")
      ->delimiter(',')
      ->check(non_negative_number());
  cmd->add_option("--sik-noise", options->sik_noise_m,
                  "sik: standard deviation of the noise added to the end-effectors, metres")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--seed", options->seed, "sik: seed of that noise")->capture_default_str();
  cmd->add_flag("-q,--quiet", options->quiet, "No progress on stderr");
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
      "Writes TRACK/joints3d.csv (frame,joint,x,y,z; the HE15 joints in H-Anim names) and\n"
      "TRACK/diagnostics/: centerline.csv, timings.csv, reinitializations.csv,\n"
      "body_dimensions.csv, for subtracted silhouettes silhouette_iou.csv, and with --inspect\n"
      "inspect/FRAME/camNN.png and hull.csv.");
  cmd->callback([&action, options, dataset, out] {
    action = [options, dataset, out] {
      const TrackSummary s = track_dataset(*dataset, *out, *options);
      if (!options->quiet) {
        std::fprintf(stderr,
                     "tracked %d frames in %.2f s (%.1f frames/s), %d re-initializations -> %s\n",
                     s.frames, s.seconds, s.frames / std::max(s.seconds, 1e-9), s.reinitializations,
                     s.track.string().c_str());
      }
      return 0;
    };
  });
}

}  // namespace simcap::cli
