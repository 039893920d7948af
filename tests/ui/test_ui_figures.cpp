// SPDX-License-Identifier: MIT
// The report's figures: their data are the report model's with the report's constants
// (checked against steps worked by hand from Appendices A and B), each renders a picture
// with its plot in it, exports write whole PNG and SVG files or nothing, the window's
// Figures menu opens each in a dialog, and `amazeballs-cli figure` writes them headless.
#include "support/cli_runner.h"

#include "ui/figures/figure_actions.h"
#include "ui/figures/report_figures.h"
#include "ui/main_window.h"

#include <QDir>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

using ab::ui::ReportFigure;

namespace {

// Pixels of the figure's line colour (MATLAB blue, 0072bd), give or take antialiasing.
int linePixels(const QImage& image)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            n += std::abs(c.red() - 0x00) < 30 && std::abs(c.green() - 0x72) < 30 && std::abs(c.blue() - 0xbd) < 30;
        }
    return n;
}

// Distinct colours in the image: a blank or one-colour picture has few.
int colours(const QImage& image)
{
    QSet<QRgb> seen;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            seen.insert(image.pixel(x, y));
    return int(seen.size());
}

bool isSvg(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    QXmlStreamReader xml(&f);
    bool root = false;
    while (!xml.atEnd())
        if (xml.readNext() == QXmlStreamReader::StartElement && !root)
            root = xml.name() == QLatin1String("svg");
    return root && !xml.hasError();
}

} // namespace

class UiFigures : public QObject {
    Q_OBJECT

private slots:
    void figureNumbersReadBack()
    {
        for (ReportFigure f : ab::ui::allReportFigures())
            QVERIFY(ab::ui::parseReportFigure(ab::ui::figureNumber(f)) == f);
        QVERIFY(!ab::ui::parseReportFigure("2.8"));
    }

    // Appendix A: the ball falls from 2000 with grav 0.0982 per step^2, the position
    // moved by the old velocity, so p(n) = 2000 - 0.0982 n (n - 1) / 2, first <= 0 at
    // n = 203, where the floor branch sets it to 0.
    void figure25IsStage1OfTheReport()
    {
        const ab::ui::FigureData d = ab::ui::computeFigure(ReportFigure::Bounce1d);
        QCOMPARE(d.spec.model, ab::ModelKind::Report);
        QCOMPARE(d.steps, 2000LL);
        QCOMPARE(d.t.size(), std::size_t(2001)); // the start and every step
        QCOMPARE(d.p.front().y(), 2000.0);
        QVERIFY(std::abs(d.p[2].y() - (2000.0 - 0.0982)) < 1e-9);
        QVERIFY(std::abs(d.p[202].y() - (2000.0 - 0.0982 * 202 * 201 / 2)) < 1e-9);
        const auto floor = std::find_if(d.p.begin(), d.p.end(), [](const Eigen::Vector3d& p) { return p.y() <= 0.0; });
        QCOMPARE(int(floor - d.p.begin()), 203);
        QCOMPARE(d.t[203], 203.0);
        QVERIFY(std::abs(d.v[204].y() - 0.6 * 203 * 0.0982) < 1e-12); // eq 2.3, k = 0.6
    }

    // Appendix B with eqs 2.18-2.22: the first step is free flight, the new velocity
    // moving the position: v = (10, -0.0982, 15), p = (2.1, 20 - 0.000982, 2.15).
    void figures26And27AreStage2OfTheReport()
    {
        for (ReportFigure f : {ReportFigure::BoxTrajectory, ReportFigure::BoxVelocity}) {
            const ab::ui::FigureData d = ab::ui::computeFigure(f);
            QCOMPARE(d.spec.scene, ab::SceneId::Box3d);
            QCOMPARE(d.t.size(), std::size_t(6001));
            QVERIFY((d.p[0] - Eigen::Vector3d(2, 20, 2)).norm() < 1e-12);
            QVERIFY((d.v[1] - Eigen::Vector3d(10, -0.0982, 15)).norm() < 1e-12);
            QVERIFY((d.p[1] - Eigen::Vector3d(2.1, 20 - 0.000982, 2.15)).norm() < 1e-12);
            QVERIFY(std::abs(d.t[6000] - 60.0) < 1e-9);
        }
    }

    void figure31HasTheTwoHundredBallsItShows()
    {
        const ab::ui::FigureData d = ab::ui::computeFigure(ReportFigure::ManyBalls);
        QCOMPARE(d.last.size(), 200);
        QCOMPARE(d.steps, 1000LL);
        QVERIFY(d.last.p.allFinite());
        // Every centre within the box the report's walls keep them in (+-49, 2.2 r slack
        // for the push a collision gives).
        QVERIFY(d.last.p.cwiseAbs().maxCoeff() <= 49.0 + 2.2);
    }

    void everyFigureRendersItsPicture_data()
    {
        QTest::addColumn<ReportFigure>("figure");
        for (ReportFigure f : ab::ui::allReportFigures())
            QTest::newRow(ab::ui::figureNumber(f).data()) << f;
    }

    void everyFigureRendersItsPicture()
    {
        QFETCH(ReportFigure, figure);
        const QImage image = ab::ui::renderFigure(ab::ui::computeFigure(figure), QSize(900, 700));
        QCOMPARE(image.size(), QSize(900, 700));
        QVERIFY(colours(image) > 50); // text, axes, shading: not a blank page
        if (figure != ReportFigure::ManyBalls)
            QVERIFY(linePixels(image) > 300); // the plotted line is there
    }

    void exportWritesWholePngAndSvgFiles()
    {
        QTemporaryDir dir;
        const ab::ui::FigureData d = ab::ui::computeFigure(ReportFigure::Bounce1d);
        const QString png = dir.filePath("f.png"), svg = dir.filePath("f.svg");
        ab::ui::exportFigure(d, png, QSize(800, 600));
        ab::ui::exportFigure(d, svg, QSize(800, 600));
        QCOMPARE(QImage(png).size(), QSize(800, 600));
        QVERIFY(isSvg(svg));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), qsizetype(2)); // no temporary left behind
    }

    void failedExportLeavesNothingAndTheOldFileAsItWas()
    {
        QTemporaryDir dir;
        const ab::ui::FigureData d = ab::ui::computeFigure(ReportFigure::Bounce1d);
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::ui::exportFigure(d, dir.filePath("missing/f.png")));
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::ui::exportFigure(d, dir.filePath("f.jpg")));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot).size(), qsizetype(0));
    }

    void figuresMenuOpensEachFigureInADialog()
    {
        ab::ui::MainWindow w;
        auto* menu = w.menuBar()->findChild<QMenu*>("figuresMenu");
        QVERIFY(menu);
        QCOMPARE(menu->actions().size(), qsizetype(4));
        menu->actions().at(1)->trigger();
        auto* dialog = w.findChild<ab::ui::FigureDialog*>("figure-2.6");
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QCOMPARE(dialog->data().figure, ReportFigure::BoxTrajectory);
        QTemporaryDir dir;
        dialog->exportTo(dir.filePath("from-dialog.svg"));
        QVERIFY(isSvg(dir.filePath("from-dialog.svg")));
    }

    void cliWritesEachFigure()
    {
        QTemporaryDir dir;
        for (const char* n : {"2.5", "2.6", "2.7", "3.1"}) {
            const std::string path = dir.filePath(QString("fig-%1.png").arg(n)).toStdString();
            const auto r = testing::cli({"figure", n, "--out", path, "--width", "640", "--height", "480"});
            QVERIFY2(r.status == 0, r.err.c_str());
            QCOMPARE(QImage(QString::fromStdString(path)).size(), QSize(640, 480));
        }
        const std::string svg = dir.filePath("fig.svg").toStdString();
        QCOMPARE(testing::cli({"figure", "2.7", "--out", svg}).status, 0);
        QVERIFY(isSvg(QString::fromStdString(svg)));
    }

    void cliRefusesBadArgumentsWithOneLine_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("named");
        QTest::newRow("unknown figure") << QStringList{"figure", "2.8", "--out", "x.png"} << "2.8";
        QTest::newRow("no figure") << QStringList{"figure", "--out", "x.png"} << "figure number";
        QTest::newRow("no --out") << QStringList{"figure", "2.5"} << "--out";
        QTest::newRow("bad type") << QStringList{"figure", "2.5", "--out", "x.gif"} << ".png, .svg or .pdf";
        QTest::newRow("tiny width") << QStringList{"figure", "2.5", "--out", "x.png", "--width", "5"} << "--width";
        QTest::newRow("unknown option") << QStringList{"figure", "2.5", "--out", "x.png", "--dpi", "3"} << "--dpi";
    }

    void cliRefusesBadArgumentsWithOneLine()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, named);
        std::vector<std::string> a;
        for (const QString& s : args)
            a.push_back(s.toStdString());
        const auto r = testing::cli(a);
        QCOMPARE(r.status, 2);
        QVERIFY2(QString::fromStdString(r.err).contains(named), r.err.c_str());
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY(!QFile::exists("x.png"));
    }
};

QTEST_MAIN(UiFigures)
#include "test_ui_figures.moc"
