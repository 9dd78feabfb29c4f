// Fuzz target: the trackers' own libpng decoder (tracker::decode_png), grey and colour, which
// promises an image or an empty one.
#include <opencv2/imgcodecs.hpp>

#include "tests/fuzz/fuzz_input.h"
#include "tracker/common/png_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("frame.png", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] {
    simcap::tracker::decode_png(path, cv::IMREAD_UNCHANGED);
    simcap::tracker::decode_png(path, cv::IMREAD_COLOR);
  });
  return 0;
}
