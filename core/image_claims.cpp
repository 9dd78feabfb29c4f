#include "core/image_claims.h"

#include <cstdint>

namespace simcap {
namespace {

constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1a\n";
// Deflate codes at most 258 bytes in 2 bits.
constexpr std::uint64_t kZlibDensest = 1032;

std::uint64_t be32(std::string_view b, std::size_t at) {
  const auto u = [&](std::size_t i) {
    return static_cast<std::uint64_t>(static_cast<unsigned char>(b[at + i]));
  };
  return u(0) << 24 | u(1) << 16 | u(2) << 8 | u(3);
}

std::uint32_t le32(std::string_view b, std::size_t at) {
  const auto u = [&](std::size_t i) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + i]));
  };
  return u(0) | u(1) << 8 | u(2) << 16 | u(3) << 24;
}

int png_channels(int colour_type) {
  switch (colour_type) {
    case 2:
      return 3;
    case 4:
      return 2;
    case 6:
      return 4;
    default:  // grey, palette
      return 1;
  }
}

}  // namespace

bool is_png(std::string_view bytes) {
  return bytes.starts_with(kPngSignature);
}

PngClaims png_claims(std::string_view bytes) {
  PngClaims claims;
  if (!is_png(bytes)) {
    claims.damage = "not a PNG file (no PNG signature)";
    return claims;
  }
  int depth = 8;
  if (bytes.size() >= 24 && bytes.substr(12, 4) == "IHDR") {
    claims.width = static_cast<long>(be32(bytes, 16));
    claims.height = static_cast<long>(be32(bytes, 20));
  }
  if (bytes.size() >= 26) {
    depth = static_cast<unsigned char>(bytes[24]);
    claims.channels = png_channels(static_cast<unsigned char>(bytes[25]));
  }
  std::uint64_t data = 0;
  bool ended = false;
  for (std::size_t at = kPngSignature.size(); !ended;) {
    if (bytes.size() - at < 12) {
      claims.damage = "it ends at byte " + std::to_string(bytes.size()) + " without an IEND chunk";
      return claims;
    }
    const std::uint64_t length = be32(bytes, at);
    const std::string_view type = bytes.substr(at + 4, 4);
    if (length > bytes.size() - at - 12) {
      claims.damage = "chunk '" + std::string(type) + "' at byte " + std::to_string(at) +
                      " claims " + std::to_string(length) + " bytes, more than the file holds";
      return claims;
    }
    if (type == "IDAT") data += length;
    ended = type == "IEND";
    at += 12 + length;
  }
  const std::uint64_t row =
      (static_cast<std::uint64_t>(claims.width) * claims.channels * depth + 7) / 8;
  if (row * static_cast<std::uint64_t>(claims.height) > kZlibDensest * data + kZlibDensest) {
    claims.damage = std::to_string(data) + " bytes of image data cannot hold the " +
                    std::to_string(claims.width) + "x" + std::to_string(claims.height) +
                    " pixels the header claims";
  }
  return claims;
}

std::string exr_header_damage(std::string_view bytes) {
  if (bytes.size() < 8 || le32(bytes, 0) != 20000630) return {};
  const bool multipart = (le32(bytes, 4) & 0x1000) != 0;
  std::size_t at = 8;
  // A name or type runs to its NUL; npos when the file ends first.
  auto next_string = [&](std::string_view& out) {
    const std::size_t end = bytes.find('\0', at);
    if (end == std::string_view::npos) return false;
    out = bytes.substr(at, end - at);
    at = end + 1;
    return true;
  };
  // A multi-part file holds one header per part and ends the list with an empty one.
  for (bool in_header = false;;) {
    std::string_view name, type;
    if (!next_string(name)) return "the header ends before its last attribute";
    if (name.empty()) {
      if (!multipart || !in_header) return {};
      in_header = false;
      continue;
    }
    in_header = true;
    if (!next_string(type) || bytes.size() - at < 4) {
      return "attribute '" + std::string(name) + "' ends with the file";
    }
    const auto size = static_cast<std::int32_t>(le32(bytes, at));
    at += 4;
    if (size < 0 || static_cast<std::size_t>(size) > bytes.size() - at) {
      return "attribute '" + std::string(name) + "' claims " + std::to_string(size) + " bytes, " +
             std::to_string(bytes.size() - at) + " are left in the file";
    }
    at += static_cast<std::size_t>(size);
  }
}

}  // namespace simcap
