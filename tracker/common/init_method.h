// How a tracker finds its first pose: from the first frame's ground truth, as the theses
// initialized theirs, or from the images alone (each family documents what it assumes).
#pragma once

#include "core/name_table.h"

namespace simcap::tracker {

enum class InitMethod { gt, automatic };
inline constexpr NameTable<InitMethod, 2> kInitMethods{
    {{"gt", InitMethod::gt}, {"auto", InitMethod::automatic}}};

}  // namespace simcap::tracker
