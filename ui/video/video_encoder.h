// SPDX-License-Identifier: MIT
// Encodes RGB frames into MP4 (H.264, libx264), WebM (VP9, libvpx-vp9) or GIF (one palette
// computed for the clip, ui/video/gif_palette.h) with FFmpeg's libraries, into a stream:
// the caller decides where the bytes go (writeFileAtomically's temporary file), so a
// cancelled or failed encode leaves nothing behind. No Qt here.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace ab::video {

enum class VideoFormat { Mp4, WebM, Gif };

// The format a file name asks for, by its extension (.mp4, .webm, .gif; any case).
std::optional<VideoFormat> videoFormatOfPath(std::string_view path);
std::string_view videoFormatKey(VideoFormat format); // "mp4", "webm", "gif"
// The codec's name as FFmpeg reports it: "h264", "vp9", "gif".
std::string_view videoCodecName(VideoFormat format);

// Limits every clip keeps to.
inline constexpr int kMaxSide = 4096; // pixels, each side
inline constexpr int kMinFps = 1, kMaxFps = 120;

// Throws InputError naming what is wrong: a side of zero or below, above kMaxSide, or
// odd where the format stores colour at half resolution (H.264's 4:2:0).
void checkFrameSize(VideoFormat format, int width, int height);
void checkFps(int fps);
// Throws InputError when this FFmpeg build has no encoder for the format.
void checkEncoderAvailable(VideoFormat format);

struct VideoSettings {
    VideoFormat format = VideoFormat::Mp4;
    int width = 1280, height = 720;
    int fps = 30;
};

// Frames are packed RGB, 8 bits a channel (r, g, b per pixel, `stride` bytes a row), the
// top row first, exactly width x height.
class VideoEncoder {
public:
    // Opens the encoder and the container and writes the header into `out`, which must
    // be seekable (MP4 writes its index at the end). Throws InputError (settings) or
    // std::runtime_error (FFmpeg).
    VideoEncoder(const VideoSettings& settings, std::ostream& out);
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // GIF only: frames sampled over the clip to compute its palette from; give them all
    // before the first addFrame (a GIF without samples takes its palette from the first frame).
    bool wantsPaletteSamples() const;
    void addPaletteSample(const std::uint8_t* rgb, int stride);

    void addFrame(const std::uint8_t* rgb, int stride);
    // Drains the encoder and writes the container's trailer; the stream is then whole.
    void finish();
    long long framesWritten() const;

private:
    struct Impl;
    std::unique_ptr<Impl> d_;
};

} // namespace ab::video
