// SPDX-License-Identifier: MIT
// What the preset tests share: a minimal preset document to build bad files from, and the
// built-in presets by key.
#pragma once

#include "core/io/preset.h"

#include <stdexcept>
#include <string>

namespace testing {

// A minimal valid preset document for `scene` with `extra` members appended.
inline std::string presetDoc(const char* scene, const char* extra = "")
{
    return std::string(R"({"format": "amazeballs-preset", "version": 1, "name": "t", "scene": ")") + scene +
           R"(", "model": "report")" + extra + "}";
}

inline const ab::Preset& builtin(const std::string& key)
{
    for (const ab::BuiltinPreset& b : ab::builtinPresets())
        if (b.key == key)
            return b.preset;
    throw std::runtime_error("no built-in preset " + key);
}

} // namespace testing
