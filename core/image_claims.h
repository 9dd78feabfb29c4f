// What a PNG's or an OpenEXR's structure claims, read from its bytes without decoding: decoders
// allocate what a damaged file claims before they find the damage, so the claims are checked first.
#pragma once

#include <string>
#include <string_view>

namespace simcap {

// The PNG signature starts `bytes`.
bool is_png(std::string_view bytes);

struct PngClaims {
  long width = 0, height = 0;  // IHDR's (0 x 0 when IHDR is not the first chunk)
  int channels = 1;
  // Empty when every chunk fits in the file, IEND ends it and the image data could hold the
  // pixels IHDR claims at zlib's densest (1032:1); else what is wrong.
  std::string damage;
};
PngClaims png_claims(std::string_view bytes);

// Empty when every attribute of an OpenEXR file's headers fits in the file (OpenEXR 3.1 allocates
// what an attribute's size field claims before reading it); else what is wrong. Bytes that are
// not OpenEXR give an empty answer: the reader will say so.
std::string exr_header_damage(std::string_view bytes);

}  // namespace simcap
