// SPDX-License-Identifier: MIT
// The built-in preset files, compiled into the program at build time by
// core/io/embed_presets.cmake from resources/presets/*.json (the core has no Qt, so no qrc).
#pragma once

#include <string_view>
#include <vector>

namespace ab::embedded {

struct File {
    std::string_view key;  // file name without .json
    std::string_view text; // the file's bytes
};

// In file-name order.
const std::vector<File>& presetFiles();

} // namespace ab::embedded
