// The dataset's 8-bit grey and colour PNGs decoded with libpng directly, skipping zlib's
// Adler-32 pass over the pixels (the PNG chunk CRCs still check every compressed byte).
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>

namespace simcap::tracker {

// As cv::imread(path, flags) for flags cv::IMREAD_UNCHANGED and cv::IMREAD_COLOR (BGR), and the
// same pixels. Files this path does not cover (16 bits, palettes, alpha, interlacing, grey read
// as colour, damaged files) go to cv::imread. Empty when the file cannot be read or is not a
// PNG; a header that claims more pixels than limits.h allows throws Error naming the limit
// (check_image_size).
// With `rows` >= 0 only the image's first `rows` rows are decoded and the rest are left black:
// a PNG's rows can only be inflated in order, so a caller that reads no pixel below a row stops
// there.
cv::Mat decode_png(const std::filesystem::path& path, int flags, int rows = -1);

}  // namespace simcap::tracker
