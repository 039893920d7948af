// SPDX-License-Identifier: MIT
#include "video_encoder.h"

#include "gif_palette.h"

#include "core/params.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cctype>
#include <cstring>
#include <ostream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ab::video {

namespace {

struct Codec {
    const char* muxer;   // FFmpeg's name of the container
    const char* encoder; // and of the encoder
};

Codec codecOf(VideoFormat format)
{
    switch (format) {
    case VideoFormat::Mp4:
        return {"mp4", "libx264"};
    case VideoFormat::WebM:
        return {"webm", "libvpx-vp9"};
    case VideoFormat::Gif:
        return {"gif", "gif"};
    }
    throw std::logic_error("unknown video format");
}

std::string ffmpegError(int code)
{
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

void check(int code, const char* what)
{
    if (code < 0)
        throw std::runtime_error(std::string("video: ") + what + ": " + ffmpegError(code));
}

// FFmpeg's output callbacks over a std::ostream (the temporary file).
int writeToStream(void* opaque, std::uint8_t* buf, int size)
{
    auto* out = static_cast<std::ostream*>(opaque);
    out->write(reinterpret_cast<const char*>(buf), size);
    return *out ? size : AVERROR(EIO);
}

std::int64_t seekStream(void* opaque, std::int64_t offset, int whence)
{
    auto* out = static_cast<std::ostream*>(opaque);
    out->flush();
    if (whence & AVSEEK_SIZE) {
        const std::streampos here = out->tellp();
        out->seekp(0, std::ios::end);
        const std::streampos end = out->tellp();
        out->seekp(here);
        return *out ? std::int64_t(end) : -1;
    }
    whence &= ~AVSEEK_FORCE;
    const std::ios::seekdir dir = whence == SEEK_CUR   ? std::ios::cur
                                  : whence == SEEK_END ? std::ios::end
                                                       : std::ios::beg;
    out->seekp(offset, dir);
    return *out ? std::int64_t(out->tellp()) : -1;
}

} // namespace

std::optional<VideoFormat> videoFormatOfPath(std::string_view path)
{
    const auto dot = path.rfind('.');
    if (dot == std::string_view::npos)
        return std::nullopt;
    std::string ext(path.substr(dot + 1));
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == "mp4")
        return VideoFormat::Mp4;
    if (ext == "webm")
        return VideoFormat::WebM;
    if (ext == "gif")
        return VideoFormat::Gif;
    return std::nullopt;
}

std::string_view videoFormatKey(VideoFormat format)
{
    switch (format) {
    case VideoFormat::Mp4:
        return "mp4";
    case VideoFormat::WebM:
        return "webm";
    case VideoFormat::Gif:
        return "gif";
    }
    return "?";
}

std::string_view videoCodecName(VideoFormat format)
{
    switch (format) {
    case VideoFormat::Mp4:
        return "h264";
    case VideoFormat::WebM:
        return "vp9";
    case VideoFormat::Gif:
        return "gif";
    }
    return "?";
}

void checkFrameSize(VideoFormat format, int width, int height)
{
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0)
        throw InputError("--size: " + size + " has a side of zero");
    if (width > kMaxSide || height > kMaxSide)
        throw InputError("--size: " + size + " is larger than " + std::to_string(kMaxSide) + " pixels a side");
    if (format == VideoFormat::Mp4 && (width % 2 != 0 || height % 2 != 0))
        throw InputError("--size: " + size + " has an odd side; H.264 (MP4) needs both sides even");
}

void checkFps(int fps)
{
    if (fps < kMinFps || fps > kMaxFps)
        throw InputError("--fps: " + std::to_string(fps) + " is outside [" + std::to_string(kMinFps) + ", " +
                         std::to_string(kMaxFps) + "]");
}

void checkEncoderAvailable(VideoFormat format)
{
    const Codec c = codecOf(format);
    if (!avcodec_find_encoder_by_name(c.encoder) || !av_guess_format(c.muxer, nullptr, nullptr))
        throw InputError(std::string(videoFormatKey(format)) + ": this FFmpeg has no " + c.encoder + " encoder or " +
                         c.muxer + " container; choose another format");
}

struct VideoEncoder::Impl {
    VideoSettings s;
    std::ostream* out = nullptr;
    AVFormatContext* fmt = nullptr;
    AVIOContext* io = nullptr;
    AVCodecContext* enc = nullptr;
    AVStream* stream = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    SwsContext* sws = nullptr;
    GifPalette palette;
    bool paletteBuilt = false;
    long long frames = 0;
    bool finished = false;

    ~Impl()
    {
        sws_freeContext(sws);
        av_packet_free(&packet);
        av_frame_free(&frame);
        avcodec_free_context(&enc);
        if (fmt)
            avformat_free_context(fmt);
        if (io) {
            av_freep(&io->buffer);
            avio_context_free(&io);
        }
    }

    void open();
    void openCodec(const AVCodec* codec);
    void drain(AVFrame* f);
    void convert(const std::uint8_t* rgb, int stride);
};

void VideoEncoder::Impl::openCodec(const AVCodec* codec)
{
    enc = avcodec_alloc_context3(codec);
    if (!enc)
        throw std::bad_alloc();
    enc->width = s.width;
    enc->height = s.height;
    enc->time_base = AVRational{1, s.fps};
    enc->framerate = AVRational{s.fps, 1};
    enc->sample_aspect_ratio = AVRational{1, 1};
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    if (s.format == VideoFormat::Gif) {
        enc->pix_fmt = AV_PIX_FMT_PAL8;
    } else {
        enc->pix_fmt = AV_PIX_FMT_YUV420P;
        enc->gop_size = 2 * s.fps; // a key frame every 2 s: seeking in a slide stays quick
        // HD video is BT.709; the frames are converted with the same matrix (convert()).
        enc->colorspace = AVCOL_SPC_BT709;
        enc->color_primaries = AVCOL_PRI_BT709;
        enc->color_trc = AVCOL_TRC_BT709;
        enc->color_range = AVCOL_RANGE_MPEG;
        enc->thread_count = int(std::min(cores, 16u));
    }
    AVDictionary* opts = nullptr;
    if (s.format == VideoFormat::Mp4) {
        // Constant quality; "animation" suits flat colour and sharp edges. High profile,
        // 4:2:0: what PowerPoint, Keynote, browsers and phones play.
        av_dict_set(&opts, "preset", "fast", 0);
        av_dict_set(&opts, "tune", "animation", 0);
        av_dict_set(&opts, "crf", "20", 0);
        av_dict_set(&opts, "profile", "high", 0);
    } else if (s.format == VideoFormat::WebM) {
        av_dict_set(&opts, "crf", "32", 0);
        av_dict_set(&opts, "b", "0", 0); // constant quality, no bit-rate target
        av_dict_set(&opts, "deadline", "good", 0);
        av_dict_set(&opts, "cpu-used", "5", 0);
        av_dict_set(&opts, "row-mt", "1", 0);
    }
    if (fmt->oformat->flags & AVFMT_GLOBALHEADER)
        enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    const int opened = avcodec_open2(enc, codec, &opts);
    av_dict_free(&opts);
    check(opened, "opening the encoder");
}

void VideoEncoder::Impl::open()
{
    av_log_set_level(AV_LOG_ERROR); // the encoders' own reports are not the program's
    const Codec c = codecOf(s.format);
    const AVCodec* codec = avcodec_find_encoder_by_name(c.encoder);
    if (!codec)
        checkEncoderAvailable(s.format); // throws the one-line message
    check(avformat_alloc_output_context2(&fmt, nullptr, c.muxer, nullptr), "creating the container");
    constexpr int bufferSize = 1 << 16;
    auto* buffer = static_cast<std::uint8_t*>(av_malloc(bufferSize));
    io = avio_alloc_context(buffer, bufferSize, 1, out, nullptr, writeToStream, seekStream);
    if (!io) {
        av_free(buffer);
        throw std::bad_alloc();
    }
    fmt->pb = io;
    fmt->flags |= AVFMT_FLAG_CUSTOM_IO;
    openCodec(codec);
    stream = avformat_new_stream(fmt, nullptr);
    if (!stream)
        throw std::bad_alloc();
    stream->time_base = enc->time_base;
    stream->avg_frame_rate = enc->framerate;
    check(avcodec_parameters_from_context(stream->codecpar, enc), "describing the stream");
    check(avformat_write_header(fmt, nullptr), "writing the header");

    frame = av_frame_alloc();
    packet = av_packet_alloc();
    if (!frame || !packet)
        throw std::bad_alloc();
    frame->format = enc->pix_fmt;
    frame->width = s.width;
    frame->height = s.height;
    check(av_frame_get_buffer(frame, 0), "allocating a frame");
    if (s.format != VideoFormat::Gif) {
        sws = sws_getContext(s.width, s.height, AV_PIX_FMT_RGB24, s.width, s.height, AV_PIX_FMT_YUV420P, SWS_BICUBIC,
                             nullptr, nullptr, nullptr);
        if (!sws)
            throw std::runtime_error("video: no colour conversion from RGB to YUV 4:2:0");
        // Full-range RGB in, limited-range BT.709 YUV out, as the stream says.
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    }
}

void VideoEncoder::Impl::drain(AVFrame* f)
{
    check(avcodec_send_frame(enc, f), "encoding a frame");
    while (true) {
        const int got = avcodec_receive_packet(enc, packet);
        if (got == AVERROR(EAGAIN) || got == AVERROR_EOF)
            return;
        check(got, "encoding a frame");
        if (packet->duration == 0)
            packet->duration = 1; // one frame, in the encoder's 1/fps
        av_packet_rescale_ts(packet, enc->time_base, stream->time_base);
        packet->stream_index = stream->index;
        check(av_interleaved_write_frame(fmt, packet), "writing a frame");
    }
}

void VideoEncoder::Impl::convert(const std::uint8_t* rgb, int stride)
{
    check(av_frame_make_writable(frame), "reusing a frame");
    if (s.format != VideoFormat::Gif) {
        const std::uint8_t* src[1] = {rgb};
        const int srcStride[1] = {stride};
        sws_scale(sws, src, srcStride, 0, s.height, frame->data, frame->linesize);
        return;
    }
    if (!paletteBuilt) {
        if (!palette.hasSamples())
            palette.addSample(rgb, s.width, s.height, stride);
        // 255 colours: index 255 stays transparent, for the GIF encoder's frame differencing.
        palette.build(255);
        paletteBuilt = true;
    }
    palette.map(rgb, s.width, s.height, stride, frame->data[0], frame->linesize[0]);
    auto* argb = reinterpret_cast<std::uint32_t*>(frame->data[1]);
    std::fill(argb, argb + 256, 0u); // unused entries and index 255: transparent
    const auto& colours = palette.colours();
    for (std::size_t i = 0; i < colours.size(); ++i)
        argb[i] = 0xff000000u | colours[i];
}

VideoEncoder::VideoEncoder(const VideoSettings& settings, std::ostream& out) : d_(std::make_unique<Impl>())
{
    checkFrameSize(settings.format, settings.width, settings.height);
    checkFps(settings.fps);
    d_->s = settings;
    d_->out = &out;
    d_->open();
}

VideoEncoder::~VideoEncoder() = default;

bool VideoEncoder::wantsPaletteSamples() const
{
    return d_->s.format == VideoFormat::Gif && !d_->paletteBuilt;
}

void VideoEncoder::addPaletteSample(const std::uint8_t* rgb, int stride)
{
    if (!wantsPaletteSamples())
        throw std::logic_error("VideoEncoder: palette sample after the first frame, or not a GIF");
    d_->palette.addSample(rgb, d_->s.width, d_->s.height, stride);
}

void VideoEncoder::addFrame(const std::uint8_t* rgb, int stride)
{
    if (d_->finished)
        throw std::logic_error("VideoEncoder: frame after finish()");
    d_->convert(rgb, stride);
    d_->frame->pts = d_->frames;
    d_->drain(d_->frame);
    ++d_->frames;
}

void VideoEncoder::finish()
{
    if (d_->finished)
        return;
    d_->drain(nullptr);
    check(av_write_trailer(d_->fmt), "writing the trailer");
    avio_flush(d_->io);
    d_->finished = true;
    d_->out->flush();
}

long long VideoEncoder::framesWritten() const
{
    return d_->frames;
}

} // namespace ab::video
