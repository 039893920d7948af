// SPDX-License-Identifier: MIT
// A small seeded generator whose stream is the same on every platform and standard
// library (std::uniform_real_distribution is not), so seeded scenes are reproducible.
#pragma once

#include <cstdint>

namespace ab {

// SplitMix64 (Steele, Lea, Flood 2014): a 64-bit state advanced by a Weyl constant and
// scrambled by two multiply-xorshift rounds.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next()
    {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

    // Uniform in [0, 1): the top 53 bits as a fraction.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    std::uint64_t state_;
};

} // namespace ab
