// Sizes simcap refuses to allocate for: an input that asks for more (a header's frame count or
// image size, a scene's resolution) is an Error naming the limit, before any memory is taken.
#pragma once

#include <string_view>

namespace simcap::limits {

// Frames of a clip or a dataset: 9.3 hours at 30 frames/s, 2.3 hours at 120.
inline constexpr long kMaxFrames = 1'000'000;
// Pixels of one image side and of a whole image (8192 x 8192: 1 GiB as float RGBA, the largest
// decoded form; the renderer's 640 x 480 is 0.5% of it).
inline constexpr int kMaxImageSide = 16384;
inline constexpr long kMaxImagePixels = 8192L * 8192;
inline constexpr const char* kMaxImagePixelsText = "8192x8192";
// Channels of an image file (grey, grey + alpha, RGB, RGBA).
inline constexpr int kMaxImageChannels = 4;

// Joint rotations of a whole motion in memory (frames x joints, 32 bytes each: 1 GiB), e.g. 3.9
// hours of an 81-joint humanoid at 30 frames/s. A few hundred bytes of X3D can ask for more.
inline constexpr long kMaxPoseSamples = 1L << 25;

// Frames at t = i / fps for i = 0, 1, ... within [0, duration_s] (the end kept despite rounding,
// 994 frames at 120 fps -> 30 fps); throws Error "<what>: ..." naming kMaxFrames when they are
// more, or kMaxPoseSamples when they hold more joint rotations at `joints` a frame.
int frames_within(double duration_s, double fps, long joints, std::string_view what);

}  // namespace simcap::limits
