// simcap motion dump | retarget | generate: look inside BVH clips, retarget them onto the simcap
// humanoid with foot figures, and write procedural motions as BVH.
#include <cstdio>
#include <memory>

#include "apps/simcap/commands.h"
#include "apps/simcap/number_checks.h"
#include "core/joint_track.h"
#include "models/bvh.h"
#include "models/bvh_export.h"
#include "models/foot_contact.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "models/resample.h"
#include "models/retarget.h"

namespace simcap::cli {
namespace {

struct MotionOptions {
  std::string input, output, joints_csv;
  std::string asf;  // the input is an AMC motion of this ASF skeleton
  double amc_fps = 120.0;
  double metres_per_unit = 0.0;
  double height = 1.75;
  double fps = 0.0;
  bool no_floor = false;
  ProceduralSpec spec;
};

void write_positions(const std::string& path, const Skeleton& skeleton, const Motion& motion) {
  JointTrack track;
  for (const auto& j : skeleton.joints()) track.joints.push_back(j.name);
  for (size_t f = 0; f < motion.frames.size(); ++f) {
    track.add_frame(static_cast<int>(f), joint_positions(skeleton, motion.frames[f]));
  }
  write_joint_track(path, track);
}

BvhClip clip_of(const MotionOptions& o) {
  MotionSource source;
  (o.asf.empty() ? source.bvh : source.amc) = o.input;
  source.asf = o.asf;
  source.amc_fps = o.amc_fps;
  source.bvh_metres_per_unit = o.metres_per_unit;
  return read_motion_clip(source);
}

int dump(const MotionOptions& o) {
  const BvhClip clip = clip_of(o);
  JointTrack track;
  for (const auto& j : clip.joints) track.joints.push_back(j.name);
  for (int f = 0; f < clip.frame_count(); ++f) track.add_frame(f, bvh_joint_positions(clip, f));
  write_joint_track(o.output, track);
  std::fprintf(stderr,
               "%s: %zu joints and end sites x %d frames, %.9g m per file unit (%s) -> %s\n",
               o.input.c_str(), clip.joints.size(), clip.frame_count(), clip.metres_per_unit,
               clip.units_detected ? "detected" : "given", o.output.c_str());
  return 0;
}

int retarget(const MotionOptions& o) {
  const BvhClip clip = clip_of(o);
  const Skeleton skeleton = build_humanoid({.height = o.height, .proportions = {}});
  const Retargeted result = retarget_bvh(clip, skeleton, {.place_on_floor = !o.no_floor});
  const RetargetReport& r = result.report;
  if (!r.unmapped.empty()) {
    std::string names;
    for (const auto& n : r.unmapped) names += (names.empty() ? "" : ", ") + n;
    std::fprintf(stderr, "simcap motion retarget: %zu BVH joints not mapped (motion lost): %s\n",
                 r.unmapped.size(), names.c_str());
  }
  std::printf("%s: %d frames at %.6g fps, %.9g m per file unit (%s), humanoid height %.3f m\n",
              o.input.c_str(), clip.frame_count(), clip.fps(), clip.metres_per_unit,
              clip.units_detected ? "detected" : "given", o.height);
  std::printf("%s", r.summary().c_str());
  const Motion motion = o.fps > 0 ? resample_motion(result.motion, o.fps) : result.motion;
  if (!o.output.empty()) write_bvh(o.output, skeleton, motion);
  if (!o.joints_csv.empty()) write_positions(o.joints_csv, skeleton, motion);
  return 0;
}

int generate(const MotionOptions& o) {
  const Skeleton skeleton = build_humanoid({.height = o.height, .proportions = {}});
  const Motion motion = generate_procedural(o.spec, skeleton, o.fps > 0 ? o.fps : 30.0);
  std::printf("%s: %zu frames at %.6g fps, humanoid height %.3f m\nfeet: %s\n", o.spec.kind.c_str(),
              motion.frames.size(), motion.fps, o.height,
              measure_feet(humanoid_feet(skeleton, motion)).summary().c_str());
  write_bvh(o.output, skeleton, motion);
  if (!o.joints_csv.empty()) write_positions(o.joints_csv, skeleton, motion);
  return 0;
}

}  // namespace

void add_motion(CLI::App& app, Action& action) {
  auto* motion = app.add_subcommand(
      "motion", "Inspect BVH clips, retarget them onto the simcap humanoid, generate motions");
  motion->require_subcommand(1);
  motion->footer(
      "Examples:\n"
      "  simcap motion dump walk.bvh -o joints.csv\n"
      "  simcap motion retarget walk.bvh -o walk_simcap.bvh --fps 30\n"
      "  simcap motion generate walk_path -o walk.bvh --duration 6");
  auto o = std::make_shared<MotionOptions>();
  auto add_unit = [o](CLI::App* cmd) {
    cmd->add_option("--metres-per-unit", o->metres_per_unit,
                    "Metres per file unit; 0: BVH detects it from the skeleton's size, AMC takes "
                    "the ASF's :units length (CMU: 0.0564444)")
        ->check(non_negative_number())
        ->capture_default_str();
    cmd->add_option("--asf", o->asf,
                    "The file is an Acclaim AMC motion of this ASF skeleton (CMU's own format)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--amc-fps", o->amc_fps, "Frame rate of the AMC file (CMU: 120)")
        ->check(positive_number())
        ->capture_default_str();
  };

  auto* d = motion->add_subcommand(
      "dump",
      "Write the clip's joint world positions for every frame: frame,joint,x,y,z in metres, the "
      "file's own joint names (an AMC's: each bone at its proximal end, root for the root), end "
      "sites as <Parent>_End; no retargeting");
  d->add_option("file", o->input, "BVH file, or AMC file with --asf")->required();
  d->add_option("-o,--output", o->output, "CSV file to write")->required();
  add_unit(d);
  d->footer(
      "Examples:\n"
      "  simcap motion dump models/assets/cmu_131_01_start_walk_stop.bvh -o joints.csv\n"
      "  simcap motion dump 131_01.amc --asf 131.asf -o joints.csv");
  d->callback([&action, o] { action = [o] { return dump(*o); }; });

  auto* r = motion->add_subcommand(
      "retarget",
      "Retarget a BVH clip onto the simcap humanoid; print the joint mapping and the foot "
      "figures (lowest foot point height, sliding in contact); optionally write the result");
  r->add_option("file", o->input, "BVH file, or AMC file with --asf")->required();
  r->add_option("-o,--output", o->output, "BVH file of the retargeted motion (H-Anim names)");
  r->add_option("--joints-csv", o->joints_csv,
                "Also write its joint positions (frame,joint,x,y,z)");
  r->add_option("--height", o->height, "Humanoid height in metres")
      ->check(CLI::Range(0.5, 2.6))
      ->capture_default_str();
  r->add_option("--fps", o->fps, "Resample the output to this frame rate (0: the clip's)")
      ->check(non_negative_number())
      ->capture_default_str();
  r->add_flag("--no-floor", o->no_floor, "Keep the clip's height instead of putting feet on y = 0");
  add_unit(r);
  r->footer(
      "Example:\n"
      "  simcap motion retarget models/assets/cmu_131_01_start_walk_stop.bvh -o walk.bvh --fps "
      "30");
  r->callback([&action, o] { action = [o] { return retarget(*o); }; });

  auto* g = motion->add_subcommand(
      "generate", "Generate a procedural motion for the simcap humanoid and write it as BVH");
  g->add_option("kind", o->spec.kind,
                "The kind of motion (scenes/README.md, actors: procedural, describes each)")
      ->required()
      ->check(CLI::IsMember(procedural_kinds()));
  g->add_option("-o,--output", o->output, "BVH file to write")->required();
  g->add_option("--joints-csv", o->joints_csv,
                "Also write its joint positions (frame,joint,x,y,z)");
  g->add_option("--duration", o->spec.duration_s, "Seconds")
      ->check(non_negative_number())
      ->capture_default_str();
  g->add_option("--fps", o->fps, "Frames per second (default 30)")->check(positive_number());
  g->add_option("--speed", o->spec.speed_m_s,
                "Walking speed in m/s (walk_path); step rate scale (walk_in_place, turn)")
      ->check(positive_number())
      ->capture_default_str();
  g->add_option("--radius", o->spec.path_radius, "Radius of the walk_path circle in metres")
      ->check(positive_number())
      ->capture_default_str();
  g->add_option("--turn", o->spec.turn_degrees, "Degrees to turn (turn)")->capture_default_str();
  g->add_option("--height", o->height, "Humanoid height in metres")
      ->check(CLI::Range(0.5, 2.6))
      ->capture_default_str();
  g->footer("Example:\n  simcap motion generate walk_path -o walk.bvh --duration 6 --radius 1.5");
  g->callback([&action, o] { action = [o] { return generate(*o); }; });
}

}  // namespace simcap::cli
