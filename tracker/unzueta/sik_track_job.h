// `simcap track --method sik`: SIK on a dataset's end-effectors -- the ground truth's (optionally
// noisy), or tracked from the pixels (unzueta_job.h) -- writing the solved humanoid's HE15 joints.
#pragma once

#include <cstdint>
#include <filesystem>

#include "core/joint_track.h"
#include "core/name_table.h"
#include "models/skeleton.h"
#include "tracker/common/init_method.h"
#include "tracker/common/silhouettes.h"
#include "tracker/common/track_summary.h"
#include "tracker/unzueta/camera_tracker.h"
#include "tracker/unzueta/sik.h"

namespace simcap {

// Where SIK's end-effector targets come from.
enum class EffectorSource {
  gt,         // the ground truth's joints (plus noise_sigma_m)
  depth,      // CFOF in one camera, lifted by its depth map: the thesis' "full 3D"
  mono,       // CFOF in one camera, each part at its starting depth: the thesis' "pseudo 3D"
  multiview,  // CFOF in every camera, triangulated
};
inline constexpr NameTable<EffectorSource, 4> kEffectorSources{
    {{"gt", EffectorSource::gt},
     {"depth", EffectorSource::depth},
     {"mono", EffectorSource::mono},
     {"multiview", EffectorSource::multiview}}};

struct SikTrackOptions {
  EffectorSource effectors = EffectorSource::gt;
  double noise_sigma_m = 0.0;  // gt
  std::uint64_t seed = 1;      // gt: seed of that noise
  // gt: also the truth's elbows and knees as SIK's optional middle targets (with the same noise).
  bool middle_targets = false;
  // From pixels: the first frame's ROIs and body from the ground truth (gt) or the calibration
  // posture (automatic); which silhouettes the pelvis comes from; the camera of depth and mono.
  tracker::InitMethod init = tracker::InitMethod::automatic;
  tracker::SilhouetteMethod silhouettes = tracker::SilhouetteMethod::gt;
  int camera = 0;
  tracker::CameraTrackerParams tracking;
  // --effectors depth reads a part's surface at this quantile of the depths under its pixels
  // (0: the nearest). A hand pointing at the camera is seen end-on over its forearm, whose
  // median depth lies 20-35 cm behind the hand; 0.1 fixes that (gest1: 45.4 -> 43.4 mm).
  double surface_quantile = 0.5;
  // --effectors depth: the occlusion rule (§3.3.1) orders overlapping parts by the depth read at
  // this quantile instead (the same part centre, from another surface depth). Which of two
  // overlapping blobs covers the other is a question about the blobs as a whole; the nearest
  // surface of a hand changed the rule's choices and lost hands for good (UNZUETA.md).
  double occlusion_quantile = 0.5;
  // --effectors depth: a part's surface lies at most this far (metres) behind its nearest pixels
  // (0: off): the median where the pixels are about as deep as the part, the near surface where
  // they run far behind it (the end-on hand). With the re-finding (0.05, refind 0.44, patience
  // 10) the gesture corpus' spotting F1 goes 0.45 -> 0.88, but the walks from four cameras lose
  // 12 (studio4) and 22 mm (hop4) on average, so it is off (UNZUETA.md).
  double surface_thickness = 0.0;
  // --effectors multiview: a part is triangulated from the cameras whose tracks agree within this
  // many pixels (part_consensus.h; 0: every tracking camera in one DLT, as before), and when
  // `multiview_reseed`, a camera that disagrees, predicts the part hidden or has lost it is moved
  // onto the agreed point (studio4 267.8 -> 172.4 mm, hop4 229.0 -> 211.8 mm; UNZUETA.md).
  double multiview_consensus_px = 12.0;
  bool multiview_reseed = true;
  // --effectors multiview (needs the consensus): a camera whose left and right hand (or foot)
  // tracks each follow the other limb, where the other cameras agree on both, has the two
  // tracks exchanged (view_swaps.h). Never needed on the seven clips measured (UNZUETA.md,
  // mv40): their swaps happen in several cameras at once.
  bool multiview_swaps = true;
  // --effectors multiview (needs the consensus): when both hands' (or feet's) consensus lands on
  // one limb, the cameras whose tracks lie elsewhere and agree give the other part, and a part
  // without consensus does not fall back on a camera whose track slid onto the other part
  // (pair_consensus.h; the 249-frame walk 279.6 -> 176.9 mm, UNZUETA.md, mv40).
  bool multiview_pairs = true;
  // --effectors multiview, with `multiview_reseed`: a camera whose part learnt no colours (its
  // first ROI held none of it) takes an agreeing camera's, so that the re-seeding can start it
  // (lost 4-8 % -> 0 on six runs of fourteen; hop4 102.3 -> 98.9 mm; UNZUETA.md, mv40).
  bool multiview_borrow_colours = true;
  SikOptions solver;    // SIK itself: the same defaults as ik-eval's
  int max_frames = -1;  // the first frames only; < 0: every frame
  bool quiet = false;
};

// The family's entry point: track_dataset_sik for gt, else tracker::track_dataset_unzueta.
TrackSummary track_sik(const std::filesystem::path& dataset, const std::filesystem::path& out,
                       const SikTrackOptions& options);

// Reads DATASET/gt/joints3d.csv; needs humanoid_root, skullbase (or skull_tip), l/r_radiocarpal
// and l/r_talocrural. Solves every frame in order with SIK (options.solver, collisions on, floor
// y = 0) on build_humanoid() refitted to the truth (sik_humanoid_with_truth_trunk),
// after adding N(0, noise_sigma_m^2) to each coordinate of each end-effector (std::mt19937_64
// seeded with `seed`, so a seed gives the same output); with middle_targets also l/r_elbow and
// l/r_knee, as SikTargets::elbow and knee. Writes OUT/joints3d.csv (HE15 joints) and
// OUT/diagnostics/sik_humanoid.csv (the fitted humanoid's neutral joint centres).
TrackSummary track_dataset_sik(const std::filesystem::path& dataset,
                               const std::filesystem::path& out, const SikTrackOptions& options);

// build_humanoid() at the truth's height (the median ratio of tracked bone lengths to the
// canonical ones), then the bones between each tracked joint and its nearest tracked ancestor
// scaled to their mean distance in `truth` (a bone shared by two such paths, e.g. the spine below
// vc7 and a shoulder when only HE15 is tracked, takes the first path's factor).
Skeleton sik_humanoid_for_track(const JointTrack& truth);

// sik_humanoid_for_track, then the trunk's rest shape taken from the truth: vc7 moved to its
// median position in the trunk frame (humanoid_root, Y toward skullbase, X across the hips; the
// shift spread over the vertebrae below, skullbase kept), each shoulder with its arm to its median
// in the thorax frame (vc7, Y toward humanoid_root, X across the shoulders). A clavicle or thorax
// the motion keeps turned (CMU clips retarget with the clavicles ~25 degrees up) belongs to the
// body SIK solves. Used with the true end-effectors only: with tracked ones (unzueta_job.h) it
// made the walk and the hop worse (UNZUETA.md, "SIK's floor").
Skeleton sik_humanoid_with_truth_trunk(const JointTrack& truth);

}  // namespace simcap
