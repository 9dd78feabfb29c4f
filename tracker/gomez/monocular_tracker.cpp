// The monocular tracker's frame loop (monocular_tracker.h).
#include "tracker/gomez/monocular_tracker.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include "models/pose.h"
#include "tracker/common/mask_box.h"

namespace simcap::tracker::gomez {
namespace {

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// The body posed at `x` rendered at full resolution in a crop around it and the silhouette: what
// the first frame's colours and light are learned on.
struct FullRender {
  std::vector<Eigen::Isometry3d> world;
  View view;
  LabelImage cells;
};

FullRender render_full(const Body& body, const State& x, const Camera& camera, const cv::Mat& image,
                       const cv::Mat& silhouette) {
  FullRender r;
  r.world = forward_kinematics(body.skeleton, body.dofs.pose(x));
  const cv::Rect box = (body_box(body.shape, r.world, camera) | mask_box(silhouette)) &
                       cv::Rect(0, 0, image.cols, image.rows);
  r.view = {&camera, box.x, box.y, 1, box.width, box.height};
  render_labels(body.shape, r.world, r.view, r.cells);
  return r;
}

}  // namespace

ColourClasses learn_colours(const Body& body, const State& x, const Camera& camera,
                            const cv::Mat& image, const cv::Mat& silhouette,
                            const ColourOptions& options) {
  const FullRender r = render_full(body, x, camera, image, silhouette);
  return ColourClasses(image, silhouette, r.cells, r.view, body.shape, options);
}

LightFit fit_start_light(const Body& body, const State& x, const Camera& camera,
                         const cv::Mat& image, const cv::Mat& silhouette,
                         const std::vector<std::uint8_t>& cell_class) {
  const FullRender r = render_full(body, x, camera, image, silhouette);
  return fit_light(
      shaded_pixels(body.shape, r.world, r.view, r.cells, image, silhouette, cell_class),
      camera.R * Eigen::Vector3d::UnitY());
}

Lighting settle_offsets(const BoneShading& shading, const Body& body, const State& x,
                        const FrameCues& cues, const Lighting& lighting) {
  const auto world = forward_kinematics(body.skeleton, body.dofs.pose(x));
  LabelImage labels;
  render_labels(body.shape, world, cues.view, labels);
  std::array<double, kMaxColourClasses + 1> sum{};
  std::array<int, kMaxColourClasses + 1> count{};
  for (const BoneSample& b : shading.observe(labels, world, cues)) {
    if (b.pixels < BoneShading::kMinPixels) continue;
    sum[b.cls] += b.grey - predicted_grey(b, lighting);
    ++count[b.cls];
  }
  Lighting out = lighting;
  for (int c = 0; c <= kMaxColourClasses; ++c) {
    if (count[c]) out.offset[c] += sum[c] / count[c];
  }
  return out;
}

MonocularTracker::MonocularTracker(std::unique_ptr<Body> body, const State& x0,
                                   const Camera& camera, const cv::Mat& image,
                                   const cv::Mat& silhouette, const MonocularSettings& options)
    : body_(std::move(body)), camera_(&camera), options_(options), x0_(x0) {
  classes_ = learn_colours(*body_, x0, camera, image, silhouette, options.colours);
  scorer_ =
      std::make_unique<PoseScorer>(body_->dofs, body_->shape, classes_.cell_class(), options.score);
  if (options.score.sigma_shade_grey > 0 && scorer_->shading().available()) {
    light_fit_ = fit_start_light(*body_, x0, camera, image, silhouette, classes_.cell_class());
    scorer_->set_lighting(light_fit_.lighting);
  }
  filter_ = std::make_unique<ParticleFilter>(*scorer_, &body_->arms, options.filter,
                                             body_->legs ? &*body_->legs : nullptr);
}

TrackedFrame MonocularTracker::track(const cv::Mat& image, const cv::Mat& silhouette, int frame,
                                     const State* start) {
  TrackedFrame out;
  if (start && started_) {
    estimate_ = *start;
    if (options_.search == Search::particles) filter_->reset(*start, previous_);
  }
  auto t = std::chrono::steady_clock::now();
  const State& last = started_ ? estimate_ : x0_;
  const cv::Rect hint =
      body_box(body_->shape, forward_kinematics(body_->skeleton, body_->dofs.pose(last)), *camera_);
  FrameCues cues = make_cues(*camera_, image, silhouette, classes_, hint, options_.cues);
  out.cues_ms = ms_since(t);
  if (start) {
    out.start_score = scorer_->score(*start, cues);
  }
  t = std::chrono::steady_clock::now();
  if (!started_) {
    started_ = true;
    if (scorer_->lighting().known()) {
      light_fit_.lighting =
          settle_offsets(scorer_->shading(), *body_, x0_, cues, light_fit_.lighting);
      scorer_->set_lighting(light_fit_.lighting);
    }
    out.estimate = x0_;
    out.score = scorer_->score(x0_, cues);
    out.evaluations = 1;
    if (options_.search == Search::particles) filter_->reset(x0_, cues);
  } else if (options_.search == Search::particles) {
    out.filter = filter_->step(previous_, cues, frame);
    out.estimate = out.filter.best;
    // Scored afresh: the filter keeps energies, whose terms its simplices mix.
    out.score = scorer_->score(out.estimate, cues);
    out.evaluations = out.filter.evaluations;
  } else {
    const Registered r = register_pose(*scorer_, cues, estimate_, options_.registration);
    out.estimate = r.x;
    out.score = r.score;
    out.evaluations = r.evaluations;
  }
  out.search_ms = ms_since(t);
  estimate_ = out.estimate;
  // A heading that jumped by more than a quarter turn (the filter took a reflection, whose left
  // and right angles are swapped) restarts the smoothing: averaging across it would blend the
  // two sides' angles.
  const int turn = body_->dofs.find("root_turn");
  const bool jumped = turn >= 0 && output_.size() > 0 &&
                      std::abs(out.estimate[turn] - output_[turn]) > std::numbers::pi / 2;
  if (output_.size() == 0 || !(options_.smoothing > 0) || jumped) {
    output_ = out.estimate;
  } else {
    const BodyDofs& dofs = body_->dofs;
    for (int i = 0; i < dofs.size(); ++i) {
      output_[i] = dofs[i].translation ? out.estimate[i]
                                       : options_.smoothing * output_[i] +
                                             (1 - options_.smoothing) * out.estimate[i];
    }
  }
  out.output = output_;
  previous_ = std::move(cues);
  return out;
}

}  // namespace simcap::tracker::gomez
