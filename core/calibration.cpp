#include "core/calibration.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/core/persistence.hpp>
#include <set>
#include <sstream>
#include <string_view>

#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

constexpr double kRotationTolerance = 1e-6;
// OpenCV's calibration files hold one YAML document; EasyMocap's too.
constexpr int kMaxYamlDocuments = 1;

cv::Mat to_mat(const Eigen::MatrixXd& m) {
  cv::Mat out;
  cv::eigen2cv(m, out);
  return out;
}

// Reads fields of one camera and reports problems as "file: camera 'name': field 'key': ...".
class FieldReader {
 public:
  FieldReader(const fs::path& file, const cv::FileNode& node, std::string camera)
      : file_(file), node_(node), camera_(std::move(camera)) {}

  [[noreturn]] void fail(std::string_view key, std::string_view message) const {
    throw_input_error(file_, 0, "camera '" + camera_ + "': field '" + std::string(key) + "'",
                      message);
  }

  Eigen::MatrixXd matrix(std::string_view key, int rows, int cols) const {
    const cv::FileNode n = node_[std::string(key)];
    if (n.empty()) fail(key, "missing (expected a " + shape(rows, cols) + " matrix)");
    // The declared size is checked before OpenCV allocates for it. Distortion and vectors are
    // accepted as rows or columns, as OpenCV itself does.
    if (!n.isMap() || !n["rows"].isInt() || !n["cols"].isInt()) {
      fail(key, "expected a " + shape(rows, cols) + " !!opencv-matrix");
    }
    const int got_rows = static_cast<int>(n["rows"]), got_cols = static_cast<int>(n["cols"]);
    const bool vector_like = rows == 1 || cols == 1;
    const bool ok = (got_rows == rows && got_cols == cols) ||
                    (vector_like && (got_rows == 1 || got_cols == 1) &&
                     static_cast<long>(got_rows) * got_cols == static_cast<long>(rows) * cols);
    if (!ok) {
      fail(key, "expected a " + shape(rows, cols) + " matrix, got " + shape(got_rows, got_cols));
    }
    cv::Mat m;
    try {
      n >> m;
    } catch (const std::exception&) {  // cv::Exception, or a standard one from a damaged node
      fail(key, "expected a " + shape(rows, cols) + " !!opencv-matrix");
    }
    if (m.empty() || m.total() != static_cast<size_t>(rows * cols) || m.channels() != 1) {
      fail(key, "expected a " + shape(rows, cols) + " !!opencv-matrix");
    }
    m = m.reshape(1, rows);
    m.convertTo(m, CV_64F);
    Eigen::MatrixXd out;
    cv::cv2eigen(m, out);
    if (!out.allFinite()) fail(key, "expected finite numbers");
    return out;
  }

  Eigen::Matrix3d rotation(std::string_view key) const {
    const Eigen::Matrix3d R = matrix(key, 3, 3);
    if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > kRotationTolerance ||
        R.determinant() < 0) {
      fail(key, "not a rotation matrix (expected R^T R = I and det R = +1)");
    }
    return R;
  }

  Eigen::Matrix3d intrinsics(std::string_view key) const {
    const Eigen::Matrix3d K = matrix(key, 3, 3);
    if (K(0, 0) <= 0 || K(1, 1) <= 0 || K(0, 1) != 0 || K(1, 0) != 0 || K(2, 0) != 0 ||
        K(2, 1) != 0 || K(2, 2) != 1) {
      // OpenCV's projection model has no skew term, so a skewed K could not be honoured.
      fail(key, "not a camera matrix (expected [fx 0 cx; 0 fy cy; 0 0 1] with fx, fy > 0)");
    }
    return K;
  }

  int positive_int(std::string_view key) const {
    const cv::FileNode n = node_[std::string(key)];
    if (n.empty() || !n.isInt()) fail(key, "missing or not an integer");
    const int v = static_cast<int>(n);
    if (v <= 0) fail(key, "must be positive, got " + std::to_string(v));
    return v;
  }

  void check_rodrigues_matches(std::string_view key, const Eigen::Matrix3d& R) const {
    const Eigen::Vector3d rvec = matrix(key, 3, 1);
    cv::Mat Rm;
    cv::Rodrigues(to_mat(rvec), Rm);
    Eigen::Matrix3d Rr;
    cv::cv2eigen(Rm, Rr);
    if ((Rr - R).norm() > 1e-5) fail(key, "Rodrigues vector disagrees with the 3x3 rotation");
  }

 private:
  static std::string shape(int r, int c) { return std::to_string(r) + "x" + std::to_string(c); }
  const fs::path& file_;
  cv::FileNode node_;
  std::string camera_;
};

// The lines on which yaml-cpp's events start (0-based); the syntax check needs no document tree.
struct YamlEventLines : YAML::EventHandler {
  std::set<int> lines;
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { lines.insert(m.line); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { lines.insert(m.line); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                const std::string&) override {
    lines.insert(m.line);
  }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    lines.insert(m.line);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    lines.insert(m.line);
  }
  void OnMapEnd() override {}
};

// How many flow collections ('[', '{') are still open after `row`, starting from `depth`;
// brackets inside quotes and comments do not count.
int flow_depth_after(std::string_view row, int depth) {
  char quote = 0;
  for (const char c : row) {
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#') {
      break;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return depth;
}

// A line on which no value starts continues one from an earlier line (a multi-line plain scalar
// to yaml-cpp), which OpenCV 4.6's reader reads as structure and may loop forever on (fuzzing
// findings, tests/fuzz/regressions/calibration_opencv/value_over_two_lines and
// calibration_easymocap/bracket_continues_value). Blank lines, comments, document markers and
// lines that only close brackets of an open flow collection start none by nature.
void check_one_line_values(const fs::path& path, std::string_view text,
                           const std::set<int>& lines) {
  int depth = 0;
  for (std::size_t start = 0, line = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view row = text.substr(start, end - start);
    start = end + 1;
    const int open = depth;
    depth = flow_depth_after(row, depth);
    const std::size_t first = row.find_first_not_of(open > 0 ? " \t\r]}," : " \t\r");
    if (first == std::string_view::npos || row[first] == '#' || row.starts_with("---") ||
        row.starts_with("...") || lines.contains(static_cast<int>(line))) {
      continue;
    }
    throw_input_error(path, static_cast<int>(line) + 1, "",
                      "this line continues a value from an earlier line; calibration values "
                      "(and keys) fit on one line");
  }
}

// A line that starts with "---" or "..." and goes on without a blank is a plain scalar to
// yaml-cpp but a document start or end to OpenCV, whose reader then loops forever on some files
// (fuzzing findings, tests/fuzz/regressions/calibration_opencv/dashes_glued_to_text and
// calibration_easymocap/dots_glued_to_text).
void check_document_markers(const fs::path& path, std::string_view text) {
  for (std::size_t start = 0, line = 1; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view row = text.substr(start, end - start);
    start = end + 1;
    for (const std::string_view marker : {"---", "..."}) {
      if (row.size() > 3 && row.starts_with(marker) &&
          !std::isspace(static_cast<unsigned char>(row[3]))) {
        throw_input_error(path, static_cast<int>(line), "",
                          "'" + std::string(marker) + "' (a document " +
                              (marker == "---" ? "start" : "end") + ") needs a blank after it");
      }
    }
  }
}

// YAML allows no control characters but tab and line breaks, and OpenCV's reader loops forever
// on some files with a NUL in their header line (a fuzzing finding,
// tests/fuzz/regressions/calibration_opencv/nul_in_header); the header is blanked before
// yaml-cpp's check, so they are refused here, over the whole file.
void check_control_characters(const fs::path& path, std::string_view text) {
  int line = 1;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') ++line;
    if ((byte < 0x20 && c != '\t' && c != '\n' && c != '\r') || byte == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02x", byte);
      throw_input_error(path, line, "",
                        std::string("a control character (byte ") + code +
                            "); YAML allows none but tab and line breaks");
    }
  }
}

// OpenCV 4.6's YAML reader loops forever on some malformed files (a fuzzing finding, kept in
// tests/fuzz/regressions/calibration_opencv/), so yaml-cpp checks the syntax first; its errors
// also name the line, which OpenCV's do not. Documents are counted because yaml-cpp 0.7 itself
// returns empty documents without end on some inputs (a file holding only ","), which is why
// this is not YAML::LoadAll.
void check_yaml_syntax(const fs::path& path) {
  std::string text = read_text(path);
  check_control_characters(path, text);
  // OpenCV's header "%YAML:1.0" is a directive yaml-cpp refuses; blanking it keeps line numbers.
  if (text.starts_with("%YAML:")) text.erase(0, text.find('\n'));
  check_document_markers(path, text);
  std::istringstream in(text);
  try {
    YAML::Parser parser(in);
    YamlEventLines events;
    for (int documents = 0; parser.HandleNextDocument(events);) {
      if (++documents > kMaxYamlDocuments) {
        throw_input_error(path, 0, "",
                          "not a calibration file: more than one YAML document (yaml-cpp starts "
                          "another where a line is less indented than the first value)");
      }
    }
    check_one_line_values(path, text, events.lines);
  } catch (const YAML::Exception& e) {
    throw_input_error(path, e.mark.line + 1, "", "not valid YAML: " + e.msg);
  }
}

cv::FileStorage open_for_reading(const fs::path& path) {
  if (!fs::exists(path)) throw Error(path.string() + ": calibration file not found");
  check_yaml_syntax(path);
  try {
    cv::FileStorage fsr(path.string(), cv::FileStorage::READ);
    if (!fsr.isOpened()) throw Error(path.string() + ": cannot open as an OpenCV YAML file");
    return fsr;
  } catch (const cv::Exception& e) {
    throw Error(path.string() + ": not a valid OpenCV YAML file: " + e.msg);
  } catch (const std::exception& e) {
    // OpenCV's parser throws standard exceptions (std::length_error) on some damaged files.
    throw Error(path.string() + ": not a valid OpenCV YAML file: " + e.what());
  }
}

// FileStorage::operator[] asserts (throws cv::Exception) on a file whose top is not a map.
void require_top_map(const fs::path& path, const cv::FileStorage& fsr, const std::string& fields) {
  if (!fsr.root().isMap()) {
    throw_input_error(path, 0, "", "expected a map of fields at the top (" + fields + ", ...)");
  }
}

std::vector<std::string> read_names(const fs::path& path, const cv::FileStorage& fsr,
                                    const std::string& key) {
  require_top_map(path, fsr, key);
  const cv::FileNode n = fsr[key];
  if (n.empty() || !n.isSeq()) {
    throw_input_error(path, 0, "field '" + key + "'", "missing (expected a list of camera names)");
  }
  std::vector<std::string> names;
  for (const auto& item : n) {
    if (!item.isString()) {
      throw_input_error(path, 0, "field '" + key + "'", "every entry must be a camera name");
    }
    names.push_back(static_cast<std::string>(item));
  }
  if (names.empty()) throw_input_error(path, 0, "field '" + key + "'", "lists no camera");
  return names;
}

// Formatted in memory, then written and checked by write_text_atomic: FileStorage does not
// report a failed write (a full disk), which would leave a truncated file in place.
template <typename WriteBody>
void write_storage(const fs::path& path, WriteBody&& body) {
  cv::FileStorage fsw(path.extension().string(), cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  if (!fsw.isOpened()) throw Error(path.string() + ": cannot format for writing");
  body(fsw);
  write_text_atomic(path, fsw.releaseAndGetString());
}

}  // namespace

Eigen::Vector3d rodrigues_of(const Eigen::Matrix3d& R) {
  cv::Mat rvec;
  cv::Rodrigues(to_mat(R), rvec);
  Eigen::Vector3d out;
  cv::cv2eigen(rvec, out);
  return out;
}

void write_opencv_calibration(const fs::path& path, const std::vector<Camera>& cams) {
  write_storage(path, [&](cv::FileStorage& fsw) {
    fsw << "camera_names"
        << "[";
    for (const auto& c : cams) fsw << c.name;
    fsw << "]";
    for (const auto& c : cams) {
      fsw << c.name << "{";
      fsw << "image_width" << c.width << "image_height" << c.height;
      fsw << "K" << to_mat(c.K) << "dist" << to_mat(c.dist.transpose());
      fsw << "R" << to_mat(c.R) << "rvec" << to_mat(rodrigues_of(c.R)) << "t" << to_mat(c.t);
      fsw << "}";
    }
  });
}

std::vector<Camera> read_opencv_calibration(const fs::path& path) {
  cv::FileStorage fsr = open_for_reading(path);
  std::vector<Camera> cams;
  for (const auto& name : read_names(path, fsr, "camera_names")) {
    const cv::FileNode node = fsr[name];
    if (node.empty() || !node.isMap()) {
      throw_input_error(path, 0, "camera '" + name + "'",
                        "listed in camera_names but has no entry of its own");
    }
    const FieldReader r(path, node, name);
    Camera c;
    c.name = name;
    c.width = r.positive_int("image_width");
    c.height = r.positive_int("image_height");
    c.K = r.intrinsics("K");
    c.dist = r.matrix("dist", 1, 5).transpose();
    c.R = r.rotation("R");
    r.check_rodrigues_matches("rvec", c.R);
    c.t = r.matrix("t", 3, 1);
    cams.push_back(std::move(c));
  }
  return cams;
}

void write_easymocap_calibration(const fs::path& intri_path, const fs::path& extri_path,
                                 const std::vector<Camera>& cams) {
  auto write_names = [&](cv::FileStorage& fsw) {
    fsw << "names"
        << "[";
    for (const auto& c : cams) fsw << c.name;
    fsw << "]";
  };
  write_storage(intri_path, [&](cv::FileStorage& fsw) {
    write_names(fsw);
    for (const auto& c : cams) {
      fsw << "K_" + c.name << to_mat(c.K);
      fsw << "dist_" + c.name << to_mat(c.dist.transpose());
    }
  });
  write_storage(extri_path, [&](cv::FileStorage& fsw) {
    write_names(fsw);
    for (const auto& c : cams) {
      fsw << "R_" + c.name << to_mat(rodrigues_of(c.R));
      fsw << "Rot_" + c.name << to_mat(c.R);
      fsw << "T_" + c.name << to_mat(c.t);
    }
  });
}

std::vector<Camera> read_easymocap_calibration(const fs::path& intri_path,
                                               const fs::path& extri_path) {
  cv::FileStorage intri = open_for_reading(intri_path);
  cv::FileStorage extri = open_for_reading(extri_path);
  const auto names = read_names(intri_path, intri, "names");
  require_top_map(extri_path, extri, "Rot_" + names.front() + ", T_" + names.front());
  std::vector<Camera> cams;
  for (const auto& name : names) {
    const FieldReader ri(intri_path, intri.root(), name);
    const FieldReader re(extri_path, extri.root(), name);
    Camera c;
    c.name = name;
    c.K = ri.intrinsics("K_" + name);
    c.dist = ri.matrix("dist_" + name, 1, 5).transpose();
    c.R = re.rotation("Rot_" + name);
    re.check_rodrigues_matches("R_" + name, c.R);
    c.t = re.matrix("T_" + name, 3, 1);
    cams.push_back(std::move(c));
  }
  return cams;
}

const Camera& find_camera(const std::vector<Camera>& cams, std::string_view name,
                          const fs::path& source) {
  std::string known;
  for (const auto& c : cams) {
    if (c.name == name) return c;
    known += (known.empty() ? "" : ", ") + c.name;
  }
  throw Error(source.string() + ": unknown camera '" + std::string(name) +
              "' (the file has: " + known + ")");
}

}  // namespace simcap
