// Fuzz target: a scene file with command-line overrides (load_scene, as `simcap render` and
// `--set` read them). Leading lines "#!set KEY=VALUE" (YAML comments) are the overrides.
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = simcap::fuzz::as_text(data, size);
  std::vector<std::string> overrides;
  constexpr std::string_view prefix = "#!set ";
  for (std::size_t pos = 0; pos < text.size() && text.substr(pos).starts_with(prefix);) {
    const std::size_t eol = std::min(text.find('\n', pos), text.size());
    overrides.emplace_back(text.substr(pos + prefix.size(), eol - pos - prefix.size()));
    pos = eol + 1;
  }
  const auto path = simcap::fuzz::write_input("scene.yaml", text);
  simcap::fuzz::expect_value_or_error([&] {
    const simcap::Scene scene = simcap::load_scene(path, overrides);
    simcap::scene_to_yaml(scene);
  });
  return 0;
}
