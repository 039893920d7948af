// SPDX-License-Identifier: MIT
// The preset file's document (its format: preset.cpp), as presetToJson writes it.
#pragma once

#include "preset.h"
#include "strict_json.h"

#include <string_view>

namespace ab::presetfile {

inline constexpr std::string_view formatTag = "amazeballs-preset";

// The document of a checked preset: its keys in the format's order, only what is set, every
// number a double (as the reader makes them).
json::Document document(const Preset& p);

} // namespace ab::presetfile
