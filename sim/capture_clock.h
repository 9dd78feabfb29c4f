// When each camera captures each pixel of a frame: the frame's nominal time, the camera's sync
// offset, the rolling shutter's row delay and the exposure that blurs motion. Renderer, ground
// truth and dataset writer all take their times from here, so images and tables agree.
#pragma once

#include <vector>

#include "scenes/scene.h"

namespace simcap {

// The Embree ray times of one camera's rows, in the units of its group's window (the bodies'
// time steps span [0, 1] over the window). Float, and computed by at_row() alone, so that the
// renderer and the ground truth's visibility rays use bit-identical times.
struct RayTimes {
  float row0 = 0;      // the middle of row 0's exposure
  float per_row = 0;   // rolling shutter: added per image row
  float exposure = 0;  // exposure length; blur samples spread over row time -+ exposure / 2

  float at_row(int row) const { return row0 + per_row * static_cast<float>(row); }
};

class CaptureClock {
 public:
  // Cameras sharing a sync offset. Their rows are captured within [begin_s, end_s] relative to
  // the frame's nominal time, which the bodies' time steps span when the group is rendered.
  struct Group {
    double offset_s = 0;
    double begin_s = 0, end_s = 0;
    std::vector<int> cameras;  // indices into scene.cameras, in rig order
  };

  // Offsets drawn from rig.sync's sigma are keyed by (seed, camera name): a camera rendered
  // alone (render --cameras) keeps its offset.
  explicit CaptureClock(const Scene& scene);

  // True when every camera captures every row at the frame's nominal time in an instant (the
  // default): the renderer then poses the bodies once per frame, as it always did.
  bool still() const { return still_; }
  // Nominal time of dataset frame `frame`: (first_frame + frame) / fps.
  double frame_time(int frame) const;
  double offset_s(int camera) const { return offset_s_.at(camera); }
  double readout_s() const { return readout_s_; }
  // Exposure length; zero unless render.shutter > 0 with more than one sample per pixel.
  double exposure_s() const { return exposure_s_; }
  // Time of a row's exposure middle relative to the frame's nominal time; `row` may be
  // fractional (a projected point's v) and is clamped to [0, height - 1].
  double row_offset_s(int camera, double row) const;
  const std::vector<Group>& groups() const { return groups_; }
  int group_of(int camera) const { return group_of_.at(camera); }
  RayTimes ray_times(int camera) const;
  // Vertex time steps of the moving bodies. With a rolling shutter, depth, mask and parts see
  // the bodies between steps, so there are enough that linear interpolation follows the motion
  // (kStepsPerFrame per frame period over the window), at most Embree's 129: four keep a hand
  // swung at 10 rad/s on a 0.8 m arm within 1 mm of its arc, and Embree's motion-blur BVH build
  // grows with the steps (16 made a 30 ms readout render 8x slower than a still frame, 4 makes
  // it 3x). Without one, the labels' rays are at the exposure's middle, which the middle of
  // three steps holds exactly; only the blurred colour sees the two halves of the exposure
  // (at most one frame period) interpolated, the hand above within 3 mm of its arc. Three
  // instead of five steps at shutter 1 halve the build (53 -> 30 ms a frame on studio4).
  int time_steps() const { return time_steps_; }
  static constexpr int kStepsPerFrame = 4;
  // The time step every label ray's time falls on (the exposure's middle, without a rolling
  // shutter), or -1: the renderer traces those rays against a still copy of that step
  // (EmbreeScene's still scene), only the other blur samples paying for motion blur.
  int still_step() const { return still_step_; }

 private:
  double fps_;
  int first_frame_;
  std::vector<double> offset_s_;
  std::vector<int> heights_;
  double readout_s_ = 0, exposure_s_ = 0;
  bool still_ = true;
  int time_steps_ = 1;
  int still_step_ = -1;
  std::vector<Group> groups_;
  std::vector<int> group_of_;
};

}  // namespace simcap
