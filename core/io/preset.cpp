// SPDX-License-Identifier: MIT
#include "preset.h"

namespace ab {

Preset loadPreset(const std::string& nameOrPath)
{
    throw InputError("--preset " + nameOrPath + ": presets are not readable in this build");
}

void applyPreset(const Preset&, RunSpec&) {}

} // namespace ab
