// Gomez Jauregui's monocular tracker frame by frame: the cues of each frame, the particle filter
// (or the chapter-3 registration alone), and the output smoothing of his avatar stream
// (theta*_t = a theta*_{t-1} + (1 - a) theta_t, a = 0.6).
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>

#include "core/camera.h"
#include "core/name_table.h"
#include "tracker/gomez/body.h"
#include "tracker/gomez/colour_classes.h"
#include "tracker/gomez/frame_cues.h"
#include "tracker/gomez/light_fit.h"
#include "tracker/gomez/particle_filter.h"
#include "tracker/gomez/registration.h"

namespace simcap::tracker::gomez {

// particles: the particle filter with heuristics (chapter 4); simplex: Nelder-Mead registration
// from the previous frame's pose (chapter 3).
enum class Search { particles, simplex };
inline constexpr NameTable<Search, 2> kSearches{
    {{"particles", Search::particles}, {"simplex", Search::simplex}}};

struct MonocularSettings {
  BodyKind body = BodyKind::full;
  // The full body stands on the floor y = 0 (its lowest sole touches it): simcap's addition, the
  // ground plane the thesis's seated user did not need; it fixes the root's height and, seen by
  // a calibrated camera from above, much of its depth.
  bool floor = true;
  // Scale the capsules to the first silhouette (thesis §3.3's shape adjustment).
  bool fit_shape = true;
  Search search = Search::particles;
  FilterOptions filter;
  RegistrationOptions registration;
  ScoreOptions score;
  CueOptions cues;
  ColourOptions colours;
  // Output smoothing of the angles (root translation excluded: it would lag a walk); 0 is off.
  double smoothing = 0.6;
};

struct TrackedFrame {
  State estimate;  // the search's best pose
  State output;    // after smoothing
  Score score;
  Score start_score;  // of the given start pose (--oracle: the truth's), when one was given
  FilterStep filter;  // particles: the filter's statistics
  int evaluations = 0;
  double cues_ms = 0, search_ms = 0;
};

class MonocularTracker {
 public:
  // `body` in the pose `x0` on the first frame (`image` CV_8UC3, `silhouette` CV_8UC1, seen by
  // `camera`, which must outlive the tracker): the colour classes are learned there.
  MonocularTracker(std::unique_ptr<Body> body, const State& x0, const Camera& camera,
                   const cv::Mat& image, const cv::Mat& silhouette,
                   const MonocularSettings& options);

  // The first call returns x0 (the known first pose); later calls search from the last frame,
  // or from `start` when given (every particle there).
  TrackedFrame track(const cv::Mat& image, const cv::Mat& silhouette, int frame,
                     const State* start = nullptr);

  const Body& body() const { return *body_; }
  const ColourClasses& classes() const { return classes_; }
  const PoseScorer& scorer() const { return *scorer_; }
  const FrameCues& last_cues() const { return previous_; }
  const Camera& camera() const { return *camera_; }
  // The shading's light, fitted on the first frame (LightFit::pixels 0: none).
  const LightFit& light_fit() const { return light_fit_; }

 private:
  std::unique_ptr<Body> body_;
  const Camera* camera_;
  MonocularSettings options_;
  ColourClasses classes_;
  std::unique_ptr<PoseScorer> scorer_;
  std::unique_ptr<ParticleFilter> filter_;
  State x0_, estimate_, output_;
  FrameCues previous_;
  bool started_ = false;
  LightFit light_fit_;
};

// The shading's light fitted on one frame with `body` posed at `x` (full resolution, a crop
// around the body and the silhouette): the start pose, known (--init gt) or assumed (--init auto).
LightFit fit_start_light(const Body& body, const State& x, const Camera& camera,
                         const cv::Mat& image, const cv::Mat& silhouette,
                         const std::vector<std::uint8_t>& cell_class);

// `lighting` with each class's offset moved so that the arm bones of `body` posed at `x` show
// on average the grey it predicts for them in `cues` (their working-resolution means, which the
// shading term compares, not the full-resolution pixels the light was fitted to).
Lighting settle_offsets(const BoneShading& shading, const Body& body, const State& x,
                        const FrameCues& cues, const Lighting& lighting);

// Learns the colour classes of `body` posed at `x` on one frame (full resolution, a crop around
// the body and the silhouette).
ColourClasses learn_colours(const Body& body, const State& x, const Camera& camera,
                            const cv::Mat& image, const cv::Mat& silhouette,
                            const ColourOptions& options);

}  // namespace simcap::tracker::gomez
