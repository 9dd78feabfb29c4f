#include "tracker/common/png_decoder.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/image_claims.h"
#include "core/image_io.h"

namespace simcap::tracker {
namespace {

struct Source {
  const std::uint8_t* data;
  size_t size, offset;
};

void read_from(png_structp png, png_bytep out, png_size_t n) {
  auto* s = static_cast<Source*>(png_get_io_ptr(png));
  if (s->offset + n > s->size) png_error(png, "truncated");
  std::copy_n(s->data + s->offset, n, out);
  s->offset += n;
}

// libpng reports errors by longjmp: the two steps below hold nothing with a destructor, so the
// jump skips no clean-up.
bool read_header(png_structp png, png_infop info, png_uint_32* width, png_uint_32* height,
                 int* depth, int* colour, int* interlace) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  png_get_IHDR(png, info, width, height, depth, colour, interlace, nullptr, nullptr);
  return true;
}

// All rows, or the first `count` (then the rest of the file, and its CRCs, are not read).
bool read_rows(png_structp png, png_infop info, png_bytepp rows, png_uint_32 count,
               png_uint_32 height) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_update_info(png, info);
  if (count < height) {
    for (png_uint_32 r = 0; r < count; ++r) png_read_row(png, rows[r], nullptr);
    return true;
  }
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

}  // namespace

cv::Mat decode_png(const std::filesystem::path& path, int flags, int rows) {
  // OpenCV throws for some files it cannot read (a size beyond its own limit) instead of
  // returning an empty image.
  auto fallback = [&] {
    try {
      return cv::imread(path.string(), flags);
    } catch (const cv::Exception&) {
      return cv::Mat();
    }
  };
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  if (error || !in) return {};
  std::vector<std::uint8_t> bytes(size);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size))) {
    return {};
  }
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  // Not a PNG: cv::imread would try every decoder it has on it, and GDCM's DICOM reader aborts
  // the process on some bytes (a fuzzing finding).
  if (!is_png(text)) return {};
  // The size IHDR claims is checked before either decoder sees the file: a file libpng refuses
  // still goes to cv::imread, which would allocate up to 2^30 pixels. A damaged file (a chunk
  // longer than the file, no IEND, too few bytes for its pixels) is refused too: cv::imread
  // allocated what a chunk length claimed (1.3 GB for a 206-byte file the fuzzer found).
  const PngClaims claims = png_claims(text);
  if (claims.width > 0) check_image_size(path, claims.width, claims.height, 1);
  if (!claims.damage.empty()) return {};
  if (flags != cv::IMREAD_UNCHANGED && flags != cv::IMREAD_COLOR) return fallback();
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  struct Release {
    png_structp* png;
    png_infop* info;
    ~Release() { png_destroy_read_struct(png, info, nullptr); }
  } release{&png, &info};
  if (!info) return fallback();
  // Silence libpng's own messages: a file it rejects goes to OpenCV, which reports it.
  png_set_error_fn(
      png, nullptr, [](png_structp p, png_const_charp) { png_longjmp(p, 1); },
      [](png_structp, png_const_charp) {});
  png_set_option(png, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
  // No chunk of a file this size needs more (a damaged length field asked for gigabytes).
  png_set_chunk_malloc_max(png, std::max<png_alloc_size_t>(bytes.size(), 1 << 20));
  Source source{bytes.data(), bytes.size(), 0};
  png_set_read_fn(png, &source, read_from);
  png_uint_32 width = 0, height = 0;
  int depth = 0, colour = 0, interlace = 0;
  if (!read_header(png, info, &width, &height, &depth, &colour, &interlace)) return fallback();
  check_image_size(path, width, height, png_get_channels(png, info));
  const bool grey = colour == PNG_COLOR_TYPE_GRAY && flags == cv::IMREAD_UNCHANGED;
  const bool rgb = colour == PNG_COLOR_TYPE_RGB;
  if (depth != 8 || interlace != PNG_INTERLACE_NONE || !(grey || rgb)) return fallback();
  const png_uint_32 count = rows >= 0 ? std::min<png_uint_32>(rows, height) : height;
  const int type = grey ? CV_8UC1 : CV_8UC3, decoded = static_cast<int>(count);
  cv::Mat image(static_cast<int>(height), static_cast<int>(width), type);
  std::vector<png_bytep> pointers(height);
  for (png_uint_32 r = 0; r < height; ++r) pointers[r] = image.ptr(static_cast<int>(r));
  if (!read_rows(png, info, pointers.data(), count, height)) return fallback();
  // OpenCV's order is BGR. libpng's png_set_bgr swaps byte by byte, a tenth of a frame's
  // tracking; OpenCV's vectorized swap costs a fraction of that.
  cv::Mat out = grey ? image : cv::Mat(image.size(), type);
  if (!grey && decoded > 0) {
    cv::Mat top = out.rowRange(0, decoded);
    cv::cvtColor(image.rowRange(0, decoded), top, cv::COLOR_RGB2BGR);
  }
  out.rowRange(decoded, out.rows).setTo(0);
  return out;
}

}  // namespace simcap::tracker
