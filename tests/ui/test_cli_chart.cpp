// SPDX-License-Identifier: MIT
// `amazeballs-cli chart` in process: it writes the window's chart as a PNG that decodes
// and shows something, and as an SVG that parses with an <svg> root; bad input exits
// with status 2, one line naming it, and no file.
#include "support/cli_runner.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include <cmath>
#include <set>
#include <sstream>

namespace {

using testing::cli;
using Result = testing::CliResult;

// Distinct colours in a coarse grid of the image: a blank image has one.
int distinctColours(const QImage& image)
{
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 7)
        for (int x = 0; x < image.width(); x += 7)
            colours.insert(image.pixel(x, y));
    return int(colours.size());
}

QString svgRoot(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QXmlStreamReader xml(&f);
    while (!xml.atEnd()) {
        if (xml.readNext() == QXmlStreamReader::StartElement)
            return xml.name().toString();
    }
    return xml.hasError() ? QString("error: ") + xml.errorString() : QString();
}

} // namespace

class CliChart : public QObject {
    Q_OBJECT

private slots:
    void writesAVelocityChartAsPng()
    {
        QTemporaryDir dir;
        const QString png = dir.filePath("velocity.png");
        const Result r = cli(
            {"chart", "box3d", "--chart", "velocity", "--out", png.toStdString(), "--width", "900", "--height", "600"});
        QCOMPARE(r.status, 0);
        QImage image(png);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(900, 600));
        QVERIFY(distinctColours(image) > 8);
        // The three axis colours of the chart's lines are there (vx red, vy green, vz blue).
        bool red = false, green = false, blue = false;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                red = red || (c.red() > 180 && c.green() < 80 && c.blue() < 80);
                green = green || (c.green() > 130 && c.red() < 90 && c.blue() < 90);
                blue = blue || (c.blue() > 150 && c.red() < 80 && c.green() < 150);
            }
        QVERIFY(red && green && blue);
    }

    void writesAPositionChartAsSvg()
    {
        QTemporaryDir dir;
        const QString svg = dir.filePath("drop.svg");
        QCOMPARE(cli({"chart", "bounce1d", "--chart", "position", "--out", svg.toStdString(), "--steps", "500"}).status,
                 0);
        QCOMPARE(svgRoot(svg), QString("svg"));
    }

    void chartsTheChosenBallOfTwo()
    {
        QTemporaryDir dir;
        const QString png = dir.filePath("ball2.png");
        QCOMPARE(cli({"chart", "two-balls", "--chart", "energy", "--ball", "2", "--out", png.toStdString(), "--steps",
                      "300"})
                     .status,
                 0);
        QVERIFY(!QImage(png).isNull());
    }

    void writesTheConservationChartsOfManyBalls()
    {
        QTemporaryDir dir;
        const QString momentum = dir.filePath("momentum.png");
        const QString activity = dir.filePath("activity.svg");
        QCOMPARE(cli({"chart", "many-balls", "--chart", "momentum", "--out", momentum.toStdString(), "--steps", "300"})
                     .status,
                 0);
        QImage image(momentum);
        QVERIFY(!image.isNull());
        QVERIFY(distinctColours(image) > 8);
        QCOMPARE(cli({"chart", "many-balls", "--chart", "activity", "--out", activity.toStdString(), "--steps", "300"})
                     .status,
                 0);
        QCOMPARE(svgRoot(activity), QString("svg"));
        const QString two = dir.filePath("two.png");
        QCOMPARE(cli({"chart", "two-balls", "--chart", "momentum", "--model", "physical", "--set", "m2=3", "--out",
                      two.toStdString(), "--steps", "300"})
                     .status,
                 0);
        QVERIFY(!QImage(two).isNull());
    }

    void theOneBallsVelocityEndsWhereItLeavesAtTheFoot()
    {
        // street-one-ball leaves the street at t = 6.9 s (its description, St1) within its 8 s:
        // its velocity's cells end there, as the window's lines do, with no drop to rest, and
        // the speeds end with the last ball on the street.
        QTemporaryDir dir;
        const QString csv = dir.filePath("one.csv");
        const Result r = cli({"chart", "street", "--preset", "street-one-ball", "--chart", "velocity", "--out",
                              dir.filePath("one.svg").toStdString(), "--data", csv.toStdString()});
        QCOMPARE(r.status, 0);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QStringList rows;
        for (const QString& line : QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts))
            if (!line.startsWith('#'))
                rows << line;
        const QStringList header = rows.takeFirst().split(',');
        const int vx = int(header.indexOf("vx [m/s]")), median = int(header.indexOf("speed_median [m/s]"));
        QVERIFY(vx > 0 && median > 0);
        double lastT = -1.0, lastSpeed = 0.0;
        int empty = 0;
        for (const QString& row : rows) {
            const QStringList cells = row.split(',');
            QCOMPARE(cells[vx].isEmpty(), cells[median].isEmpty()); // one ball: it is the street's last
            if (cells[vx].isEmpty()) {
                ++empty;
                continue;
            }
            QCOMPARE(empty, 0); // once gone, gone
            lastT = cells[0].toDouble();
            lastSpeed = cells[median].toDouble();
        }
        QVERIFY2(std::abs(lastT - 6.9) < 0.05, qPrintable(QString::number(lastT)));
        QVERIFY2(std::abs(lastSpeed - 14.1) < 0.1, qPrintable(QString::number(lastSpeed)));
        QVERIFY(empty > 60); // the second after it left, and more
    }

    void badInputExitsWith2AndWritesNothing_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown chart") << QStringList{"--chart", "speed"} << "--chart: unknown chart 'speed'";
        QTest::newRow("missing chart") << QStringList{} << "missing --chart";
        QTest::newRow("image type") << QStringList{"--chart", "position", "--ext", "jpg"}
                                    << "unknown image type 'jpg' (use .png, .svg or .pdf)";
        QTest::newRow("no image type") << QStringList{"--chart", "position", "--ext", ""}
                                       << "out.: no image type (use .png, .svg or .pdf)";
        QTest::newRow("ball out of range")
            << QStringList{"--chart", "position", "--ball", "2"} << "--ball: 2 is outside";
        QTest::newRow("bad parameter") << QStringList{"--chart", "position", "--set", "k=7"} << "k: 7 is outside";
        QTest::newRow("momentum of one ball")
            << QStringList{"--chart", "momentum"} << "--chart: the momentum chart is for two-balls and many-balls only";
        QTest::newRow("activity of one ball")
            << QStringList{"--chart", "activity"} << "--chart: the activity chart is for many-balls only, not box3d";
        QTest::newRow("tiny width") << QStringList{"--chart", "position", "--width", "5"} << "--width";
    }

    void badInputExitsWith2AndWritesNothing()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        QTemporaryDir dir;
        QString ext = "png";
        std::vector<std::string> a{"chart", "box3d"};
        for (int i = 0; i < args.size(); ++i) {
            if (args[i] == "--ext") {
                ext = args[++i];
                continue;
            }
            a.push_back(args[i].toStdString());
        }
        a.push_back("--out");
        a.push_back(dir.filePath("out." + ext).toStdString());
        const Result r = cli(a);
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find(mentions.toStdString()) != std::string::npos, r.err.c_str());
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }

    void unwritableFolderExitsWith2BeforeRunning()
    {
        const Result r = cli({"chart", "box3d", "--chart", "position", "--out", "/nonexistent-dir/x.png"});
        QCOMPARE(r.status, 2);
        QVERIFY(r.err.find("does not exist") != std::string::npos);
    }
};

QTEST_MAIN(CliChart)
#include "test_cli_chart.moc"
