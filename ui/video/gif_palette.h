// SPDX-License-Identifier: MIT
// One palette for a whole GIF clip (a GIF frame holds at most 256 colours): a histogram of
// frames sampled over the clip, split by median cut into the colours that cover it best,
// and each frame mapped to them with a 4x4 ordered dither (the same pixel of a still
// background maps to the same index in every frame, so GIF's frame differencing and LZW
// keep working; error diffusion would make still areas crawl). No Qt here.
#pragma once

#include <cstdint>
#include <vector>

namespace ab::video {

class GifPalette {
public:
    GifPalette();

    // Counts the colours of one packed RGB frame (every pixel).
    void addSample(const std::uint8_t* rgb, int width, int height, int stride);
    bool hasSamples() const { return total_ > 0; }
    // Median cut of what was counted into at most `colours` entries (1-256), 0xRRGGBB each.
    void build(int colours);
    const std::vector<std::uint32_t>& colours() const { return palette_; }

    // Index of the palette colour for every pixel of the frame, dithered; build() first.
    void map(const std::uint8_t* rgb, int width, int height, int stride, std::uint8_t* out, int outStride);

private:
    std::uint8_t nearest(int r, int g, int b);

    // 5 bits a channel: 32,768 cells, each with its pixel count and colour sums (so a
    // cell's colour is the exact mean of its pixels, not the cell's centre).
    std::vector<std::uint64_t> count_, sumR_, sumG_, sumB_;
    std::uint64_t total_ = 0;
    std::vector<std::uint32_t> palette_;
    std::vector<std::int16_t> lookup_; // 6 bits a channel -> palette index, -1 until asked
};

} // namespace ab::video
