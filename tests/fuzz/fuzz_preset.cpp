// SPDX-License-Identifier: MIT
// libFuzzer target: the JSON reader and the preset reader on it. Whatever the bytes, the
// reader either returns a document that writes back to text that reads as the same
// document, or throws InputError with a one-line message; then parsePreset either returns
// a preset that writes back to JSON and reads again as the same preset, or throws
// InputError with a message. Any other exception, a crash or a sanitizer report is a bug.
#include "core/io/preset.h"
#include "core/io/strict_json.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace {

void require(bool condition)
{
    if (!condition)
        std::abort();
}

void requireOneLine(const ab::InputError& e)
{
    require(*e.what() != '\0' && std::strchr(e.what(), '\n') == nullptr);
}

void checkDocument(std::string_view json)
{
    ab::json::Document doc;
    try {
        doc = ab::json::parse(json, "fuzz input");
    } catch (const ab::InputError& e) {
        requireOneLine(e);
        return;
    }
    require(ab::json::parse(ab::json::write(doc), "written back") == doc);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view json(reinterpret_cast<const char*>(data), size);
    checkDocument(json);
    ab::Preset preset;
    try {
        preset = ab::parsePreset(json, "fuzz input");
    } catch (const ab::InputError& e) {
        requireOneLine(e);
        return 0;
    }
    require(ab::parsePreset(ab::presetToJson(preset), "written back") == preset);
    return 0;
}
