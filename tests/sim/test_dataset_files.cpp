// The dataset's image files hold exactly what the renderer produced: depth EXRs are float32,
// bit for bit (sensor noise included), with the compression the writer asks for.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <filesystem>

#include "core/image_io.h"
#include "scenes/scene.h"
#include "sim/dataset_writer.h"
#include "sim/render_setup.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::TempDir;

bool same_bits(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  for (int y = 0; y < a.rows; ++y) {
    if (std::memcmp(a.ptr(y), b.ptr(y), a.cols * a.elemSize()) != 0) return false;
  }
  return true;
}

TEST(DatasetFiles, DepthIsWrittenExactly) {
  TempDir dir;
  // Depth noise fills the low mantissa bits, which a lossy codec would change first.
  const Scene scene =
      load_scene(std::string(SIMCAP_SOURCE_DIR) + "/scenes/studio4.yaml",
                 {"rig.resolution=[160,120]", "noise.depth_sigma=0.003", "render.normals=true"});
  RenderSetup setup(scene);
  setup.pose(5);
  std::vector<RenderedView> views;
  setup.renderer().render(setup.cameras(), 5, views);
  std::vector<std::string> names;
  for (const Camera& c : scene.cameras) names.push_back(c.name);
  DatasetWriter writer(dir.path(), names, true);
  writer.write_frame(5, views);

  for (size_t c = 0; c < views.size(); ++c) {
    for (const auto& [kind, image] :
         {std::pair{"depth", views[c].depth}, std::pair{"normal", views[c].normal}}) {
      SCOPED_TRACE(names[c] + " " + kind);
      const auto file = writer.image_path(static_cast<int>(c), kind, 5);
      EXPECT_TRUE(same_bits(read_image(file), image));
      auto in = OIIO::ImageInput::open(file.string());
      ASSERT_TRUE(in);
      EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
      EXPECT_EQ(in->spec().get_string_attribute("compression"), kDatasetCompression.exr);
    }
  }
}

}  // namespace
}  // namespace simcap
