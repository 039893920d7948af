// SPDX-License-Identifier: MIT
// What the preset tests share: a minimal preset document to build bad files from.
#pragma once

#include <string>

namespace testing {

// A minimal valid preset document for `scene` with `extra` members appended.
inline std::string presetDoc(const char* scene, const char* extra = "")
{
    return std::string(R"({"format": "amazeballs-preset", "version": 1, "name": "t", "scene": ")") + scene +
           R"(", "model": "report")" + extra + "}";
}

} // namespace testing
