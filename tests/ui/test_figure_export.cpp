// SPDX-License-Identifier: MIT
// Figures and data for a lab report, from `amazeballs-cli chart`, `figure`, `run` and the
// shared chart recipe: the size presets give the physical size (SVG's width attribute,
// the PDF's page as pdfinfo reads it) and the PNG's pixels at its dpi; a PDF renders
// with pdftoppm; no cursor unless asked; the legend draws each series' own pen; the
// caption comes only with --caption; the chart-data CSV holds the closed form, the
// comparison and the settings; the difference chart is the run minus the comparison;
// bad sizes, dpis and extensions are refused with one line, status 2 and no file.
#include "support/cli_runner.h"
#include "support/sim_helpers.h"

#include "core/diagnostics/conservation.h"
#include "ui/charts/chart_recipe.h"
#include "ui/charts/headless_app.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QLineSeries>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

using testing::cli;
using Result = testing::CliResult;

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The svg element's width attribute in millimetres (QSvgGenerator writes "85.0mm").
double svgWidthMm(const QString& path)
{
    const QRegularExpression width(R"re(<svg width="([0-9.]+)mm")re");
    const auto m = width.match(QString::fromUtf8(readAll(path)));
    return m.hasMatch() ? m.captured(1).toDouble() : -1.0;
}

// pdfinfo's "Page size: W x H pts", in millimetres; {-1, -1} when it fails.
QSizeF pdfPageMm(const QString& path)
{
    QProcess p;
    p.start("pdfinfo", {path});
    if (!p.waitForFinished(30000) || p.exitCode() != 0)
        return QSizeF(-1, -1);
    const QRegularExpression size(R"(Page size:\s+([0-9.]+) x ([0-9.]+) pts)");
    const auto m = size.match(QString::fromUtf8(p.readAllStandardOutput()));
    if (!m.hasMatch())
        return QSizeF(-1, -1);
    return QSizeF(m.captured(1).toDouble() * 25.4 / 72.0, m.captured(2).toDouble() * 25.4 / 72.0);
}

std::vector<std::string> chartArgs(const QString& out, std::initializer_list<std::string> more)
{
    std::vector<std::string> a{"chart", "box3d", "--chart", "velocity", "--steps", "1500", "--out", out.toStdString()};
    a.insert(a.end(), more);
    return a;
}

ab::ui::MotionTrack trackOf(const ab::RunSpec& spec, long long steps)
{
    const auto sim = ab::makeSimulation(spec);
    const ab::ConservationMeter meter(*sim);
    ab::ui::MotionTrack track;
    long long i = 0;
    for (const ab::State& s : testing::record(spec, steps))
        track.add(i++, s.t, s.p.col(0), s.v.col(0), meter.measure(s));
    return track;
}

} // namespace

class FigureExport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { ab::ui::ensureGuiApplication(); }

    void svgAndPdfCarryThePresetsPhysicalWidth_data()
    {
        QTest::addColumn<QString>("size");
        QTest::addColumn<double>("widthMm");
        QTest::addColumn<double>("heightMm");
        QTest::newRow("report-column") << "report-column" << 85.0 << 64.0;
        QTest::newRow("report-full") << "report-full" << 170.0 << 105.0;
        QTest::newRow("slide") << "slide" << 1920 / 144.0 * 25.4 << 1080 / 144.0 * 25.4; // 13.33 x 7.5 in
        QTest::newRow("custom mm") << "120x80mm" << 120.0 << 80.0;
    }
    void svgAndPdfCarryThePresetsPhysicalWidth()
    {
        QFETCH(QString, size);
        QFETCH(double, widthMm);
        QFETCH(double, heightMm);
        QTemporaryDir dir;
        const QString svg = dir.filePath("v.svg"), pdf = dir.filePath("v.pdf");
        QCOMPARE(cli(chartArgs(svg, {"--size", size.toStdString()})).status, 0);
        QCOMPARE(cli(chartArgs(pdf, {"--size", size.toStdString()})).status, 0);
        QVERIFY2(std::abs(svgWidthMm(svg) - widthMm) < 0.5, qPrintable(QString::number(svgWidthMm(svg))));
        const QSizeF page = pdfPageMm(pdf);
        QVERIFY2(page.width() > 0, "pdfinfo (poppler-utils, scripts/setup.sh) did not read the PDF");
        QVERIFY2(std::abs(page.width() - widthMm) < 0.5, qPrintable(QString::number(page.width())));
        QVERIFY2(std::abs(page.height() - heightMm) < 0.5, qPrintable(QString::number(page.height())));
    }

    void aPdfRendersWithPdftoppm()
    {
        QTemporaryDir dir;
        const QString pdf = dir.filePath("v.pdf");
        QCOMPARE(cli(chartArgs(pdf, {"--size", "report-column", "--caption"})).status, 0);
        QProcess p;
        p.start("pdftoppm", {"-png", "-r", "150", "-singlefile", pdf, dir.filePath("page")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const QImage page(dir.filePath("page.png"));
        // 85 x 64 mm at 150 dpi: 502 x 378 pixels, within a pixel of rounding.
        QVERIFY(std::abs(page.width() - 502) <= 1 && std::abs(page.height() - 378) <= 1);
        int ink = 0; // the lines and text: pixels far from white
        for (int y = 0; y < page.height(); ++y)
            for (int x = 0; x < page.width(); ++x)
                ink += qGray(page.pixel(x, y)) < 128;
        QVERIFY2(ink > 2000, qPrintable(QString::number(ink)));
    }

    void aPngHasThePresetsPixelsAtItsDpi()
    {
        QTemporaryDir dir;
        const QString column = dir.filePath("c.png"), slide = dir.filePath("s.png"), fine = dir.filePath("f.png");
        QCOMPARE(cli(chartArgs(column, {"--size", "report-column"})).status, 0);
        QCOMPARE(cli(chartArgs(slide, {"--size", "slide"})).status, 0);
        QCOMPARE(cli(chartArgs(fine, {"--size", "report-column", "--dpi", "600"})).status, 0);
        const QImage c(column), s(slide), f(fine);
        QCOMPARE(c.size(), QSize(1004, 756)); // 85 x 64 mm at 300 dpi: 85 / 25.4 * 300 = 1003.9
        QCOMPARE(c.dotsPerMeterX(), 11811);   // 300 dpi
        QCOMPARE(s.size(), QSize(1920, 1080));
        QCOMPARE(f.size(), QSize(2008, 1512));
    }

    void anExportHasNoCursorUnlessAskedFor()
    {
        const ab::RunSpec spec = testing::spec(ab::SceneId::Box3d, {});
        const ab::ui::MotionTrack track = trackOf(spec, 300);
        ab::ui::ChartRecipe recipe;
        recipe.kind = ab::ui::ChartKind::Velocity;
        recipe.scene = &ab::sceneInfo(ab::SceneId::Box3d);
        recipe.tEnd = 3.0;
        recipe.run = &track;
        QTemporaryDir dir;
        const ab::ui::FigureOptions options;
        ab::ui::exportChartFigure(recipe, dir.filePath("plain.svg"), options);
        recipe.cursor = 1.5;
        ab::ui::exportChartFigure(recipe, dir.filePath("cursor.svg"), options);
        // The cursor is the one line drawn in its grey, rgb(96, 96, 102).
        QVERIFY(!readAll(dir.filePath("plain.svg")).contains("#606066"));
        QVERIFY(readAll(dir.filePath("cursor.svg")).contains("#606066"));
        const auto chart = ab::ui::buildFigureChart(recipe, options);
        QCOMPARE(chart->cursorLine()->points().front().x(), 1.5);
    }

    void legendEntriesDrawTheirSeriesPens()
    {
        const ab::RunSpec spec = testing::spec(ab::SceneId::Box3d, {});
        const ab::ui::MotionTrack track = trackOf(spec, 200);
        const ab::ui::MotionTrack other =
            trackOf(ab::variantOf(spec, {ab::ModelKind::Physical, ab::Integrator::SymplecticEuler,
                                         ab::ImpactMode::Located, std::nullopt}),
                    200);
        ab::ui::ChartRecipe recipe;
        recipe.kind = ab::ui::ChartKind::Velocity;
        recipe.scene = &ab::sceneInfo(ab::SceneId::Box3d);
        recipe.tEnd = 2.0;
        recipe.run = &track;
        recipe.runName = "report";
        recipe.comparison = &other;
        recipe.comparisonName = "physical symplectic-euler";
        recipe.closedForm = ab::ui::ReferenceMotion{"closed form", [](double) { return std::nullopt; }};
        const auto chart = ab::ui::buildFigureChart(recipe, {});
        const auto& entries = chart->legendEntries();
        // "report:", vx, vy, vz, the closed form, the comparison.
        QCOMPARE(int(entries.size()), 6);
        QCOMPARE(entries[0].pen.style(), Qt::NoPen);
        for (int a = 0; a < 3; ++a) {
            const QPen series = chart->line(a)->pen();
            QCOMPARE(entries[std::size_t(1 + a)].pen.style(), series.style());
            QCOMPARE(entries[std::size_t(1 + a)].pen.color(), series.color());
            QCOMPARE(entries[std::size_t(1 + a)].pen.widthF(), series.widthF());
            QCOMPARE(entries[std::size_t(1 + a)].text, QString("v") + "xyz"[a]);
        }
        // The three axes' lines differ in style as well as colour: told apart in greyscale.
        QVERIFY(chart->line(0)->pen().style() != chart->line(1)->pen().style());
        QVERIFY(chart->line(1)->pen().style() != chart->line(2)->pen().style());
        QCOMPARE(entries[4].pen.style(), chart->referenceLine(0)->pen().style());
        QCOMPARE(entries[4].pen.style(), Qt::DashLine);
        QCOMPARE(entries[5].pen.style(), chart->comparisonLine(0)->pen().style());
        QCOMPARE(entries[5].text, QString("physical symplectic-euler"));
        // The two runs differ in colour and style, in the legend and on the chart.
        for (int a = 0; a < 3; ++a) {
            QVERIFY(entries[5].pen.color() != entries[std::size_t(1 + a)].pen.color());
            QVERIFY(entries[5].pen.style() != entries[std::size_t(1 + a)].pen.style());
            QVERIFY(chart->comparisonLine(a)->pen().color() != chart->line(a)->pen().color());
        }
    }

    void aOneAxisLegendNamesEachRunInItsOwnPen()
    {
        const ab::RunSpec spec = testing::spec(ab::SceneId::Bounce1d, {});
        const ab::ui::MotionTrack track = trackOf(spec, 100);
        const ab::ui::MotionTrack other =
            trackOf(ab::variantOf(spec, {ab::ModelKind::Physical, ab::Integrator::SymplecticEuler,
                                         ab::ImpactMode::Located, std::nullopt}),
                    100);
        ab::ui::ChartRecipe recipe;
        recipe.kind = ab::ui::ChartKind::Position;
        recipe.scene = &ab::sceneInfo(ab::SceneId::Bounce1d);
        recipe.tEnd = 100.0;
        recipe.run = &track;
        recipe.runName = "report";
        recipe.comparison = &other;
        recipe.comparisonName = "physical symplectic-euler";
        const auto chart = ab::ui::buildFigureChart(recipe, {});
        const auto& entries = chart->legendEntries();
        QCOMPARE(int(entries.size()), 2);
        QCOMPARE(entries[0].text, QString("y (report)"));
        QCOMPARE(entries[0].pen, chart->line(1)->pen());
        QCOMPARE(entries[1].text, QString("y (physical symplectic-euler)"));
        QCOMPARE(entries[1].pen, chart->comparisonLine(1)->pen());
        QVERIFY(entries[0].pen.color() != entries[1].pen.color());
        QVERIFY(entries[0].pen.style() != entries[1].pen.style());
    }

    void theCaptionComesOnlyWithCaption()
    {
        QTemporaryDir dir;
        const QString with = dir.filePath("with.svg"), without = dir.filePath("without.svg");
        QCOMPARE(cli(chartArgs(with, {"--caption", "--set", "k=0.8"})).status, 0);
        QCOMPARE(cli(chartArgs(without, {"--set", "k=0.8"})).status, 0);
        const QByteArray a = readAll(with), b = readAll(without);
        QVERIFY(a.contains("Stage 2 (box3d)"));
        QVERIFY(a.contains("k = 0.8 (report: 0.9)"));
        QVERIFY(a.contains("dt = 0.01 s"));
        QVERIFY(!b.contains("Stage 2 (box3d)"));
        QVERIFY(!b.contains("report: 0.9"));
    }

    void theStreetsConstantsAreNamedItsDefaultsNotTheReports()
    {
        // The report never reached the street: its constants are the program's defaults, and
        // the street's step of 1/60 s reads as a reader writes it.
        QTemporaryDir dir;
        const QString svg = dir.filePath("street.svg"), csv = dir.filePath("street.csv");
        QCOMPARE(cli({"chart", "street", "--chart", "energy", "--steps", "3", "--set", "n=40", "--caption", "--out",
                      svg.toStdString(), "--data", csv.toStdString()})
                     .status,
                 0);
        const QByteArray caption = readAll(svg), data = readAll(csv);
        QVERIFY(caption.simplified().contains("n = 40") && caption.contains("(default: 10000)")); // wrapped between
        QVERIFY(caption.contains("dt = 1/60 s"));
        QVERIFY(caption.contains("impacts located inside the step")); // the window's Impacts words
        QVERIFY(!caption.contains("report:"));
        QVERIFY(data.contains("# constant n = 40 (the default: 10000)\n"));
        QVERIFY(data.contains("# constant slope = 17 deg (the default value)\n"));
        QVERIFY(!data.contains("the report's"));
    }

    void theChartDataCsvHasTheClosedFormTheComparisonAndTheSettings()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath("v.csv");
        const Result r = cli(chartArgs(dir.filePath("v.png"),
                                       {"--compare", "physical:rk4", "--data", csv.toStdString(), "--set", "k=0.8"}));
        QCOMPARE(r.status, 0);
        QStringList lines = QString::fromUtf8(readAll(csv)).split('\n', Qt::SkipEmptyParts);
        QVERIFY(lines.front().startsWith("# Amazeballs "));
        const QStringList comments = lines.filter(QRegularExpression("^# "));
        for (const char* line : {"# scene: box3d", "# dt: 0.01 s", "# constant k = 0.8 (the report's: 0.9)",
                                 "# constant g = 9.82 m/s^2 (the report's value)", "# ball: 1 of 1",
                                 "# comparison (compare_ columns): model physical, integrator rk4"})
            QVERIFY2(!comments.filter(QString::fromLatin1(line)).isEmpty(), line);
        lines.erase(lines.begin(), lines.begin() + comments.size());
        const QStringList header = lines.front().split(',');
        for (const char* column :
             {"t [s]", "vx [m/s]", "vy_closed_form [m/s]", "y_closed_form [m]", "compare_t [s]", "compare_vy [m/s]"})
            QVERIFY2(header.contains(column), column);
        QCOMPARE(lines.size(), 1 + 1501); // the header and every state of 1500 steps
        // The first row: the start, in every family (Appendix B: p0 = (2, 20, 2), v0 = (10, 0, 15)).
        const QStringList first = lines[1].split(',');
        QCOMPARE(first[header.indexOf("ball")], QString("1"));
        QCOMPARE(first[header.indexOf("vz [m/s]")].toDouble(), 15.0);
        QCOMPARE(first[header.indexOf("vz_closed_form [m/s]")].toDouble(), 15.0);
        QCOMPARE(first[header.indexOf("compare_vz [m/s]")].toDouble(), 15.0);
        // The report's first step, vy = -g dt = -0.0982, in shortest round-trip form.
        QCOMPARE(lines[2].split(',')[header.indexOf("vy [m/s]")], QString("-0.09820000000000001"));
        // The impacts column counts the report's contacts (its bounce counter, Appendix B); it
        // read 0 throughout. Falling from y0 = 20 by the semi-implicit step, y_n = y0 - g dt^2
        // n (n + 1) / 2 first reaches the floor at n (n + 1) >= 2 y0 / (g dt^2) = 40733.2, so n
        // = 202 (t = 2.02 s); the step from there finds the contact: 1 from t = 2.03 s on.
        const int impacts = header.indexOf("impacts [1]");
        QVERIFY(impacts > 0);
        int firstContact = -1;
        for (int row = 1; row < lines.size() && firstContact < 0; ++row)
            if (lines[row].split(',')[impacts] != "0")
                firstContact = row;
        QVERIFY(firstContact > 0);
        const QStringList contact = lines[firstContact].split(',');
        QCOMPARE(contact[impacts], QString("1"));
        QVERIFY2(std::abs(contact[0].toDouble() - 2.03) < 1e-9, qPrintable(contact[0]));
    }

    void theDifferenceChartIsTheRunMinusTheComparisonAtSampleTimes()
    {
        // The report's box3d and the physical model's, recorded; the chart's points checked
        // against the two recordings sample by sample (both share dt = 0.01 s).
        const ab::RunSpec spec = testing::spec(ab::SceneId::Box3d, {});
        const ab::ui::MotionTrack run = trackOf(spec, 400);
        const ab::ui::MotionTrack other = trackOf(
            ab::variantOf(spec, {ab::ModelKind::Physical, ab::Integrator::Rk4, ab::ImpactMode::Located, std::nullopt}),
            400);
        ab::ui::MotionChart chart(ab::ui::ChartKind::Difference);
        chart.setComparison("report", "physical rk4");
        chart.configure(ab::sceneInfo(ab::SceneId::Box3d), 0);
        chart.setTimeSpan(4.0);
        chart.showTrack(run, 1000); // up to 4000 samples: every one of the 401
        chart.showComparisonTrack(other, 1000);
        for (int a = 0; a < 3; ++a) {
            const QList<QPointF> points = chart.line(a)->points();
            QCOMPARE(points.size(), 401);
            for (int i : {0, 1, 57, 200, 399, 400}) {
                QCOMPARE(points[i].x(), run.t()[std::size_t(i)]);
                QCOMPARE(points[i].y(), run.p(a)[std::size_t(i)] - other.p(a)[std::size_t(i)]);
            }
        }
        // By hand at step 1: the report moves y by v dt - g dt^2 = -0.000982 m (its
        // semi-implicit step, 20 -> 19.999018); RK4 by -g dt^2 / 2 = -0.000491 m.
        QVERIFY(std::abs(chart.line(1)->points()[1].y() - (-0.000491)) < 1e-12);
        QVERIFY(std::abs(chart.line(0)->points()[1].y()) < 1e-12); // x moves 10 dt in both
    }

    void theDifferenceChartInterpolatesAComparisonOfAnotherStep()
    {
        ab::ConservationSample scene;
        ab::ui::MotionTrack run, other;
        for (int i = 0; i <= 4; ++i)
            run.add(i, 0.5 * i, Eigen::Vector3d(0, 1.0 * i, 0), Eigen::Vector3d::Zero(), scene); // y = 2 t
        for (int i = 0; i <= 2; ++i)
            other.add(i, 1.0 * i, Eigen::Vector3d(0, 3.0 * i, 0), Eigen::Vector3d::Zero(), scene); // y = 3 t
        ab::ui::MotionChart chart(ab::ui::ChartKind::Difference);
        chart.setComparison("a", "b");
        chart.configure(ab::sceneInfo(ab::SceneId::Bounce1d), 0);
        chart.showTrack(run, 100);
        chart.showComparisonTrack(other, 100);
        const QList<QPointF> points = chart.line(1)->points();
        QCOMPARE(points.size(), 5);
        for (int i = 0; i <= 4; ++i) // 2 t - 3 t = -t, the comparison linear between its samples
            QCOMPARE(points[i].y() + 1.0, -0.5 * i + 1.0);
    }

    void badSizesDpisAndTypesAreRefused_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("ext");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("size name") << QStringList{"--size", "a4"} << "png"
                                   << "--size: 'a4' is not a size";
        QTest::newRow("zero") << QStringList{"--size", "0x600"} << "png"
                              << "--size: '0x600' is empty";
        QTest::newRow("too few px") << QStringList{"--size", "1x1"} << "png"
                                    << "--size: 1x1 at 144 dpi (0.2x0.2mm) is too small for a chart, its text at 8 pt "
                                       "(at least 70x50mm, 397x283 px at 144 dpi)";
        QTest::newRow("too few mm") << QStringList{"--size", "60x45mm"} << "pdf"
                                    << "--size: 60x45mm is too small for a chart";
        QTest::newRow("too dense") << QStringList{"--size", "1004x756", "--dpi", "600"} << "png"
                                   << "--size: 1004x756 at 600 dpi (43x32mm) is too small";
        QTest::newRow("too few px wide") << QStringList{"--width", "300", "--height", "300"} << "png"
                                         << "--width/--height: 300x300 at 144 dpi (53x53mm) is too small";
        QTest::newRow("too many px") << QStringList{"--size", "20001x600"} << "png"
                                     << "larger than 20000 px";
        QTest::newRow("too many mm") << QStringList{"--size", "2001x100mm"} << "pdf"
                                     << "larger than 2 m";
        QTest::newRow("dpi low") << QStringList{"--dpi", "49"} << "png"
                                 << "--dpi: 49 is outside [50, 2400]";
        QTest::newRow("dpi high") << QStringList{"--dpi", "2401"} << "png"
                                  << "--dpi: 2401 is outside [50, 2400]";
        QTest::newRow("png too large") << QStringList{"--size", "1000x100mm", "--dpi", "600"} << "png"
                                       << "more than 20000 px";
        QTest::newRow("extension") << QStringList{} << "jpg"
                                   << "unknown image type 'jpg' (use .png, .svg or .pdf)";
        QTest::newRow("compare") << QStringList{"--compare", "exact"} << "png"
                                 << "--compare: 'exact': unknown model";
        QTest::newRow("data type") << QStringList{"--data", "x.txt"} << "png"
                                   << "--data: x.txt must end in .csv";
        QTest::newRow("difference alone") << QStringList{"--init", "INIT", "--chart", "difference"} << "png"
                                          << "the difference chart needs --compare";
    }
    void badSizesDpisAndTypesAreRefused()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, ext);
        QFETCH(QString, mentions);
        QTemporaryDir dir;
        QTemporaryDir initDir; // a start state for the run without a closed form
        const QString init = initDir.filePath("init.csv");
        {
            QFile f(init);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("t,ball,x,y,z,vx,vy,vz\n0,0,2,20,2,10,0,15\n");
        }
        std::vector<std::string> a{"chart", "box3d", "--steps", "10"};
        bool chart = false;
        for (const QString& s : args) {
            chart = chart || s == "--chart";
            a.push_back(s == "INIT" ? init.toStdString() : s.toStdString());
        }
        if (!chart)
            a.insert(a.end(), {"--chart", "velocity"});
        a.insert(a.end(), {"--out", dir.filePath("out." + ext).toStdString()});
        const Result r = cli(a);
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find(mentions.toStdString()) != std::string::npos, r.err.c_str());
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }

    void theReportsFigureTakesTheSizesAndPdf()
    {
        QTemporaryDir dir;
        const QString pdf = dir.filePath("f.pdf"), png = dir.filePath("f.png");
        QCOMPARE(cli({"figure", "2.7", "--size", "report-full", "--out", pdf.toStdString()}).status, 0);
        const QSizeF page = pdfPageMm(pdf);
        QVERIFY(std::abs(page.width() - 170.0) < 0.5 && std::abs(page.height() - 105.0) < 0.5);
        QCOMPARE(cli({"figure", "2.5", "--size", "report-column", "--dpi", "150", "--out", png.toStdString()}).status,
                 0);
        QCOMPARE(QImage(png).size(), QSize(502, 378));
        const Result bad = cli({"figure", "2.5", "--size", "huge", "--out", dir.filePath("g.pdf").toStdString()});
        QCOMPARE(bad.status, 2);
        QVERIFY(!QFile::exists(dir.filePath("g.pdf")));
    }

    void runWritesShortestNumbersAndCommentsOnlyWithMeta()
    {
        const Result plain = cli({"run", "box3d", "--steps", "1"});
        QCOMPARE(plain.status, 0);
        QVERIFY(plain.out.rfind("t,ball,x,y,z,vx,vy,vz\n", 0) == 0); // the contract's header first
        // Step 1 of the report's box3d: vy = -g dt = -9.82 * 0.01, shortest form.
        QVERIFY2(plain.out.find("\n0.01,0,2.1,19.999018,2.15,10,-0.09820000000000001,15\n") != std::string::npos,
                 plain.out.c_str());
        const Result meta = cli({"run", "box3d", "--steps", "1", "--meta", "--set", "k=0.8"});
        QCOMPARE(meta.status, 0);
        QVERIFY(meta.out.rfind("# Amazeballs ", 0) == 0);
        QVERIFY(meta.out.find("# constant k = 0.8 (the report's: 0.9)\n") != std::string::npos);
        QVERIFY(meta.out.find("\nt,ball,x,y,z,vx,vy,vz\n") != std::string::npos);
        // The street's chart data keeps the energy's sums and says that its chart draws them per
        // ball; a trajectory, which has no energy columns, says nothing of them.
        const Result street = cli({"run", "street", "--set", "n=20", "--steps", "2", "--meta"});
        QCOMPARE(street.status, 0);
        QVERIFY2(street.out.find("energy") == std::string::npos, street.out.substr(0, 2000).c_str());
        QTemporaryDir dir;
        const std::string csv = dir.filePath("street.csv").toStdString();
        QCOMPARE(cli({"chart", "street", "--set", "n=20", "--steps", "2", "--chart", "energy", "--out",
                      dir.filePath("e.png").toStdString(), "--data", csv})
                     .status,
                 0);
        QFile data(QString::fromStdString(csv));
        QVERIFY(data.open(QIODevice::ReadOnly));
        QVERIFY(data.readAll().contains("# energy columns: sums over the 20 balls; the energy chart draws each divided "
                                        "by 20, the mean per ball\n"));
    }
};

QTEST_MAIN(FigureExport)
#include "test_figure_export.moc"
