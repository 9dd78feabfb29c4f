// Fuzz target: a dataset's gt/gestures.csv of labelled gesture intervals (read_gesture_table).
#include "core/gesture_table.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("gestures.csv", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::read_gesture_table(path); });
  return 0;
}
