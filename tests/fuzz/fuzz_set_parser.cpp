// SPDX-License-Identifier: MIT
// libFuzzer target: `--set NAME=VALUE` as ParamValues::parseAssignment reads it, on every
// scene's table. Whatever the bytes, the parser either sets one value that is within its
// range and reads back from its own formatting, or throws InputError with a message and
// changes nothing, its message on one line. Any other exception, a crash or a sanitizer
// report is a bug.
#include "core/scene.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void require(bool condition)
{
    if (!condition)
        std::abort();
}

void fuzzOne(const ab::SceneInfo& scene, std::string_view text)
{
    ab::ParamValues values = scene.defaults();
    const ab::ParamValues before = values;
    try {
        values.parseAssignment(text);
    } catch (const ab::InputError& e) {
        require(*e.what() != '\0');
        require(std::string_view(e.what()).find('\n') == std::string_view::npos); // one line
        require(values == before); // nothing half-applied
        return;
    }
    for (std::size_t i = 0; i < scene.params.size(); ++i) {
        const ab::ParamSpec& spec = scene.params[i];
        const Eigen::Vector3d value = values.raw(i);
        require(!ab::checkValue(spec, value));
        // What is shown reads back to the same value.
        ab::ParamValues again = scene.defaults();
        again.parse(spec.key, ab::formatValue(spec, value));
        require(again.raw(i) == value);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (const ab::SceneInfo* scene : ab::allScenes())
        fuzzOne(*scene, text);
    return 0;
}
