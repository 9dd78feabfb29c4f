// MPEG-4 Body Animation Parameters (ISO/IEC 14496-2): the 186 BAP names and ids, and the BAP 3.1
// text file that avatar players read, so any tracker's joint angles can animate an MPEG-4 body.
#pragma once

#include <array>
#include <bitset>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

// File layout (what format_bap writes and parse_bap reads; whitespace-separated tokens, so line
// breaks inside a frame are not significant to the reader):
//
//   3.1 <name> <frames per second> <frame count>        header (name without spaces)
//   <186 mask bits, 0 or 1>                             per frame: which BAPs it sets, by id
//   <frame number> <one integer per set BAP, by id>
//
// Rotational BAPs (every id but 181..183) are integers in 1e-5 rad, the unit of MPEG-4 players
// (VREng's 3.1 reader divides by pi*1e5/180 to get degrees). The root translations 181..183
// (HumanoidRoot_tr_vertical, _lateral, _frontal) are integers in millimetres, simcap's choice.
// Lines starting with '#' are comments. The sign and axis of each angle are the caller's
// (simcap writes its own right-handed joint axes, models/joint_limits.h).

namespace simcap {

inline constexpr int kBapCount = 186;

// "l_shoulder_flexion" for 32, ..., ids 1..186 as in ISO/IEC 14496-2 (Table 2-2 of Gomez
// Jauregui 2011 lists the 20 of his upper body). Throws Error for an id outside 1..186.
std::string_view bap_name(int id);
// The id of a BAP name, or 0 when there is none.
int bap_id(std::string_view name);
// True for the root translations 181..183 (millimetres in the file, metres in memory).
bool bap_is_translation(int id);

struct BapFrame {
  int number = 0;               // frame number written in the file
  std::bitset<kBapCount> mask;  // bit id-1 set: the frame sets BAP id
  // values[id - 1]: radians for rotations, metres for translations; 0 where the mask is clear.
  std::array<double, kBapCount> values{};

  void set(int id, double value);  // sets the mask bit too; throws Error for a bad id
};

struct BapFile {
  std::string name = "simcap";  // no whitespace
  double fps = 30.0;
  std::vector<BapFrame> frames;
};

std::string format_bap(const BapFile& file);
// Written atomically.
void write_bap(const std::filesystem::path& path, const BapFile& file);
// Reads the layout above. Errors name `source` and the line, and say what was expected.
BapFile parse_bap(std::string_view text, const std::string& source);
BapFile read_bap(const std::filesystem::path& path);

}  // namespace simcap
