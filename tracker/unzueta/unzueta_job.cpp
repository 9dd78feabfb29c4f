#include "tracker/unzueta/unzueta_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <optional>

#include "core/csv.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/progress.h"
#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "tracker/common/dataset.h"
#include "tracker/common/mask_box.h"
#include "tracker/common/png_decoder.h"
#include "tracker/common/triangulation.h"
#include "tracker/unzueta/depth_lookup.h"
#include "tracker/unzueta/pair_consensus.h"
#include "tracker/unzueta/part_consensus.h"
#include "tracker/unzueta/part_model.h"
#include "tracker/unzueta/sik.h"
#include "tracker/unzueta/sik_track_job.h"
#include "tracker/unzueta/view_swaps.h"

namespace simcap::tracker {
namespace fs = std::filesystem;

namespace {

// The pelvis' depth is read on the silhouette within this fraction of the person's height of
// its image position.
constexpr double kPelvisWindow = 0.03;
// Height assumed for the floor contact of the feet before the body is measured (the feet's
// centres lie ~4% of it above the floor, so a 10 cm error moves them by 4 mm).
constexpr double kAssumedHeight = 1.75;
// The left/right pairs of parts.
constexpr std::array<std::array<Effector, 2>, 2> kPairs = {
    {{Effector::left_hand, Effector::right_hand}, {Effector::left_foot, Effector::right_foot}}};

std::string frame_name(int frame, const char* ext) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d.%s", frame, ext);
  return buf;
}

struct Images {
  cv::Mat bgr, silhouette, depth;
};

class Pipeline {
 public:
  Pipeline(const fs::path& root, const SikTrackOptions& options)
      : options_(options), ds_(root), silhouettes_(ds_, options.silhouettes) {
    frames_ = ds_.frames(silhouettes_.image_kind());
    if (silhouettes_.image_kind() != "rgb" && ds_.frames("rgb") != frames_) {
      throw Error(root.string() + ": rgb and mask frames differ");
    }
    if (options.max_frames >= 0 && static_cast<int>(frames_.size()) > options.max_frames) {
      frames_.resize(options.max_frames);
    }
    if (frames_.empty()) throw Error(root.string() + ": no frames to track");
    if (options.effectors == EffectorSource::gt) {
      throw Error("the pixel pipeline needs --effectors depth, mono or multiview");
    }
    if (options.camera < 0 || options.camera >= ds_.camera_count()) {
      throw Error("--camera: the dataset has " + std::to_string(ds_.camera_count()) +
                  " camera(s); index " + std::to_string(options.camera) + " does not exist");
    }
    if (options.effectors == EffectorSource::multiview) {
      if (ds_.camera_count() < 2) {
        throw Error("--effectors multiview: " + root.string() + " has one camera (needs two)");
      }
      for (int c = 0; c < ds_.camera_count(); ++c) cameras_.push_back(c);
    } else {
      cameras_.push_back(options.camera);
    }
    trackers_.assign(cameras_.size(), CameraTracker(options.tracking));
  }

  TrackSummary run(const UnzuetaSink& sink) {
    Progress progress("sik from pixels", static_cast<long>(frames_.size()), options_.quiet);
    const auto start = std::chrono::steady_clock::now();
    for (size_t k = 0; k < frames_.size(); ++k) {
      const int f = frames_[k];
      std::vector<Images> images;
      for (int c : cameras_) images.push_back(read(c, f));
      if (k == 0) {
        initialize(f, images);
      } else {
        for (size_t i = 0; i < cameras_.size(); ++i) {
          trackers_[i].track(images[i].bgr, images[i].silhouette, part_depths(cameras_[i]),
                             limb_roots(cameras_[i]));
        }
      }
      UnzuetaFrame out;
      out.frame = f;
      out.centre = k == 0 ? centre_ : lift(images);
      if (k > 0 && options_.effectors == EffectorSource::multiview && options_.multiview_swaps) {
        unswap(out.centre);
      }
      if (options_.effectors == EffectorSource::multiview && options_.multiview_reseed) {
        reseed(out.centre);
      }
      solve(out);
      centre_ = out.centre;
      if (sink) sink(out, cameras_, trackers_);
      progress.advance();
    }
    progress.finish();
    TrackSummary s;
    s.frames = static_cast<int>(frames_.size());
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return s;
  }

  const Skeleton& skeleton() const { return skeleton_; }

 private:
  const Camera& camera(int c) const { return ds_.cameras()[c]; }

  Images read(int c, int f) const {
    Images im;
    im.silhouette = silhouettes_.extract(c, f, &im.bgr);
    if (im.bgr.empty()) im.bgr = ds_.rgb(c, f);
    if (options_.effectors == EffectorSource::depth) {
      const fs::path path = ds_.root() / camera(c).name / "depth" / frame_name(f, "exr");
      if (!fs::is_regular_file(path)) {
        throw Error(path.string() + ": missing (--effectors depth reads the dataset's depth maps)");
      }
      im.depth = read_image(path);
    }
    return im;
  }

  // Each part's distance from camera c for the occlusion rule: with --effectors depth the
  // lifted centre at the occlusion quantile, else the previous centre's.
  std::array<double, kEffectorCount> part_depths(int c) const {
    if (options_.effectors == EffectorSource::depth) return order_z_;
    std::array<double, kEffectorCount> z;
    for (Effector e : kEffectors) z[index_of(e)] = camera(c).to_camera(centre_[index_of(e)]).z();
    return z;
  }

  // Where each part's limb starts in camera c, from the previous pose: the neck's base, the
  // shoulders, the hips (SIK places them from the pelvis and head, not from hands and feet).
  std::array<std::optional<cv::Point2d>, kEffectorCount> limb_roots(int c) const {
    std::array<std::optional<cv::Point2d>, kEffectorCount> out;
    if (position_.empty()) return out;
    for (Effector e : kEffectors) {
      if (e == Effector::pelvis) continue;
      if (const auto p = camera(c).project(position_[limb_root_[index_of(e)]])) {
        out[index_of(e)] = cv::Point2d(p->x(), p->y());
      }
    }
    return out;
  }

  // --- first frame ------------------------------------------------------------------------

  void initialize(int f, const std::vector<Images>& images) {
    std::optional<JointTrack> truth;
    if (options_.init == InitMethod::gt) truth = ds_.ground_truth("--init gt");
    // ROIs per camera.
    std::vector<InitialRegions> regions(cameras_.size());
    const size_t primary =
        options_.effectors == EffectorSource::multiview ? static_cast<size_t>(options_.camera) : 0;
    std::array<Eigen::Vector3d, kEffectorCount> posture{};
    if (options_.init == InitMethod::gt) {
      for (size_t i = 0; i < cameras_.size(); ++i) {
        const fs::path labels =
            ds_.root() / camera(cameras_[i]).name / "parts" / frame_name(f, "png");
        cv::Mat l = decode_png(labels, cv::IMREAD_UNCHANGED);
        if (l.empty())
          throw Error(labels.string() +
                      ": missing or unreadable (--init gt reads the part labels)");
        // The labels name joints, not people: with several actors every head is a skullbase.
        l.setTo(0, ds_.mask(cameras_[i], f) == 0);
        regions[i] = labelled_part_regions(l, ds_.root() / "parts.json");
      }
    } else {
      regions[primary] = calibration_posture_regions(images[primary].silhouette);
      posture = posture_geometry(cameras_[primary], regions[primary], images[primary]);
      for (size_t i = 0; i < cameras_.size(); ++i) {
        if (i != primary)
          regions[i] = project_regions(cameras_[i], cameras_[primary], regions[primary], posture,
                                       images[i].silhouette);
      }
    }
    const std::string hint =
        options_.init == InitMethod::gt
            ? " (--init gt: the part labels show none of the parts there; is the person in its "
              "view?)"
            : " (--init auto: the person must start in the calibration posture, hands raised "
              "beside the head, facing " +
                  camera(cameras_[primary]).name + "; --init gt starts from the labels)";
    // Multiview starts in the cameras that see the person; the others start lost (below).
    std::vector<size_t> started, unstarted;
    std::string why;
    for (size_t i = 0; i < cameras_.size(); ++i) {
      try {
        trackers_[i].initialize(images[i].bgr, images[i].silhouette, regions[i]);
        started.push_back(i);
      } catch (const Error& e) {
        const std::string where = camera(cameras_[i]).name + ": " + e.what();
        if (options_.effectors != EffectorSource::multiview) {
          throw Error("frame " + std::to_string(f) + ", " + where + hint);
        }
        unstarted.push_back(i);
        why += (why.empty() ? "" : "; ") + where;
      }
    }
    if (!unstarted.empty() && started.size() < 2) {
      std::string names;
      for (size_t i : started) names += (names.empty() ? "" : ", ") + camera(cameras_[i]).name;
      throw Error("frame " + std::to_string(f) +
                  ": --effectors multiview needs the person in at least two cameras to start, " +
                  (started.empty() ? "none could" : "only " + names + " could") + " (" + why + ")" +
                  hint);
    }
    // The body SIK solves.
    if (truth) {
      skeleton_ = sik_humanoid_for_track(*truth);
    } else {
      BodyParameters unit_body;
      unit_body.height = 1.0;
      const Skeleton unit = build_humanoid(unit_body);
      const PartModel unit_parts(unit, build_body_mesh(unit));
      const double head_fraction =
          (unit[unit_parts.joint(Effector::head)].center + unit_parts.centre_offset(Effector::head))
              .y();
      BodyParameters body;
      body.height = std::clamp(posture[index_of(Effector::head)].y() / head_fraction, 0.6, 2.5);
      skeleton_ = build_humanoid(body);
    }
    const BodyMesh mesh = build_body_mesh(skeleton_);
    solver_.emplace(SikBody(skeleton_), mesh, options_.solver);
    parts_.emplace(skeleton_, mesh);
    he15_.clear();
    for (const std::string& name : he15_joints()) he15_.push_back(skeleton_.require(name));
    limb_root_ = {skeleton_.require("vc7"),        skeleton_.require("l_shoulder"),
                  skeleton_.require("r_shoulder"), skeleton_.require("l_hip"),
                  skeleton_.require("r_hip"),      0};
    // Neutral rotations until the first solve.
    rotation_.assign(skeleton_.size(), Eigen::Quaterniond::Identity());

    // The parts' first 3D centres: with --init gt the truth's (the part labels give no 3D
    // posture), else the calibration posture's.
    if (truth) {
      const int ti = truth->frames.empty() || truth->frames.front() != f ? -1 : 0;
      if (ti < 0) throw Error("--init gt: the ground truth has no frame " + std::to_string(f));
      for (Effector e : kEffectors) {
        const int j = truth->joint_index(std::string(effector_joint(e)));
        if (j < 0)
          throw Error("--init gt: the ground truth lacks " + std::string(effector_joint(e)));
        posture[index_of(e)] = truth->positions[ti][j] + parts_->centre_offset(e);
      }
    }
    if (!unstarted.empty()) {
      start_lost(unstarted, started.front(), posture[index_of(Effector::pelvis)], images);
    }
    centre_ = posture;
    for (Effector e : kEffectors)
      order_z_[index_of(e)] = camera(cameras_[0]).to_camera(centre_[index_of(e)]).z();
    if (options_.effectors == EffectorSource::mono) {
      for (Effector e : kEffectors)
        mono_depth_[index_of(e)] = camera(cameras_[0]).to_camera(centre_[index_of(e)]).z();
    } else {
      centre_ = lift(images);  // parts it cannot see keep the posture's centres
    }
    // The pelvis measurement's offset from the root joint.
    const Eigen::Vector3d pelvis = centre_[index_of(Effector::pelvis)];
    if (truth) {
      pelvis_offset_ = truth->positions[0][truth->joint_index("humanoid_root")] - pelvis;
    } else {
      pelvis_offset_ = Eigen::Vector3d(0, skeleton_[0].center.y() - pelvis.y(), 0);
    }
  }

  // Cameras that did not see the person on the first frame start with every part lost, the
  // person as high in the image as in camera `donor` at the focal length over the pelvis'
  // depth (`pelvis`; behind the camera: as high as in the donor); reseed brings their parts in.
  void start_lost(const std::vector<size_t>& which, size_t donor, const Eigen::Vector3d& pelvis,
                  const std::vector<Images>& images) {
    const Camera& d = camera(cameras_[donor]);
    const double donor_scale = d.K(0, 0) / d.to_camera(pelvis).z();
    for (size_t i : which) {
      const Camera& cam = camera(cameras_[i]);
      const double z = cam.to_camera(pelvis).z();
      const double scale = z > 0 ? cam.K(0, 0) / z / donor_scale : 1.0;
      trackers_[i].start_lost(images[i].bgr, images[i].silhouette,
                              trackers_[donor].person_px() * scale);
    }
  }

  // Calibration posture in 3D from one view: the feet on the floor, the rest in the vertical
  // plane through them facing the camera; with depth images, read off them instead.
  std::array<Eigen::Vector3d, kEffectorCount> posture_geometry(int c, const InitialRegions& r,
                                                               const Images& im) const {
    const Camera& cam = camera(c);
    std::array<Eigen::Vector3d, kEffectorCount> p{};
    auto centre_px = [&](Effector e) {
      const cv::Rect2d& roi = *r.roi[index_of(e)];
      return cv::Point2d(roi.x + 0.5 * roi.width, roi.y + 0.5 * roi.height);
    };
    const double foot_y = 0.04 * kAssumedHeight;
    for (Effector e : {Effector::left_foot, Effector::right_foot}) {
      const Eigen::Vector3d ray = cam.unproject(Eigen::Vector2d(centre_px(e).x, centre_px(e).y));
      const Eigen::Vector3d o = cam.centre();
      if (std::abs(ray.y()) < 1e-6 || (foot_y - o.y()) / ray.y() <= 0) {
        throw Error("calibration posture: the camera does not see the floor under the feet");
      }
      p[index_of(e)] = o + ray * ((foot_y - o.y()) / ray.y());
    }
    const Eigen::Vector3d mid =
        0.5 * (p[index_of(Effector::left_foot)] + p[index_of(Effector::right_foot)]);
    Eigen::Vector3d normal = mid - cam.centre();
    normal.y() = 0;
    normal.normalize();
    for (Effector e :
         {Effector::head, Effector::left_hand, Effector::right_hand, Effector::pelvis}) {
      cv::Point2d px;
      if (e == Effector::pelvis) {
        const auto m = PelvisTracker(PelvisParams{}.scaled_for(r.person_px)).measure(im.silhouette);
        if (!m) throw Error("calibration posture: no silhouette for the pelvis");
        px = *m;
      } else {
        px = centre_px(e);
      }
      const Eigen::Vector3d ray = cam.unproject(Eigen::Vector2d(px.x, px.y));
      p[index_of(e)] = cam.centre() + ray * ((mid - cam.centre()).dot(normal) / ray.dot(normal));
    }
    if (!im.depth.empty()) {
      for (Effector e : kEffectors) {
        const Eigen::Vector3d q = cam.to_camera(p[index_of(e)]);
        const auto px = cam.project_camera(q);
        const int half = static_cast<int>(0.03 * r.person_px);
        const auto z =
            depth_quantile(im.depth, mask_samples(im.silhouette, {px.x(), px.y()}, half, 1), 0.5);
        if (z) p[index_of(e)] = point_at_depth(cam, {px.x(), px.y()}, *z);
      }
    }
    return p;
  }

  // The primary camera's ROIs carried to camera c through the posture's 3D points.
  InitialRegions project_regions(int c, int primary, const InitialRegions& r,
                                 const std::array<Eigen::Vector3d, kEffectorCount>& posture,
                                 const cv::Mat& silhouette) const {
    InitialRegions out;
    out.person_px = mask_box(silhouette).height;
    for (Effector e : kEffectors) {
      if (e == Effector::pelvis || !r.roi[index_of(e)]) continue;
      const Eigen::Vector3d& x = posture[index_of(e)];
      const auto px = camera(c).project(x);
      if (!px || !camera(c).in_frustum(x)) continue;
      const double side = r.roi[index_of(e)]->width * camera(primary).to_camera(x).z() /
                          camera(primary).K(0, 0) * camera(c).K(0, 0) / camera(c).to_camera(x).z();
      out.roi[index_of(e)] = cv::Rect2d(px->x() - 0.5 * side, px->y() - 0.5 * side, side, side);
    }
    return out;
  }

  // --- every frame --------------------------------------------------------------------------

  // A part's views for the triangulation: every camera that tracks it.
  struct PartViews {
    std::vector<PixelObservation> views;
    std::vector<size_t> camera;  // per view, its index in cameras_
    int seen = -1;               // a camera that still has the part (tracking or predicted)
  };
  PartViews part_views(Effector e) const {
    PartViews v;
    for (size_t k = 0; k < cameras_.size(); ++k) {
      const CfofState s = trackers_[k].state(e);
      if (s == CfofState::lost) continue;
      if (v.seen < 0 || s == CfofState::tracking) v.seen = static_cast<int>(k);
      if (s != CfofState::tracking) continue;
      const cv::Point2d p = trackers_[k].position(e);
      v.views.push_back({&camera(cameras_[k]), {p.x, p.y}});
      v.camera.push_back(k);
    }
    return v;
  }

  // A part from the views that agree (`c`), else one camera's ray at the part's previous depth.
  // Remembers which cameras agreed, for `reseed`.
  Eigen::Vector3d place(Effector e, const PartViews& v, const std::optional<PartConsensus>& c) {
    const int i = index_of(e);
    agreeing_[i].assign(cameras_.size(), false);
    if (c) {
      for (size_t k = 0; k < v.views.size(); ++k) agreeing_[i][v.camera[k]] = c->inlier[k];
      return c->position;
    }
    if (v.seen < 0) return centre_[i];
    const Camera& cam = camera(cameras_[v.seen]);
    return point_at_depth(cam, trackers_[v.seen].position(e), cam.to_camera(centre_[i]).z());
  }

  // A part from every camera that tracks it: the views that agree (part_consensus; with
  // multiview_consensus_px 0 all of them in one DLT).
  Eigen::Vector3d lift_multiview(Effector e) {
    const PartViews v = part_views(e);
    if (options_.multiview_consensus_px > 0) {
      return place(e, v, part_consensus(v.views, {options_.multiview_consensus_px}));
    }
    std::optional<PartConsensus> all;
    if (const auto x = triangulate(v.views)) {
      all.emplace();
      all->position = *x;
      all->inlier.assign(v.views.size(), false);
    }
    return place(e, v, all);
  }

  // A left/right pair (pair_consensus: both parts' consensus on one limb leaves the other limb
  // to the cameras that still track it there; a part without consensus does not fall back on a
  // track on the other part's point).
  void lift_pair(Effector l, Effector r, std::array<Eigen::Vector3d, kEffectorCount>& centre) {
    const PartViews vl = part_views(l), vr = part_views(r);
    const PairConsensus c = pair_consensus(vl.views, vr.views, {options_.multiview_consensus_px});
    centre[index_of(l)] = place(l, without_slid(l, vl, c.left, c.right), c.left);
    centre[index_of(r)] = place(r, without_slid(r, vr, c.right, c.left), c.right);
  }

  // A part without consensus falls back on one camera's ray; a camera whose track of it has
  // slid onto the other part's consensus point (slid_onto_other) would put the two limbs
  // together, so another camera that still has the part is used.
  PartViews without_slid(Effector e, PartViews v, const std::optional<PartConsensus>& own,
                         const std::optional<PartConsensus>& other) const {
    if (own || !other || v.seen < 0) return v;
    if (trackers_[v.seen].state(e) != CfofState::tracking) return v;
    const cv::Point2d p = trackers_[v.seen].position(e);
    if (!slid_onto_other(camera(cameras_[v.seen]), {p.x, p.y}, other->position,
                         centre_[index_of(e)], options_.multiview_consensus_px)) {
      return v;
    }
    const int slid = v.seen;
    v.seen = -1;
    for (size_t k = 0; k < cameras_.size(); ++k) {
      if (static_cast<int>(k) == slid || trackers_[k].state(e) == CfofState::lost) continue;
      if (v.seen < 0 || trackers_[k].state(e) == CfofState::tracking) v.seen = static_cast<int>(k);
    }
    return v;
  }

  // Multiview: a camera whose left and right hand (or foot) tracks each follow the other limb,
  // where two or more other cameras agree on both (tracks_swapped), has its two tracks
  // exchanged; the pair is then triangulated again with that camera's tracks.
  void unswap(std::array<Eigen::Vector3d, kEffectorCount>& centre) {
    for (const auto& [l, r] : kPairs) {
      const std::vector<bool>& agree_l = agreeing_[index_of(l)];
      const std::vector<bool>& agree_r = agreeing_[index_of(r)];
      bool swapped = false;
      for (size_t k = 0; k < cameras_.size(); ++k) {
        CameraTracker& t = trackers_[k];
        if (t.state(l) != CfofState::tracking || t.state(r) != CfofState::tracking) continue;
        if (agree_l[k] && agree_r[k]) continue;
        int others_l = 0, others_r = 0;
        for (size_t o = 0; o < cameras_.size(); ++o) {
          others_l += o != k && agree_l[o];
          others_r += o != k && agree_r[o];
        }
        if (others_l < 2 || others_r < 2) continue;
        const cv::Point2d pl = t.position(l), pr = t.position(r);
        if (tracks_swapped(camera(cameras_[k]), {pl.x, pl.y}, {pr.x, pr.y}, centre[index_of(l)],
                           centre[index_of(r)], options_.multiview_consensus_px)) {
          t.swap(l, r);
          swapped = true;
        }
      }
      if (!swapped) continue;
      if (options_.multiview_pairs) {
        lift_pair(l, r, centre);
      } else {
        centre[index_of(l)] = lift_multiview(l);
        centre[index_of(r)] = lift_multiview(r);
      }
    }
  }

  // Multiview: where two or more cameras agree on a part, the cameras that disagree, predict it
  // hidden or have lost it are moved to the agreed point's projection (CameraTracker::correct).
  void reseed(const std::array<Eigen::Vector3d, kEffectorCount>& centre) {
    for (Effector e : kEffectors) {
      if (e == Effector::pelvis) continue;
      const std::vector<bool>& agree = agreeing_[index_of(e)];
      if (std::count(agree.begin(), agree.end(), true) < 2) continue;
      const Eigen::Vector3d& x = centre[index_of(e)];
      const size_t donor = std::find(agree.begin(), agree.end(), true) - agree.begin();
      const Camera& donor_cam = camera(cameras_[donor]);
      for (size_t k = 0; k < cameras_.size(); ++k) {
        const Camera& cam = camera(cameras_[k]);
        if (agree[k] || !cam.in_frustum(x)) continue;
        if (options_.multiview_borrow_colours) {
          // The part's size in pixels goes with the focal length over the depth.
          const double scale =
              cam.K(0, 0) / cam.to_camera(x).z() / (donor_cam.K(0, 0) / donor_cam.to_camera(x).z());
          trackers_[k].borrow_colours(e, trackers_[donor], scale);
        }
        if (const auto p = cam.project(x)) trackers_[k].correct(e, {p->x(), p->y()});
      }
    }
  }

  // The parts' centres this frame; with --effectors depth also their occlusion depths
  // (order_z_), which a part that is not tracked keeps.
  std::array<Eigen::Vector3d, kEffectorCount> lift(const std::vector<Images>& images) {
    std::array<Eigen::Vector3d, kEffectorCount> out = centre_;
    if (options_.effectors == EffectorSource::multiview && options_.multiview_pairs &&
        options_.multiview_consensus_px > 0) {
      for (Effector e : {Effector::head, Effector::pelvis}) out[index_of(e)] = lift_multiview(e);
      for (const auto& [l, r] : kPairs) lift_pair(l, r, out);
      return out;
    }
    for (Effector e : kEffectors) {
      const int i = index_of(e);
      if (options_.effectors == EffectorSource::multiview) {
        out[i] = lift_multiview(e);
        continue;
      }
      const int c = cameras_[0];
      const CameraTracker& t = trackers_[0];
      const CfofState s = t.state(e);
      if (s == CfofState::lost) continue;
      const cv::Point2d px = t.position(e);
      if (options_.effectors == EffectorSource::mono) {
        out[i] = point_at_depth(camera(c), px, mono_depth_[i]);
        continue;
      }
      std::optional<PartDepth> z;
      const Eigen::Vector3d ray = camera(c).unproject({px.x, px.y});
      const double behind =
          parts_->depth_behind_surface(e, rotation_[parts_->joint(e)], ray, e == Effector::pelvis);
      if (s == CfofState::tracking) {
        const std::vector<cv::Point> at =
            e == Effector::pelvis ? mask_samples(images[0].silhouette, px,
                                                 static_cast<int>(kPelvisWindow * t.person_px()), 2)
                                  : t.surface(e);
        const bool pelvis = e == Effector::pelvis;
        z = part_depth(images[0].depth, at, pelvis ? 0.5 : options_.surface_quantile,
                       pelvis ? 0.5 : options_.occlusion_quantile,
                       pelvis ? 0.0 : options_.surface_thickness);
      }
      if (z) {
        order_z_[i] =
            camera(c).to_camera(centre_behind_surface(camera(c), px, z->order, behind)).z();
      }
      out[i] = z ? centre_behind_surface(camera(c), px, z->surface, behind)
                 : point_at_depth(camera(c), px, camera(c).to_camera(centre_[i]).z());
    }
    return out;
  }

  void solve(UnzuetaFrame& out) {
    const SikBody& body = solver_->body();
    // Twice: the second pass turns the part-to-joint offsets as the first pass posed the body.
    for (int pass = 0; pass < 2; ++pass) {
      for (Effector e : kEffectors) {
        const int i = index_of(e);
        out.target[i] = e == Effector::pelvis
                            ? Eigen::Vector3d(out.centre[i] + pelvis_offset_)
                            : parts_->joint_from_centre(e, out.centre[i], rotation_);
      }
      SikTargets targets;
      targets.pelvis = out.target[index_of(Effector::pelvis)];
      targets.head = out.target[index_of(Effector::head)];
      targets.wrist = {out.target[index_of(Effector::left_hand)],
                       out.target[index_of(Effector::right_hand)]};
      targets.ankle = {out.target[index_of(Effector::left_foot)],
                       out.target[index_of(Effector::right_foot)]};
      body.forward(solver_->solve(targets), rotation_, position_);
    }
    out.he15.clear();
    for (int j : he15_) out.he15.push_back(position_[j]);
  }

  SikTrackOptions options_;
  Dataset ds_;
  SilhouetteExtractor silhouettes_;
  std::vector<int> frames_, cameras_;
  std::vector<CameraTracker> trackers_;
  Skeleton skeleton_;
  std::optional<SikSolver> solver_;
  std::optional<PartModel> parts_;
  std::vector<int> he15_;
  std::array<int, kEffectorCount> limb_root_{};
  std::array<Eigen::Vector3d, kEffectorCount> centre_{};
  std::array<std::vector<bool>, kEffectorCount> agreeing_;
  std::array<double, kEffectorCount> mono_depth_{};
  std::array<double, kEffectorCount> order_z_{};  // --effectors depth: see part_depths
  Eigen::Vector3d pelvis_offset_ = Eigen::Vector3d::Zero();
  std::vector<Eigen::Quaterniond> rotation_;
  std::vector<Eigen::Vector3d> position_;
};

}  // namespace

TrackSummary run_unzueta(const fs::path& dataset, const SikTrackOptions& options,
                         const UnzuetaSink& sink) {
  Pipeline pipeline(dataset, options);
  return pipeline.run(sink);
}

TrackSummary track_dataset_unzueta(const fs::path& dataset, const fs::path& out,
                                   const SikTrackOptions& options) {
  Pipeline pipeline(dataset, options);
  JointTrack track;
  track.joints = he15_joints();
  fs::create_directories(out / "diagnostics");
  CsvWriter e2d(out / "effectors2d.csv", kEffectors2dColumns);
  CsvWriter e3d(out / "effectors3d.csv", {"frame", "effector", "joint", "x", "y", "z"});
  const Dataset ds(dataset);
  char line[256];
  TrackSummary s = pipeline.run([&](const UnzuetaFrame& f, const std::vector<int>& cameras,
                                    const std::vector<CameraTracker>& trackers) {
    track.add_frame(f.frame, f.he15);
    for (Effector e : kEffectors) {
      const Eigen::Vector3d& x = f.target[index_of(e)];
      std::snprintf(line, sizeof line, "%d,%s,%s,%.7f,%.7f,%.7f\n", f.frame,
                    std::string(effector_name(e)).c_str(), std::string(effector_joint(e)).c_str(),
                    x.x(), x.y(), x.z());
      e3d.out() << line;
    }
    for (size_t k = 0; k < cameras.size(); ++k) {
      const Camera& cam = ds.cameras()[cameras[k]];
      for (Effector e : kEffectors) {
        const auto px = cam.project(f.target[index_of(e)]);
        if (!px) continue;
        const cv::Point2d part = trackers[k].position(e);
        std::snprintf(line, sizeof line, "%d,%s,%s,%s,%.3f,%.3f,%.3f,%.3f,%s\n", f.frame,
                      cam.name.c_str(), std::string(effector_name(e)).c_str(),
                      std::string(effector_joint(e)).c_str(), px->x(), px->y(), part.x, part.y,
                      cfof_state_name(trackers[k].state(e)));
        e2d.out() << line;
      }
    }
  });
  CsvWriter neutral(out / "diagnostics" / "sik_humanoid.csv", {"joint", "x", "y", "z"});
  for (const Joint& j : pipeline.skeleton().joints()) {
    std::snprintf(line, sizeof line, "%s,%.7f,%.7f,%.7f\n", j.name.c_str(), j.center.x(),
                  j.center.y(), j.center.z());
    neutral.out() << line;
  }
  neutral.commit();
  e2d.commit();
  e3d.commit();
  write_joint_track(out / "joints3d.csv", track);
  s.track = out;
  return s;
}

}  // namespace simcap::tracker
