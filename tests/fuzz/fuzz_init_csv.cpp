// SPDX-License-Identifier: MIT
// libFuzzer target: the --init trajectory CSV reader. Whatever the bytes, parseFirstState
// either returns a state of at least one ball whose numbers are all finite, at one time,
// or throws InputError with a one-line message. Any other exception, a crash or a
// sanitizer report is a bug.
#include "core/io/trajectory_csv.h"
#include "core/params.h"

#include <cmath>
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

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const ab::State s = ab::parseFirstState(text, "--init: fuzz.csv");
        require(s.size() >= 1);
        require(s.p.allFinite() && s.v.allFinite() && std::isfinite(s.t));
    } catch (const ab::InputError& e) {
        require(*e.what() != '\0');
        require(std::strchr(e.what(), '\n') == nullptr);
    }
    return 0;
}
