// SPDX-License-Identifier: MIT
// Animation export (ui/video/, `amazeballs-cli video`), checked by decoding what was
// written with FFmpeg's own demuxers and decoders: the container, codec, size and frame
// count (the clip's length times its frame rate) of each format; a decoded frame shows a
// ball in its colour where the simulation puts it at that frame's moment, projected with
// a camera framed as the window frames the scene, and is not blank. The same run gives
// the same frames. Cancel and Ctrl+C leave no file, and bad input is refused with one
// line, status 2 and no file. Needs OpenGL: run under xvfb-run with QT_QPA_PLATFORM=xcb.
#include "support/cli_runner.h"
#include "support/opengl_platform.h"

#include "ui/charts/scene_layout.h"
#include "ui/main_window.h"
#include "ui/video/animation_actions.h"
#include "ui/video/animation_dialog.h"
#include "ui/video/animation_export.h"
#include "ui/view/view_frame.h"

#include "core/io/atomic_file.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <filesystem>
#include <set>
#include <signal.h>

namespace fs = std::filesystem;
using ab::ui::AnimationRequest;
using ab::video::VideoFormat;

namespace {

struct Decoded {
    std::string container, codec;
    int width = 0, height = 0;
    long long frames = 0;
    QImage frame; // the frame asked for, as RGB
};

// Every frame of `path` decoded (counted), frame `keep` converted to RGB.
Decoded decode(const QString& path, long long keep)
{
    Decoded d;
    AVFormatContext* fmt = nullptr;
    if (avformat_open_input(&fmt, path.toLocal8Bit().constData(), nullptr, nullptr) < 0)
        return d;
    avformat_find_stream_info(fmt, nullptr);
    d.container = fmt->iformat->name;
    const int index = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) {
        avformat_close_input(&fmt);
        return d;
    }
    const AVCodecParameters* par = fmt->streams[index]->codecpar;
    const AVCodec* codec = avcodec_find_decoder(par->codec_id);
    d.codec = avcodec_get_name(par->codec_id);
    d.width = par->width;
    d.height = par->height;
    AVCodecContext* dec = avcodec_alloc_context3(codec);
    avcodec_parameters_to_context(dec, par);
    avcodec_open2(dec, codec, nullptr);
    AVPacket* pkt = av_packet_alloc();
    AVFrame* f = av_frame_alloc();
    const auto take = [&] {
        while (avcodec_receive_frame(dec, f) == 0) {
            if (d.frames == keep) {
                d.frame = QImage(f->width, f->height, QImage::Format_RGB888);
                SwsContext* sws = sws_getContext(f->width, f->height, AVPixelFormat(f->format), f->width, f->height,
                                                 AV_PIX_FMT_RGB24, SWS_BICUBIC, nullptr, nullptr, nullptr);
                if (f->format == AV_PIX_FMT_YUV420P) {
                    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
                    sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
                }
                std::uint8_t* dst[1] = {d.frame.bits()};
                const int dstStride[1] = {int(d.frame.bytesPerLine())};
                sws_scale(sws, f->data, f->linesize, 0, f->height, dst, dstStride);
                sws_freeContext(sws);
            }
            ++d.frames;
        }
    };
    while (av_read_frame(fmt, pkt) >= 0) {
        if (pkt->stream_index == index && avcodec_send_packet(dec, pkt) >= 0)
            take();
        av_packet_unref(pkt);
    }
    avcodec_send_packet(dec, nullptr);
    take();
    av_frame_free(&f);
    av_packet_free(&pkt);
    avcodec_free_context(&dec);
    avformat_close_input(&fmt);
    return d;
}

// Two balls over the first second of their run, at 1x: 12 frames at 12 fps.
AnimationRequest twoBalls(VideoFormat format, int width, int height)
{
    AnimationRequest r(ab::RunSpec(ab::SceneId::TwoBalls));
    r.steps = std::llround(2.0 / ab::defaultDt(ab::SceneId::TwoBalls, ab::ModelKind::Report));
    r.from = 0.0;
    r.to = 1.0;
    r.video = ab::video::VideoSettings{format, width, height, 12};
    return r;
}

// A lit ball is its own colour scaled by the light: compare hues, not exact values.
bool looksLike(const QColor& pixel, unsigned ballRgb)
{
    const QColor ball = QColor::fromRgb(ballRgb);
    if (pixel.saturationF() < 0.3f)
        return false;
    const int dh = std::abs(pixel.hsvHue() - ball.hsvHue());
    return std::min(dh, 360 - dh) < 25;
}

// The state a clip shows at run time t: the last state of the run at or before t.
ab::State stateAt(const ab::RunSpec& spec, double t)
{
    const auto sim = ab::makeSimulation(spec);
    ab::State shown = sim->start();
    const long long steps = std::llround(t / sim->dt()) + 2;
    ab::runRecorded(*sim, sim->start(), steps, 1, [&](const ab::State& s) {
        if (s.t <= t + 1e-9)
            shown = s;
    });
    return shown;
}

// Distinct colours in the image (a blank frame has one or two).
int colourCount(const QImage& image)
{
    std::set<QRgb> seen;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            seen.insert(image.pixel(x, y));
    return int(seen.size());
}

bool folderIsEmpty(const QString& dir)
{
    return fs::is_empty(fs::path(dir.toStdString()));
}

} // namespace

class VideoExport : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        if (!testing::platformHasOpenGl())
            QSKIP(testing::kNeedsOpenGl);
    }

    void aClipHoldsItsLengthTimesItsFrameRateInFrames_data()
    {
        QTest::addColumn<int>("format");
        QTest::addColumn<QString>("container");
        QTest::addColumn<QString>("codec");
        QTest::newRow("mp4") << int(VideoFormat::Mp4) << "mov,mp4,m4a,3gp,3g2,mj2"
                             << "h264";
        QTest::newRow("webm") << int(VideoFormat::WebM) << "matroska,webm"
                              << "vp9";
        QTest::newRow("gif") << int(VideoFormat::Gif) << "gif"
                             << "gif";
    }
    void aClipHoldsItsLengthTimesItsFrameRateInFrames()
    {
        QFETCH(int, format);
        QFETCH(QString, container);
        QFETCH(QString, codec);
        QTemporaryDir dir;
        const auto f = VideoFormat(format);
        const QString path = dir.filePath("clip." + QString::fromLatin1(ab::video::videoFormatKey(f).data()));
        const AnimationRequest r = twoBalls(f, 160, 96);
        const ab::ui::AnimationStats stats = ab::ui::exportAnimation(r, path.toStdString());
        QCOMPARE(stats.frames, 12LL); // 1 s of run at 1x, 12 fps
        const Decoded d = decode(path, 0);
        QCOMPARE(QString::fromStdString(d.container), container);
        QCOMPARE(QString::fromStdString(d.codec), codec);
        QCOMPARE(d.width, 160);
        QCOMPARE(d.height, 96);
        QVERIFY2(std::abs(d.frames - 12) <= 1, qPrintable(QString("%1 frames decoded").arg(d.frames)));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QFileInfo(path).fileName()});
    }

    void sixtySecondsAtThirtyFramesASecondAreExactly1800Frames()
    {
        AnimationRequest r(ab::RunSpec(ab::SceneId::TwoBalls));
        r.steps = std::llround(60.0 / ab::defaultDt(ab::SceneId::TwoBalls, ab::ModelKind::Report));
        r.video.fps = 30;
        const ab::ui::AnimationPlan plan = ab::ui::planAnimation(r);
        QCOMPARE(plan.frames, 1800LL);
        QCOMPARE(plan.timeOf(900), 30.0); // half way through the clip, half way through the run
        r.speed = 2.0;                    // twice as fast: half the frames
        QCOMPARE(ab::ui::planAnimation(r).frames, 900LL);
        AnimationRequest stage1(ab::RunSpec(ab::SceneId::Bounce1d)); // 1x plays 10 steps a second
        stage1.steps = 100;
        stage1.video.fps = 30;
        QCOMPARE(ab::ui::planAnimation(stage1).frames, 300LL);
    }

    void aDecodedFrameShowsEachBallWhereTheSimulationPutsIt_data()
    {
        QTest::addColumn<int>("format");
        QTest::newRow("mp4") << int(VideoFormat::Mp4);
        QTest::newRow("gif") << int(VideoFormat::Gif);
    }
    void aDecodedFrameShowsEachBallWhereTheSimulationPutsIt()
    {
        QFETCH(int, format);
        QTemporaryDir dir;
        const auto f = VideoFormat(format);
        const QString path = dir.filePath("clip." + QString::fromLatin1(ab::video::videoFormatKey(f).data()));
        const QSize size(480, 270);
        const AnimationRequest r = twoBalls(f, size.width(), size.height());
        ab::ui::exportAnimation(r, path.toStdString());
        const long long k = 9; // t = 0.75 s: the balls have left their start
        const Decoded d = decode(path, k);
        QVERIFY(!d.frame.isNull());
        QVERIFY2(colourCount(d.frame) > 20, "the frame is blank");

        const ab::State s = stateAt(r.spec, 0.75);
        const ab::ui::SceneLayout layout = ab::ui::layoutFor(r.spec);
        ab::ui::OrbitCamera camera;
        ab::ui::frameSceneCamera(camera, ab::ui::buildSceneGeometry(layout, "m"), layout,
                                 float(size.width()) / float(size.height()));
        const std::vector<unsigned> colours = ab::ui::ballColours(r.spec, 2);
        for (int ball = 0; ball < 2; ++ball) {
            const QVector3D centre(float(s.p(0, ball)), float(s.p(1, ball)), float(s.p(2, ball)));
            const QVector4D clip =
                camera.projection(float(size.width()) / float(size.height())) * camera.view() * QVector4D(centre, 1.0f);
            const QVector3D ndc = clip.toVector3DAffine();
            const QPoint pixel(int((ndc.x() + 1.0) * 0.5 * size.width()), int((1.0 - ndc.y()) * 0.5 * size.height()));
            QVERIFY(QRect(QPoint(0, 0), size).contains(pixel));
            const QColor seen = d.frame.pixelColor(pixel);
            QVERIFY2(looksLike(seen, colours[std::size_t(ball)]),
                     qPrintable(QString("ball %1 at (%2, %3): pixel %4, ball colour #%5")
                                    .arg(ball + 1)
                                    .arg(pixel.x())
                                    .arg(pixel.y())
                                    .arg(seen.name())
                                    .arg(colours[std::size_t(ball)], 6, 16, QChar('0'))));
        }
    }

    void theSameRunGivesTheSameFrames()
    {
        AnimationRequest r = twoBalls(VideoFormat::Mp4, 320, 180);
        r.charts = false;
        const ab::ui::AnimationPlan plan = ab::ui::planAnimation(r);
        ab::ui::AnimationFrames a(r, plan), b(r, plan);
        const QImage first = a.frame(7);
        QCOMPARE(b.frame(7), first);
        QVERIFY(a.frame(8) != first); // the balls move between frames
    }

    void theChartsGoBesideTheView()
    {
        AnimationRequest r = twoBalls(VideoFormat::Mp4, 640, 360);
        r.charts = true;
        const ab::ui::AnimationPlan plan = ab::ui::planAnimation(r);
        ab::ui::AnimationFrames frames(r, plan);
        QCOMPARE(frames.viewRect(), QRect(0, 0, 384, 360));
        const QImage f0 = frames.frame(0), f6 = frames.frame(6);
        const QImage strip0 = f0.copy(384, 0, 256, 360), strip6 = f6.copy(384, 0, 256, 360);
        QVERIFY2(colourCount(strip0) > 20, "no charts beside the view");
        QVERIFY(strip0 != strip6); // the time cursor moved
    }

    void theDialogCountsTheClipsFramesAndRefusesAnOddH264Size()
    {
        ab::ui::AnimationChoice initial;
        initial.from = 0.0;
        initial.to = 1000.0; // stage 4's 1000 frames at 60 a second: 16.7 s at 1x
        ab::ui::AnimationDialog dialog(0.0, 1000.0, 60.0, "frame", initial);
        QVERIFY2(dialog.summary().contains("500"), qPrintable(dialog.summary())); // at 30 fps
        auto* ok = dialog.findChild<QDialogButtonBox*>()->buttons().constFirst();
        for (QAbstractButton* b : dialog.findChild<QDialogButtonBox*>()->buttons())
            if (b->text().startsWith("Export"))
                ok = b;
        QVERIFY(ok->isEnabled());
        dialog.findChild<QComboBox*>("animationSize")->setCurrentIndex(2); // custom
        dialog.findChild<QSpinBox*>("animationWidth")->setValue(641);
        QVERIFY(!ok->isEnabled()); // H.264 needs even sides
        QVERIFY2(dialog.summary().contains("641"), qPrintable(dialog.summary()));
        dialog.findChild<QComboBox*>("animationFormat")->setCurrentIndex(2); // GIF takes odd sides
        QVERIFY(ok->isEnabled());
        QCOMPARE(dialog.choice().size, QSize(641, 720));
        QCOMPARE(dialog.choice().format, VideoFormat::Gif);
        dialog.findChild<QDoubleSpinBox*>("animationSpeed")->setValue(2.0);
        QVERIFY2(dialog.summary().contains("250"), qPrintable(dialog.summary())); // twice as fast
    }

    void cancellingLeavesNoFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("clip.mp4");
        const AnimationRequest r = twoBalls(VideoFormat::Mp4, 160, 96);
        QVERIFY_THROWS_EXCEPTION(
            ab::ui::AnimationCancelled,
            ab::ui::exportAnimation(r, path.toStdString(), [](long long done, long long) { return done < 5; }));
        QVERIFY(folderIsEmpty(dir.path()));
    }

    void cancelInTheWindowLeavesNoFile()
    {
        ab::ui::MainWindow w;
        w.resize(1200, 800);
        w.show();
        w.showScene(ab::SceneId::TwoBalls);
        auto* actions = w.findChild<ab::ui::AnimationActions*>();
        QVERIFY(actions);
        QTemporaryDir dir;
        const QString path = dir.filePath("window.webm");
        ab::ui::AnimationChoice choice;
        choice.from = 0.0;
        choice.to = 1.0;
        choice.size = QSize(320, 180);
        choice.fps = 24;
        choice.format = VideoFormat::WebM;
        bool cancelled = false;
        QTimer poke; // presses Cancel once the progress dialog is up
        connect(&poke, &QTimer::timeout, [&] {
            if (auto* p = w.findChild<QProgressDialog*>("animationProgress"); p && p->value() > 100 && !cancelled) {
                cancelled = true;
                p->cancel();
            }
        });
        poke.start(0);
        QVERIFY(!actions->exportTo(path, choice));
        QVERIFY(cancelled);
        QVERIFY(folderIsEmpty(dir.path()));
        // And without Cancel the window writes the whole clip.
        poke.stop();
        QVERIFY(actions->exportTo(path, choice));
        QCOMPARE(decode(path, 0).frames, 24LL);
    }

    void ctrlCLeavesNoFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("long.mp4");
        QProcess cli;
        cli.setProcessChannelMode(QProcess::SeparateChannels);
        cli.setReadChannel(QProcess::StandardError); // what waitForReadyRead waits for
        cli.start(AB_CLI_PATH, {"video", "two-balls", "--t-end", "60", "--size", "320x180", "--out", path});
        QVERIFY(cli.waitForStarted());
        // Interrupt it two seconds in, within its 1,800 frames (about 9 s here; its progress goes
        // to a terminal only, so the pipe has no percentage to wait for).
        QVERIFY(!cli.waitForFinished(2000));
        ::kill(pid_t(cli.processId()), SIGINT);
        QVERIFY(cli.waitForFinished(60000));
        const QByteArray err = cli.readAllStandardError();
        QCOMPARE(cli.exitCode(), 130);
        QVERIFY2(err.contains("interrupted; no output file was written"), err.constData());
        QVERIFY(folderIsEmpty(dir.path()));
    }

    void withoutADisplayItSaysSoOrWritesTheWholeClip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("headless.mp4");
        QProcess cli;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.remove("QT_QPA_PLATFORM"); // the command's own choice
        cli.setProcessEnvironment(env);
        cli.start(AB_CLI_PATH, {"video", "two-balls", "--t-end", "1", "--size", "160x96", "--quiet", "--out", path});
        QVERIFY(cli.waitForFinished(120000));
        const QByteArray err = cli.readAllStandardError();
        QCOMPARE(cli.exitStatus(), QProcess::NormalExit); // never a crash
        if (cli.exitCode() == 5) {                        // Qt 6.4 with Mesa: no OpenGL context without a display
            QCOMPARE(err.count('\n'), 1);
            QVERIFY2(err.contains("no OpenGL"), err.constData());
            QVERIFY(folderIsEmpty(dir.path()));
        } else {
            QCOMPARE(cli.exitCode(), 0);
            QCOMPARE(decode(path, 0).frames, 30LL);
        }
    }

    void progressShowsOnATerminalOnlyAndAScriptGetsOneLine()
    {
        // stderr is a pipe here: 144 "\r" progress updates reached a script before.
        QTemporaryDir dir;
        const QString path = dir.filePath("piped.mp4");
        QProcess cli;
        cli.start(AB_CLI_PATH, {"video", "two-balls", "--t-end", "1", "--size", "160x96", "--out", path});
        QVERIFY(cli.waitForFinished(120000));
        const QByteArray err = cli.readAllStandardError();
        QCOMPARE(cli.exitCode(), 0);
        QVERIFY2(!err.contains('\r'), err.constData());
        QCOMPARE(err.count('\n'), 1);
        QVERIFY2(err.startsWith("video: wrote "), err.constData());
    }

    void badInputIsRefusedWithOneLineAndNoFile_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("named");
        QTest::newRow("unknown format") << QStringList{"--out", "@/clip.avi"} << "--out";
        QTest::newRow("size zero") << QStringList{"--out", "@/clip.mp4", "--size", "0x720"} << "--size";
        QTest::newRow("odd for H.264") << QStringList{"--out", "@/clip.mp4", "--size", "321x180"} << "odd";
        QTest::newRow("above 4096") << QStringList{"--out", "@/clip.webm", "--size", "5000x100"} << "4096";
        QTest::newRow("not a size") << QStringList{"--out", "@/clip.gif", "--size", "big"} << "--size";
        QTest::newRow("fps 0") << QStringList{"--out", "@/clip.mp4", "--fps", "0"} << "--fps";
        QTest::newRow("fps 121") << QStringList{"--out", "@/clip.mp4", "--fps", "121"} << "--fps";
        QTest::newRow("from after the run") << QStringList{"--out", "@/clip.mp4", "--from", "30"} << "--from";
        QTest::newRow("to after the run") << QStringList{"--out", "@/clip.mp4", "--to", "30"} << "--to";
        QTest::newRow("to before from") << QStringList{"--out", "@/clip.mp4", "--from", "2", "--to", "1"} << "--to";
        QTest::newRow("speed 0") << QStringList{"--out", "@/clip.mp4", "--speed", "0"} << "--speed";
        QTest::newRow("unwritable") << QStringList{"--out", "@/missing/clip.mp4"} << "does not exist";
        QTest::newRow("no --out") << QStringList{} << "--out";
    }
    void badInputIsRefusedWithOneLineAndNoFile()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, named);
        QTemporaryDir dir;
        std::vector<std::string> argv{"video", "two-balls", "--t-end", "10"};
        for (const QString& a : args)
            argv.push_back(QString(a).replace("@", dir.path()).toStdString());
        const testing::CliResult r = testing::cli(argv);
        QCOMPARE(r.status, 2);
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY2(QString::fromStdString(r.err).contains(named), r.err.c_str());
        QVERIFY(folderIsEmpty(dir.path()));
    }
};

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    VideoExport test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_video.moc"
