// SPDX-License-Identifier: MIT
// libFuzzer target: the preset reader. Whatever the bytes, parsePreset either returns a
// preset that writes back to JSON and reads again as the same preset, or throws
// InputError with a message. Any other exception, a crash or a sanitizer report is a bug.
#include "core/io/preset.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

void require(bool condition)
{
    if (!condition)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view json(reinterpret_cast<const char*>(data), size);
    ab::Preset preset;
    try {
        preset = ab::parsePreset(json, "fuzz input");
    } catch (const ab::InputError& e) {
        require(*e.what() != '\0');
        return 0;
    }
    require(ab::parsePreset(ab::presetToJson(preset), "written back") == preset);
    return 0;
}
