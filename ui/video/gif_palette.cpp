// SPDX-License-Identifier: MIT
#include "gif_palette.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace ab::video {

namespace {

constexpr int kCellBits = 5, kCells = 1 << (3 * kCellBits);
constexpr int kLookupBits = 6, kLookupSize = 1 << (3 * kLookupBits);

int cellOf(int r, int g, int b)
{
    return ((r >> (8 - kCellBits)) << (2 * kCellBits)) | ((g >> (8 - kCellBits)) << kCellBits) | (b >> (8 - kCellBits));
}

// A box of histogram cells (indices into `cells`) with its pixel-weighted statistics.
struct Box {
    std::vector<int> cells;
    double weight = 0.0;
    std::array<double, 3> mean{};
    std::array<double, 3> sse{}; // per channel: sum over pixels of (value - mean)^2
};

struct CellColour {
    double n;
    std::array<double, 3> c; // the cell's mean colour
};

Box makeBox(std::vector<int> members, const std::vector<CellColour>& cells)
{
    Box box;
    box.cells = std::move(members);
    std::array<double, 3> sum{}, sum2{};
    for (int i : box.cells) {
        const CellColour& cc = cells[std::size_t(i)];
        box.weight += cc.n;
        for (int k = 0; k < 3; ++k) {
            sum[std::size_t(k)] += cc.n * cc.c[std::size_t(k)];
            sum2[std::size_t(k)] += cc.n * cc.c[std::size_t(k)] * cc.c[std::size_t(k)];
        }
    }
    for (std::size_t k = 0; k < 3; ++k) {
        box.mean[k] = sum[k] / box.weight;
        // sum (x - m)^2 = sum x^2 - (sum x)^2 / n
        box.sse[k] = std::max(0.0, sum2[k] - sum[k] * sum[k] / box.weight);
    }
    return box;
}

double boxError(const Box& b)
{
    return b.cells.size() < 2 ? -1.0 : b.sse[0] + b.sse[1] + b.sse[2];
}

// Splits `box` along its channel of largest spread at the pixel-weighted median.
std::pair<Box, Box> split(const Box& box, const std::vector<CellColour>& cells)
{
    const auto channel = std::size_t(std::max_element(box.sse.begin(), box.sse.end()) - box.sse.begin());
    std::vector<int> order = box.cells;
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return cells[std::size_t(a)].c[channel] < cells[std::size_t(b)].c[channel]; });
    double acc = 0.0;
    std::size_t cut = 1;
    for (; cut < order.size(); ++cut) {
        acc += cells[std::size_t(order[cut - 1])].n;
        if (acc >= box.weight / 2.0)
            break;
    }
    cut = std::clamp<std::size_t>(cut, 1, order.size() - 1);
    return {makeBox(std::vector<int>(order.begin(), order.begin() + std::ptrdiff_t(cut)), cells),
            makeBox(std::vector<int>(order.begin() + std::ptrdiff_t(cut), order.end()), cells)};
}

// The 4x4 Bayer matrix: thresholds 0..15, each 16th of the dither's amplitude apart.
constexpr int bayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
// Peak-to-peak dither in 8-bit levels: about the spacing of a 255-colour palette spread
// over a few hues' shading, enough to break bands on a lit sphere into a fine pattern.
constexpr int kDitherLevels = 12;

} // namespace

GifPalette::GifPalette() : count_(kCells, 0), sumR_(kCells, 0), sumG_(kCells, 0), sumB_(kCells, 0) {}

void GifPalette::addSample(const std::uint8_t* rgb, int width, int height, int stride)
{
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* p = rgb + std::ptrdiff_t(y) * stride;
        for (int x = 0; x < width; ++x, p += 3) {
            const auto cell = std::size_t(cellOf(p[0], p[1], p[2]));
            ++count_[cell];
            sumR_[cell] += p[0];
            sumG_[cell] += p[1];
            sumB_[cell] += p[2];
        }
    }
    total_ += std::uint64_t(width) * std::uint64_t(height);
}

void GifPalette::build(int colours)
{
    if (colours < 1 || colours > 256)
        throw std::invalid_argument("GifPalette::build: colours outside [1, 256]");
    std::vector<CellColour> cells(kCells);
    std::vector<int> used;
    for (int i = 0; i < kCells; ++i) {
        const auto k = std::size_t(i);
        if (count_[k] == 0)
            continue;
        const double n = double(count_[k]);
        cells[k] = {n, {double(sumR_[k]) / n, double(sumG_[k]) / n, double(sumB_[k]) / n}};
        used.push_back(i);
    }
    palette_.clear();
    lookup_.assign(kLookupSize, -1);
    if (used.empty()) {
        palette_.push_back(0);
        return;
    }
    std::vector<Box> boxes{makeBox(std::move(used), cells)};
    while (int(boxes.size()) < colours) {
        const auto worst = std::max_element(boxes.begin(), boxes.end(),
                                            [](const Box& a, const Box& b) { return boxError(a) < boxError(b); });
        if (boxError(*worst) <= 0.0)
            break; // every box is one colour
        auto [a, b] = split(*worst, cells);
        *worst = std::move(a);
        boxes.push_back(std::move(b));
    }
    for (const Box& b : boxes) {
        const auto r = std::uint32_t(std::clamp(b.mean[0] + 0.5, 0.0, 255.0));
        const auto g = std::uint32_t(std::clamp(b.mean[1] + 0.5, 0.0, 255.0));
        const auto bl = std::uint32_t(std::clamp(b.mean[2] + 0.5, 0.0, 255.0));
        palette_.push_back((r << 16) | (g << 8) | bl);
    }
}

std::uint8_t GifPalette::nearest(int r, int g, int b)
{
    const int key = ((r >> (8 - kLookupBits)) << (2 * kLookupBits)) | ((g >> (8 - kLookupBits)) << kLookupBits) |
                    (b >> (8 - kLookupBits));
    std::int16_t& hit = lookup_[std::size_t(key)];
    if (hit >= 0)
        return std::uint8_t(hit);
    // The colour at the lookup cell's centre, nearest by squared distance weighted as the
    // eye weighs the channels (about 3:4:2 for red, green, blue).
    constexpr int half = 1 << (7 - kLookupBits);
    const int cr = (r & ~(2 * half - 1)) + half, cg = (g & ~(2 * half - 1)) + half, cb = (b & ~(2 * half - 1)) + half;
    int best = 0;
    long bestD = std::numeric_limits<long>::max();
    for (std::size_t i = 0; i < palette_.size(); ++i) {
        const int dr = cr - int(palette_[i] >> 16), dg = cg - int((palette_[i] >> 8) & 0xff),
                  db = cb - int(palette_[i] & 0xff);
        const long d = 3L * dr * dr + 4L * dg * dg + 2L * db * db;
        if (d < bestD) {
            bestD = d;
            best = int(i);
        }
    }
    hit = std::int16_t(best);
    return std::uint8_t(best);
}

void GifPalette::map(const std::uint8_t* rgb, int width, int height, int stride, std::uint8_t* out, int outStride)
{
    if (palette_.empty())
        throw std::logic_error("GifPalette::map before build");
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* p = rgb + std::ptrdiff_t(y) * stride;
        std::uint8_t* o = out + std::ptrdiff_t(y) * outStride;
        for (int x = 0; x < width; ++x, p += 3) {
            // Threshold in [-1/2, 1/2) of the amplitude: (t + 0.5) / 16 - 1/2.
            const int d = ((2 * bayer[y & 3][x & 3] + 1) * kDitherLevels) / 32 - kDitherLevels / 2;
            o[x] = nearest(std::clamp(p[0] + d, 0, 255), std::clamp(p[1] + d, 0, 255), std::clamp(p[2] + d, 0, 255));
        }
    }
}

} // namespace ab::video
