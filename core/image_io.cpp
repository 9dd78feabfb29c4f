#include "core/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_claims.h"
#include "core/limits.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

OIIO::TypeDesc oiio_type(int depth) {
  switch (depth) {
    case CV_8U:
      return OIIO::TypeDesc::UINT8;
    case CV_16U:
      return OIIO::TypeDesc::UINT16;
    case CV_32F:
      return OIIO::TypeDesc::FLOAT;
    default:
      return OIIO::TypeDesc::UNKNOWN;
  }
}

// OpenEXR's own thread pool would take each scanline of an uncompressed image as a task for
// another thread: the hand-overs cost more than the copies they spread (measured: ~4% of a
// render's CPU in semaphores and context switches). simcap runs images in parallel instead.
void single_threaded_openexr() {
  [[maybe_unused]] static const bool once = OIIO::attribute("exr_threads", -1);
}

}  // namespace

void write_image(const fs::path& path, const cv::Mat& image, const ImageCompression& compression) {
  const std::string ext = path.extension().string();
  const bool exr = ext == ".exr";
  const bool png = ext == ".png";
  const int depth = image.depth();
  if (image.empty()) throw Error(path.string() + ": cannot write an empty image");
  if (!(png && (depth == CV_8U || depth == CV_16U)) && !(exr && depth == CV_32F)) {
    throw Error(path.string() +
                ": unsupported combination of file type and pixel type (PNG takes 8- or 16-bit "
                "integers, EXR takes float32)");
  }
  const cv::Mat data = image.isContinuous() ? image : image.clone();
  // Encoded in memory, then written and checked by write_text_atomic: OpenImageIO's PNG writer
  // does not report a failed write (a full disk), which would leave a truncated image in place.
  // One buffer per thread, kept between images: a fresh one would be paged in anew for every
  // image, and growing it as the encoder appends would copy it several times.
  thread_local std::vector<unsigned char> bytes;
  bytes.clear();
  bytes.reserve(data.total() * data.elemSize() + 4096);
  OIIO::Filesystem::IOVecOutput memory(bytes);
  if (exr) single_threaded_openexr();
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw Error(path.string() + ": " + OIIO::geterror());
  if (!out->supports("ioproxy") || !out->set_ioproxy(&memory)) {
    throw Error(path.string() + ": OpenImageIO cannot encode this format in memory");
  }
  OIIO::ImageSpec spec(data.cols, data.rows, data.channels(), oiio_type(depth));
  // No timestamp (OpenEXR files get one by default): equal images give byte-identical files.
  spec.attribute("DateTime", "");
  if (exr) spec.attribute("compression", compression.exr);
  if (png) {
    spec.attribute("png:compressionLevel", compression.png_level);
    // 8 is libpng's PNG_FILTER_NONE; left alone, libpng tries every filter on every row.
    if (!compression.png_filter) spec.attribute("png:filter", 8);
  }
  if (!out->open(path.string(), spec) || !out->write_image(oiio_type(depth), data.data) ||
      !out->close()) {
    throw Error(path.string() + ": write failed: " + out->geterror());
  }
  write_text_atomic(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

void check_image_size(const fs::path& path, long width, long height, int channels) {
  if (width < 1 || height < 1) {
    throw Error(path.string() + ": the image is " + std::to_string(width) + "x" +
                std::to_string(height) + " pixels; expected at least 1x1");
  }
  if (width > limits::kMaxImagePixels / height) {
    throw Error(path.string() + ": the image is " + std::to_string(width) + "x" +
                std::to_string(height) + " pixels, more than the " +
                std::to_string(limits::kMaxImagePixels) + " (" + limits::kMaxImagePixelsText +
                ") simcap allows an image");
  }
  if (channels < 1 || channels > limits::kMaxImageChannels) {
    throw Error(path.string() + ": the image has " + std::to_string(channels) +
                " channels; simcap reads 1 to " + std::to_string(limits::kMaxImageChannels));
  }
}

cv::Mat read_image(const fs::path& path) {
  if (!fs::exists(path)) throw Error(path.string() + ": image not found");
  // Read once, checked, and decoded from memory. The checks come first because the decoders
  // allocate what a damaged header claims before they find the damage.
  const std::string bytes = read_text(path);
  const std::string ext = path.extension().string();
  if (ext == ".png" && is_png(bytes)) {
    const PngClaims claims = png_claims(bytes);
    if (claims.width > 0) check_image_size(path, claims.width, claims.height, claims.channels);
    if (!claims.damage.empty()) throw Error(path.string() + ": damaged PNG: " + claims.damage);
  }
  if (const std::string damage = ext == ".exr" ? exr_header_damage(bytes) : ""; !damage.empty()) {
    throw Error(path.string() + ": damaged OpenEXR header: " + damage);
  }
  // Only the reader its extension names: ImageInput::open would, when that reader refuses the
  // file, try each of OpenImageIO's ~30 formats on it, which costs more than reading a good
  // image and reports the last format's complaint instead of the named one's.
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  auto in = OIIO::ImageInput::create(path.string());
  if (!in) throw Error(path.string() + ": cannot read image: " + OIIO::geterror());
  if (in->supports("ioproxy")) in->set_ioproxy(&memory);
  OIIO::ImageSpec opened;
  if (!in->open(path.string(), opened)) {
    throw Error(path.string() + ": cannot read image: " + in->geterror());
  }
  const OIIO::ImageSpec& spec = in->spec();
  check_image_size(path, spec.width, spec.height, spec.nchannels);
  // Some of the formats OpenImageIO reads hold volumes.
  if (spec.depth != 1) throw Error(path.string() + ": a volume image; expected a 2D image");
  int depth = CV_8U;
  if (spec.format == OIIO::TypeDesc::UINT16) depth = CV_16U;
  if (spec.format == OIIO::TypeDesc::FLOAT || spec.format == OIIO::TypeDesc::HALF) depth = CV_32F;
  cv::Mat image(spec.height, spec.width, CV_MAKETYPE(depth, spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, oiio_type(depth), image.data)) {
    throw Error(path.string() + ": cannot decode image: " + in->geterror());
  }
  in->close();
  return image;
}

}  // namespace simcap
