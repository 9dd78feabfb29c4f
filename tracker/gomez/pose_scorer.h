// How well a pose hypothesis explains a frame: the region non-overlap per colour class (thesis
// eq. 2.5) and the mean chamfer distance from the model's occluding contour to the image edges
// (eq. 3.13), combined into the particle energy -log p(z|x) of eq. 4.12.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/name_table.h"
#include "tracker/gomez/body_dofs.h"
#include "tracker/gomez/body_shape.h"
#include "tracker/gomez/bone_shading.h"
#include "tracker/gomez/frame_cues.h"
#include "tracker/gomez/label_renderer.h"

namespace simcap::tracker::gomez {

// How the per-class ratios r_c = |A_c xor B_c| / |A_c u B_c| of the m classes are combined.
// root_sum: the thesis's printed eq. 2.5, sum of r_c^(1/m), here divided by m so that F lies in
// [0, 1]; mean: their mean; pixels: all classes' non-overlap over all classes' union.
enum class RegionCombine { root_sum, mean, pixels };
inline constexpr NameTable<RegionCombine, 3> kRegionCombines{{{"root_sum", RegionCombine::root_sum},
                                                              {"mean", RegionCombine::mean},
                                                              {"pixels", RegionCombine::pixels}}};

struct ScoreOptions {
  RegionCombine combine = RegionCombine::mean;
  // The thesis compares skin on the head apart from skin on the arms (its face detector's
  // ellipse splits the image's skin pixels); here the class most of the head's cells have is
  // split by the hypothesis itself: its pixels under the model's head are the head's, the rest
  // the arms'. Without the split a hand lost behind the trunk costs little next to the face.
  bool split_head = true;
  // Spreads of the likelihood p(z|x) ~ exp(-F^2 / 2 sf^2) exp(-D^2 / 2 sd^2) (eq. 4.12): the
  // thesis took them from the costs' variability over its sequences.
  double sigma_region = 0.08;
  double sigma_edge_px = 1.5;
  // Where two capsules meet in the image, the nearer one's pixel is on an occluding contour
  // when the other lies this much further away (a forearm before the chest), metres.
  double occlusion_gap_m = 0.04;
  // The feet prior (simcap's addition): the model's lowest extent against the silhouette's, a
  // Gaussian of this spread in working pixels; 0 is off. The full body stands on the floor, so
  // the row its feet project to fixes its distance from the camera, which the region and edge
  // costs, nearly unchanged by a small change of scale, leave loose.
  double sigma_feet_px = 3.0;
  // The same for the top of the body against the silhouette's top (the body's known height
  // against a crouch it does not get up from); 0 is off.
  double sigma_top_px = 3.0;
  // The arm bones' shading (simcap's addition, bone_shading.h): the spread in grey levels of
  // each bone's observed grey about the grey its posed direction predicts under the light fitted
  // on the first frame, counted where its depth flip predicts it better (flip_penalty); 0 is
  // off. Tells an arm bone from its depth flip, which the other costs see alike.
  double sigma_shade_grey = 0.0;
};

struct Score {
  double region = 1.0;  // F in [0, 1]
  double edge = 0.0;    // D_C, working pixels
  double feet = 0.0;    // model's lowest extent minus the silhouette's, working pixels (0: none)
  double top = 0.0;     // model's highest extent minus the silhouette's, working pixels (0: none)
  double shade = 0.0;   // the arm bones' flip_penalty, grey levels squared (0: none)
};

// F^2 / 2 sf^2, D^2 / 2 sd^2, the feet and top priors' E^2 / 2 se^2 and the shading's
// residual / 2 sg^2: the negative log-likelihood's terms.
struct Energy {
  double region = 0, edge = 0, feet = 0, shade = 0;
  double total() const { return region + edge + feet + shade; }
  // The two terms Nelder-Mead weighs (regions first, then edges): the priors and the shading go
  // half to each, so that they count in both steps and their sum is the total.
  Eigen::Vector2d terms() const {
    const double both = 0.5 * (feet + shade);
    return {region + both, edge + both};
  }
};
Energy energy(const Score& score, const ScoreOptions& options);

// The colour classes the region cost compares the model's cells with.
struct RegionModel {
  std::vector<std::uint8_t> cell_class;  // class 1..m of each colour cell
  std::vector<std::uint8_t> head_cell;   // 1 for the cells of the head's capsules
  int head_class = 0;                    // the class split between head and the rest; 0: none
};
// `split_head`: the class of most head cells becomes the head class.
RegionModel region_model(const BodyShape& shape, const std::vector<std::uint8_t>& cell_class,
                         bool split_head);

// Whether the colour cells can tell a body facing the camera from one turned away: a capsule
// with a face (Capsule::front) whose crown cell has another class than most of its cells (hair
// above a face). Otherwise the costs see a body and its front/back reflection alike.
bool tells_front_from_back(const BodyShape& shape, const std::vector<std::uint8_t>& cell_class);

// The region cost of a rendered image. Only the classes some cell has are compared (the upper
// body has no trousers); the head class, if any, counts as two: under the model's head and
// elsewhere.
double region_cost(const LabelImage& labels, const RegionModel& model, const FrameCues& cues,
                   RegionCombine combine);
// Mean distance-map value over the model's occluding-contour pixels (a drawn pixel with a
// 4-neighbour that is empty, off the image, or of another capsule at least `gap_m` further
// away); `cues.far` when no contour shows.
double chamfer_cost(const LabelImage& labels, const FrameCues& cues, double gap_m);
// The feet prior's offset: `model_bottom` (full-resolution row of the posed body's lowest
// extent) minus the silhouette's feet row, in working pixels; 0 when the frame has none.
double feet_offset(double model_bottom, const FrameCues& cues);
double top_offset(double model_top, const FrameCues& cues);
// Whether a drawn pixel lies on the model's occluding contour (the rule of chamfer_cost).
bool on_contour(const LabelImage& labels, int u, int v, double gap_m);

class PoseScorer {
 public:
  // Keeps references to `dofs` and `shape`.
  PoseScorer(const BodyDofs& dofs, const BodyShape& shape,
             const std::vector<std::uint8_t>& cell_class, const ScoreOptions& options);
  const ScoreOptions& options() const { return options_; }
  const BodyDofs& dofs() const { return *dofs_; }
  const BodyShape& shape() const { return *shape_; }
  const std::vector<std::uint8_t>& cell_class() const { return region_.cell_class; }
  const BoneShading& shading() const { return shading_; }
  // The light the shading term compares with (fitted on the first frame); not called while a
  // frame is scored. The term is off until the lighting is known.
  void set_lighting(const Lighting& lighting) { lighting_ = lighting; }
  const Lighting& lighting() const { return lighting_; }

  void render(const State& x, const View& view, LabelImage& out) const;
  // Renders into a per-thread buffer and scores; safe to call from several threads.
  Score score(const State& x, const FrameCues& cues) const;
  Energy energy_of(const State& x, const FrameCues& cues) const {
    return energy(score(x, cues), options_);
  }

 private:
  const BodyDofs* dofs_;
  const BodyShape* shape_;
  ScoreOptions options_;
  RegionModel region_;
  BoneShading shading_;
  Lighting lighting_;
};

}  // namespace simcap::tracker::gomez
