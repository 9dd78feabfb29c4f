// MPEG-4 BAP names and the BAP 3.1 text file (mpeg4_bap.h).
#include "models/mpeg4_bap.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap {
namespace {

constexpr double kRadiansPerUnit = 1e-5;
constexpr double kMetresPerUnit = 1e-3;

// The standard's order: left before right for every paired parameter, the vertebrae from the
// skull down, the fingers from the pinky to the thumb, the root last.
std::vector<std::string> make_names() {
  std::vector<std::string> n = {"sacroiliac_tilt", "sacroiliac_torsion", "sacroiliac_roll"};
  const auto pairs = [&n](std::initializer_list<std::string> motions) {
    for (const std::string& m : motions) {
      n.push_back("l_" + m);
      n.push_back("r_" + m);
    }
  };
  pairs({"hip_flexion",
         "hip_abduct",
         "hip_twisting",
         "knee_flexion",
         "knee_twisting",
         "ankle_flexion",
         "ankle_twisting",
         "subtalar_flexion",
         "midtarsal_twisting",
         "metatarsal_flexion",
         "sternoclavicular_abduct",
         "sternoclavicular_rotate",
         "acromioclavicular_abduct",
         "acromioclavicular_rotate",
         "shoulder_flexion",
         "shoulder_abduct",
         "shoulder_twisting",
         "elbow_flexion",
         "elbow_twisting",
         "wrist_flexion",
         "wrist_pivot",
         "wrist_twisting"});
  for (const char* m : {"roll", "torsion", "tilt"}) n.push_back(std::string("skullbase_") + m);
  const std::pair<const char*, int> regions[] = {{"vc", 7}, {"vt", 12}, {"vl", 5}};
  for (const auto& [prefix, count] : regions) {
    for (int i = 1; i <= count; ++i) {
      for (const char* m : {"roll", "torsion", "tilt"}) {
        n.push_back(prefix + std::to_string(i) + "_" + m);
      }
    }
  }
  for (const char* finger : {"pinky", "ring", "middle", "index"}) {
    const std::string f = finger;
    pairs({f + "0_flexion", f + "1_flexion", f + "1_pivot", f + "1_twisting", f + "2_flexion",
           f + "3_flexion"});
  }
  pairs({"thumb1_flexion", "thumb1_pivot", "thumb1_twisting", "thumb2_flexion", "thumb3_flexion"});
  for (const char* m : {"tr_vertical", "tr_lateral", "tr_frontal", "rt_body_turn", "rt_body_roll",
                        "rt_body_tilt"}) {
    n.push_back(std::string("HumanoidRoot_") + m);
  }
  return n;
}

const std::vector<std::string>& names() {
  static const std::vector<std::string> table = make_names();
  return table;
}

void check_id(int id) {
  if (id < 1 || id > kBapCount) {
    throw Error("BAP id " + std::to_string(id) + " is outside 1.." + std::to_string(kBapCount));
  }
}

// Whitespace-separated tokens with their line numbers; '#' starts a comment line.
class Tokens {
 public:
  Tokens(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

  bool next(std::string* token) {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        at_line_start_ = true;
        ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        // Every byte the token loop below stops at, '\f' and '\v' too: a separator skipped
        // here but not there gave an empty token that never advanced (a fuzzing finding).
        ++pos_;
      } else if (c == '#' && at_line_start_) {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else {
        const size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) {
          ++pos_;
        }
        *token = std::string(text_.substr(start, pos_ - start));
        at_line_start_ = false;
        return true;
      }
    }
    return false;
  }
  std::string require(const std::string& what) {
    std::string t;
    if (!next(&t)) fail("expected " + what + ", got the end of the file");
    return t;
  }
  long integer(const std::string& what) {
    const std::string t = require(what);
    size_t used = 0;
    long v = 0;
    try {
      v = std::stol(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != t.size()) fail("expected " + what + " (an integer), got '" + t + "'");
    return v;
  }
  double number(const std::string& what) {
    const std::string t = require(what);
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != t.size() || !std::isfinite(v)) {
      fail("expected " + what + " (a number), got '" + t + "'");
    }
    return v;
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw_input_error(source_, line_, "", message);
  }

 private:
  std::string_view text_;
  std::string source_;
  size_t pos_ = 0;
  int line_ = 1;
  bool at_line_start_ = true;
};

}  // namespace

std::string_view bap_name(int id) {
  check_id(id);
  return names()[id - 1];
}

int bap_id(std::string_view name) {
  const auto& n = names();
  for (size_t i = 0; i < n.size(); ++i) {
    if (n[i] == name) return static_cast<int>(i) + 1;
  }
  return 0;
}

bool bap_is_translation(int id) {
  return id >= 181 && id <= 183;
}

void BapFrame::set(int id, double value) {
  check_id(id);
  mask.set(id - 1);
  values[id - 1] = value;
}

std::string format_bap(const BapFile& file) {
  if (file.name.empty() || file.name.find_first_of(" \t\r\n") != std::string::npos) {
    throw Error("BAP file: the sequence name must be one word, got '" + file.name + "'");
  }
  if (!(file.fps > 0) || !std::isfinite(file.fps)) throw Error("BAP file: fps must be positive");
  std::ostringstream out;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", file.fps);
  out << "3.1 " << file.name << ' ' << buffer << ' ' << file.frames.size() << '\n';
  for (const BapFrame& f : file.frames) {
    for (int i = 0; i < kBapCount; ++i) out << (i ? " " : "") << (f.mask[i] ? '1' : '0');
    out << '\n' << f.number;
    for (int i = 0; i < kBapCount; ++i) {
      if (!f.mask[i]) continue;
      const double unit = bap_is_translation(i + 1) ? kMetresPerUnit : kRadiansPerUnit;
      if (!std::isfinite(f.values[i])) {
        throw Error("BAP file: frame " + std::to_string(f.number) + " has a non-finite " +
                    std::string(bap_name(i + 1)));
      }
      out << ' ' << std::llround(f.values[i] / unit);
    }
    out << '\n';
  }
  return out.str();
}

void write_bap(const std::filesystem::path& path, const BapFile& file) {
  write_text_atomic(path, format_bap(file));
}

BapFile parse_bap(std::string_view text, const std::string& source) {
  Tokens t(text, source);
  BapFile file;
  const std::string version = t.require("the BAP version '3.1'");
  if (version != "3.1") t.fail("expected the BAP version '3.1', got '" + version + "'");
  file.name = t.require("the sequence name");
  file.fps = t.number("frames per second");
  if (!(file.fps > 0)) t.fail("expected frames per second > 0");
  const long count = t.integer("the frame count");
  if (count < 0) t.fail("expected a frame count >= 0");
  for (long k = 0; k < count; ++k) {
    BapFrame f;
    for (int i = 0; i < kBapCount; ++i) {
      const long bit = t.integer("mask bit " + std::to_string(i + 1) + " of frame " +
                                 std::to_string(k) + " (0 or 1)");
      if (bit != 0 && bit != 1) t.fail("expected a mask bit 0 or 1");
      f.mask[i] = bit == 1;
    }
    f.number = static_cast<int>(t.integer("the frame number"));
    for (int i = 0; i < kBapCount; ++i) {
      if (!f.mask[i]) continue;
      const double unit = bap_is_translation(i + 1) ? kMetresPerUnit : kRadiansPerUnit;
      f.values[i] =
          unit * static_cast<double>(t.integer("the value of " + std::string(bap_name(i + 1))));
    }
    file.frames.push_back(f);
  }
  std::string extra;
  if (t.next(&extra)) {
    t.fail("expected the end of the file after " + std::to_string(count) + " frames, got '" +
           extra + "'");
  }
  return file;
}

BapFile read_bap(const std::filesystem::path& path) {
  return parse_bap(read_text(path), path.string());
}

}  // namespace simcap
