// Fuzz target: an MPEG-4 BAP file (parse_bap), as `simcap track --export bap` writes it; what
// parses must format back to text that parses to the same frames.
#include <stdexcept>

#include "models/mpeg4_bap.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  simcap::fuzz::expect_value_or_error([&] {
    const auto file = simcap::parse_bap(simcap::fuzz::as_text(data, size), "fuzz.bap");
    const auto again = simcap::parse_bap(simcap::format_bap(file), "formatted.bap");
    if (again.frames.size() != file.frames.size())
      throw std::logic_error("a formatted BAP file lost frames");
  });
  return 0;
}
