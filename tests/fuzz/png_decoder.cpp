// Fuzz target: the trackers' own libpng decoder (tracker::decode_png), grey and colour, which
// promises an image or an empty one; decoded down to a row only, its rows above are the whole
// image's.
#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "tests/fuzz/fuzz_input.h"
#include "tracker/common/png_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("frame.png", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] {
    for (const int flags : {cv::IMREAD_UNCHANGED, cv::IMREAD_COLOR}) {
      const cv::Mat whole = simcap::tracker::decode_png(path, flags);
      // A row count from the input, so that the fuzzer explores none, some and all.
      const int rows = static_cast<int>(size % 19);
      const cv::Mat top = simcap::tracker::decode_png(path, flags, rows);
      if (whole.empty() || top.empty()) continue;
      const int kept = std::min(rows, whole.rows);
      if (top.size() != whole.size() || top.type() != whole.type() ||
          (kept > 0 &&
           cv::norm(top.rowRange(0, kept), whole.rowRange(0, kept), cv::NORM_INF) != 0)) {
        throw std::logic_error("the first rows decoded differ from the whole image's");
      }
    }
  });
  return 0;
}
