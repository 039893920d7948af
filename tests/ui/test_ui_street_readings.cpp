// SPDX-License-Identifier: MIT
// What the window reads off the street (stage 5) as it runs, without OpenGL: the status
// bar's energy a ball and its census in the words the bar's width holds (Details following
// it), the selected ball's own lines ending where it leaves at the foot, a ball the census
// counts gone never drawn (the view's float threshold), and the view's labels read whole.
#include "support/street_states.h"

#include "core/diagnostics/conservation.h"
#include "core/street/street_census.h"
#include "ui/charts/chart_legend.h"
#include "ui/charts/motion_chart.h"
#include "ui/charts/scene_layout.h"
#include "ui/panels/status_readout.h"
#include "ui/sim/recording.h"
#include "ui/view/orbit_camera.h"
#include "ui/view/scene_geometry.h"
#include "ui/view/view_frame.h"

#include <QApplication>
#include <QImage>
#include <QLabel>
#include <QLineSeries>
#include <QPainter>
#include <QSet>
#include <QStatusBar>
#include <QToolButton>
#include <QValueAxis>
#include <QtTest>

using namespace ab;
using namespace ab::ui;
using testing::defaultStreet;
using testing::stateAt;
using testing::streetSpec;

namespace {

// The labels of `geometry` as `camera` draws them over a view of `size`, in 14 pt on white.
QImage paintedLabels(const OrbitCamera& camera, QSize size, const SceneGeometry& geometry)
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    QFont font;
    font.setPointSizeF(14.0);
    paintSceneLabels(painter, camera, size, geometry, SceneLayout{}, {}, font, Qt::white);
    painter.end();
    return image;
}

// A camera framing the cube [0, 10]^3 from the front, level, for a view of `size`.
OrbitCamera frontOfCube(QSize size)
{
    OrbitCamera camera;
    camera.frame({0, 0, 0}, {10, 10, 10}, 0.0f, 0.0f, float(size.width()) / float(size.height()));
    return camera;
}

} // namespace

class UiStreetReadings : public QObject {
    Q_OBJECT

private slots:
    void statusBarReadsTheStreetsEnergyPerBall()
    {
        // Four balls at rest 5 m above the foot (y = 0): E/m = g h = 9.82 x 5 = 49.1 m^2/s^2
        // a ball, 196.4 for the four together (the energy chart's sum).
        const RunSpec spec = streetSpec(4);
        const auto sim = makeSimulation(spec);
        State st = sim->start();
        st.p.row(1).setConstant(5.0);
        st.v.setZero();
        st.w.setZero(3, st.size());
        QStatusBar bar;
        StatusReadout readout(&bar);
        readout.setRun(spec);
        EngineStatus status;
        status.energy = measureConservation(*sim, st).energy.total();
        readout.show(status);
        const QString sq = QString::fromUtf8("\u00b2");
        QCOMPARE(readout.energyText(), QString("E/m = 49.1 m%1/s%1 a ball").arg(sq));
        auto* label = bar.findChild<QLabel*>("statusEnergy");
        QVERIFY(label &&
                label->toolTip().contains(
                    QString("the 4 balls, as the energy chart draws it. All balls together: 196.4 m%1/s%1").arg(sq)));
        // One ball is not a crowd: stage 2 reads its own energy, g h = 9.82 x 2 per unit mass.
        RunSpec box(SceneId::Box3d);
        readout.setRun(box);
        status.energy = 19.64;
        readout.show(status);
        QCOMPARE(readout.energyText(), QString("E/m = 19.64 m%1/s%1").arg(sq));
        QVERIFY(!label->toolTip().contains("mean"));
    }

    void statusBarCountsTheStreetInTheWordsItsWidthHolds()
    {
        // Five balls: three on block 1, one past its foot, one gone beyond the open foot at
        // 50 m/s (no longer on the street: the fastest on it is 4 m/s).
        const street::Layout s = defaultStreet();
        const State st = stateAt(s, {10.0, 20.0, 30.0, s.blockFootX[0] + 5.0, s.xFoot + 1.0}, {1, 2, 3, 4, 50}, 0.0);
        const Frame frame = makeFrame(0, st, ConservationSample{});
        QStatusBar bar;
        StatusReadout readout(&bar);
        readout.setRun(streetSpec(5));
        auto* label = bar.findChild<QLabel*>("statusWarning");
        QVERIFY(label);
        const QString whole =
            "4 balls on the street, 2 past the first block's foot, 1 out at the foot; fastest 4.0 m/s";
        const QStringList forms = {whole, "4 on the street, 1 out at the foot; fastest 4.0 m/s",
                                   "1 out at the foot; fastest 4.0 m/s", "fastest 4.0 m/s"};
        bar.show();
        QSet<QString> seen;
        for (const int width : {2400, 1300, 1150, 1050, 950, 850, 700}) {
            bar.resize(width, bar.sizeHint().height());
            readout.show(EngineStatus{}, &frame);
            QTRY_COMPARE(label->width() > 0, true);
            QApplication::processEvents();
            const int room = label->contentsRect().width();
            const QString shown = readout.warningShown();
            QCOMPARE(readout.warningText(), whole); // Details and the tooltip have all of it
            // The longest form that fits the label's room, whatever the room.
            QString expected = "Balls on the street";
            for (const QString& form : forms)
                if (label->fontMetrics().horizontalAdvance(form) <= room) {
                    expected = form;
                    break;
                }
            QCOMPARE(shown, expected);
            QCOMPARE(readout.detailsButton()->isVisibleTo(&bar), shown != whole);
            seen << shown;
        }
        QVERIFY2(seen.size() >= 4,
                 qPrintable(QStringList(seen.values()).join(" | "))); // the bar went through the forms
        // A bar as wide as a desktop's shows the whole census.
        bar.resize(2400, bar.sizeHint().height());
        QTRY_COMPARE(readout.warningShown(), whole);
        // Details, opened on a narrow bar, follow the census as the run goes on.
        bar.resize(700, bar.sizeHint().height());
        readout.show(EngineStatus{}, &frame);
        QTRY_VERIFY(readout.detailsButton()->isVisible());
        readout.detailsButton()->click();
        auto* popup = bar.window()->findChild<QLabel*>("statusDetailsText");
        QVERIFY(popup && popup->isVisible());
        QCOMPARE(popup->text(), whole);
        const State later =
            stateAt(s, {10.0, 20.0, s.blockFootX[0] + 1.0, s.xFoot + 2.0, s.xFoot + 1.0}, {1, 2, 7, 0, 0}, 1.0);
        const Frame next = makeFrame(1, later, ConservationSample{});
        readout.show(EngineStatus{}, &next);
        QCOMPARE(popup->text(),
                 QString("3 balls on the street, 3 past the first block's foot, 2 out at the foot; fastest 7.0 m/s"));
        // All gone: no fastest ball on an empty street (it said "fastest 0.0 m/s").
        const State gone = stateAt(s, std::vector<double>(5, s.xFoot + 1.0), std::vector<double>(5, 0.0), 30.0);
        const Frame end = makeFrame(2, gone, ConservationSample{});
        readout.show(EngineStatus{}, &end);
        QCOMPARE(readout.warningText(), QString("All 5 balls have left at the foot"));
        // The run ended there (RunEngine: the step its last ball left): it says so and when.
        EngineStatus done;
        done.finished = true;
        done.t = 29.5;
        done.emptiedAt = 29.5;
        readout.show(done, &end);
        QCOMPARE(readout.warningText(),
                 QString("All 5 balls have left at the foot by t = 29.50 s; the run ends there, and Play starts it "
                         "again"));
        // However narrow the bar (lecture mode's large text at 1280x720), it says the run ended.
        for (const int width : {900, 600, 420, 330}) {
            bar.resize(width, bar.sizeHint().height());
            readout.show(done, &end);
            QTRY_COMPARE(label->width() > 0, true);
            QApplication::processEvents();
            const QString shown = readout.warningShown();
            QVERIFY2(shown.contains("complete"), qPrintable(QString("%1: %2").arg(width).arg(shown)));
        }
    }

    void oneBallsCensusSaysWhereItIsInTheSingular()
    {
        // The one-ball preset's bar: "1 balls on the street, 0 past ..." read as a fault.
        const street::Layout s = defaultStreet();
        QStatusBar bar;
        StatusReadout readout(&bar);
        readout.setRun(streetSpec(1));
        bar.resize(2400, bar.sizeHint().height());
        bar.show();
        const Frame onBlock = makeFrame(0, stateAt(s, {10.0}, {3.0}, 0.0), ConservationSample{});
        readout.show(EngineStatus{}, &onBlock);
        QCOMPARE(readout.warningText(), QString("The ball is on the first block at 3.0 m/s"));
        const Frame past = makeFrame(1, stateAt(s, {s.blockFootX[0] + 1.0}, {12.0}, 9.0), ConservationSample{});
        readout.show(EngineStatus{}, &past);
        QCOMPARE(readout.warningText(), QString("The ball is past the first block's foot at 12.0 m/s"));
        const Frame gone = makeFrame(2, stateAt(s, {s.xFoot + 0.5}, {0.0}, 12.0), ConservationSample{});
        readout.show(EngineStatus{}, &gone);
        QCOMPARE(readout.warningText(), QString("The ball has left at the foot"));
        EngineStatus done;
        done.finished = true;
        done.t = 12.0;
        done.emptiedAt = 12.0;
        readout.show(done, &gone);
        QCOMPARE(readout.warningText(),
                 QString("The ball has left at the foot at t = 12.00 s; the run ends there, and Play starts it again"));
    }

    void aBallsOwnLinesEndWhereItLeavesAtTheFoot()
    {
        // Ball 1 rolls 1 m a sample (10 m/s, every 0.1 s) from 4.5 m above the foot: past it
        // from the sixth sample (x = xFoot + 0.5), after which the engine holds it at rest.
        // Its position, velocity and spin end at t = 0.4 (no drop to rest drawn); the
        // energy, all balls, goes on; ball 2 stays on the street and keeps every sample.
        const RunSpec spec = streetSpec(2);
        const auto sim = makeSimulation(spec);
        const ConservationMeter meter(*sim);
        const street::Layout s = defaultStreet();
        Recording recording(layoutFor(spec), meter, 0);
        for (int k = 0; k <= 10; ++k) {
            const double x = s.xFoot - 4.5 + k;
            State st = stateAt(s, {x, 10.0}, {k < 5 ? 10.0 : 0.0, 1.0}, 0.1 * k);
            st.w.setZero(3, 2);
            recording.add(k, st);
        }
        auto chartOf = [&](ChartKind kind) {
            auto chart = std::make_unique<MotionChart>(kind);
            chart->configure(sceneInfo(SceneId::Street), recording.trackedBall(), ChartUnits{true, false, true});
            chart->setTimeSpan(1.0);
            chart->showTrack(recording.track(), 600);
            return chart;
        };
        for (ChartKind kind : {ChartKind::Position, ChartKind::Velocity, ChartKind::Spin}) {
            const auto chart = chartOf(kind);
            const int line = chart->shownAxes().front();
            QCOMPARE(chart->line(line)->count(), 5);
            QCOMPARE(chart->line(line)->points().back().x(), 0.4);
        }
        QCOMPARE(chartOf(ChartKind::Energy)->line(2)->count(), 11);
        recording.setTrackedBall(1); // rebuilt from the frames
        QCOMPARE(chartOf(ChartKind::Position)->line(0)->count(), 11);
        recording.setTrackedBall(0);
        QCOMPARE(chartOf(ChartKind::Velocity)->line(0)->count(), 5);
        recording.truncateFrom(3); // the run forked back before it left: its lines go on again
        QCOMPARE(recording.track().ballSamples(), std::size_t(3));
        recording.add(3, stateAt(s, {s.xFoot - 3.0, 10.0}, {10.0, 1.0}, 0.3));
        QCOMPARE(recording.track().ballSamples(), std::size_t(4));
    }

    void theStreetsEnergyChartDrawsTheMeanPerBall()
    {
        // The street's sums over 10,000 balls ran to an axis of "8000000": its chart draws the
        // mean a ball, as the status bar reads it. At the start (the hopper's balls) the total
        // is the mean over the balls of |v|^2 / 2 + q r^2 |w|^2 / 2 + g y (docs/spin.md; the foot
        // at y = 0), summed here from the state itself.
        const RunSpec spec = streetSpec(20);
        const auto sim = makeSimulation(spec);
        const ConservationMeter meter(*sim);
        const ChartUnits units = chartUnitsOf(meter, spec);
        QCOMPARE(units.energyMeanOver, 20);
        Recording recording(layoutFor(spec), meter, 0);
        State s = sim->start(), next;
        recording.add(0, s);
        for (long long k = 1; k <= 5; ++k) {
            sim->step(s, next);
            std::swap(s, next);
            recording.add(k, s);
        }
        MotionChart chart(ChartKind::Energy);
        chart.configure(sceneInfo(SceneId::Street), 0, units);
        chart.setTimeSpan(s.t);
        chart.showTrack(recording.track(), 600);
        QVERIFY2(chart.title().contains("mean per ball"), qPrintable(chart.title()));
        QCOMPARE(chart.valueAxis()->titleText(), QString("mean E/m"));
        const State start = sim->start();
        const double g = spec.params.real("g"), r = spec.params.real("r"), q = spec.params.real("inertia");
        double sum = 0.0;
        for (int i = 0; i < start.size(); ++i)
            sum +=
                0.5 * start.v.col(i).squaredNorm() + 0.5 * q * r * r * start.spin(i).squaredNorm() + g * start.p(1, i);
        const double mean = sum / 20.0, drawn = chart.line(2)->points().front().y();
        QVERIFY2(std::abs(drawn - mean) <= 1e-12 * mean, qPrintable(QString("%1 against %2").arg(drawn).arg(mean)));
    }

    void theEnergyChartsTotalKeepsWhatTheBallsTookOutAtTheFoot()
    {
        // One elastic superball (e = beta = 1, sticking friction) rolls and bounces off one
        // block of 30 deg: nothing is lost, so the total stays at the start's g h + v^2 / 2 while
        // the energy moves into "left at the foot" as the ball leaves; the street keeps none.
        RunSpec spec = streetSpec(1);
        for (const char* a : {"blocks=1", "slope=30", "e=1", "beta=1", "mu=10", "rest_height=0"}) {
            const std::string text(a);
            const auto eq = text.find('=');
            spec.params.parse(text.substr(0, eq), text.substr(eq + 1));
        }
        const auto sim = makeSimulation(spec);
        const ConservationMeter meter(*sim);
        const street::Layout layout = street::Layout::fromParams(spec.params);
        Recording recording(layoutFor(spec), meter, 0);
        State s = sim->start(), next;
        recording.add(0, s);
        int after = 0;
        for (long long k = 1; k < 1200 && after < 10; ++k) {
            sim->step(s, next);
            std::swap(s, next);
            recording.add(k, s);
            after += street::hasLeft(layout, s.p(0, 0)) ? 1 : 0;
        }
        QCOMPARE(after, 10);
        MotionChart chart(ChartKind::Energy);
        ChartUnits units{true, false, true};
        units.streetBlocks = 1;
        chart.configure(sceneInfo(SceneId::Street), 0, units);
        chart.setTimeSpan(s.t);
        chart.showTrack(recording.track(), 600);
        QCOMPARE(chart.shownAxes(), (std::vector<int>{0, 4, 1, 5, 2}));
        QStringList names;
        for (const LegendEntry& e : chart.legendEntries())
            names << e.text;
        QVERIFY2(names.contains("left at the foot"), qPrintable(names.join(", ")));
        const QList<QPointF> total = chart.line(2)->points(), left = chart.line(5)->points();
        const QList<QPointF> potential = chart.line(1)->points();
        QVERIFY(total.size() > 100 && total.size() == left.size());
        const double e0 = total.front().y();
        for (const QPointF& p : total)
            QVERIFY2(std::abs(p.y() - e0) <= 1e-9 * e0,
                     qPrintable(QString("t = %1: %2 against %3").arg(p.x()).arg(p.y()).arg(e0)));
        QCOMPARE(left.front().y(), 0.0);
        QVERIFY(std::abs(left.back().y() - e0) <= 1e-9 * e0);
        QCOMPARE(potential.back().y(), 0.0);
    }

    void aLabelReadsTheSameWhereverItsPointFallsWithinAPixel()
    {
        // The view's labels are outlines, filled antialiased: from a baseline between two pixel
        // rows the one-pixel bars of t and f spread over both at half strength, and the foot
        // shot's label read "lop, 70.2 m above lhe fool". Set on a whole pixel, the text is the
        // same ink, moved by whole pixels, wherever within a pixel its point falls.
        auto inked = [](double dy) {
            QImage image(240, 40, QImage::Format_RGB32);
            image.fill(Qt::white);
            QPainter p(&image);
            p.setRenderHint(QPainter::Antialiasing);
            QFont font = p.font();
            font.setPixelSize(13);
            p.setFont(font);
            ab::ui::drawHaloText(p, QPointF(120.0, 20.0 + dy), "top, the foot", Qt::black, Qt::AlignHCenter);
            p.end();
            int top = image.height(), left = image.width();
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    if (qGray(image.pixel(x, y)) < 128) {
                        top = std::min(top, y);
                        left = std::min(left, x);
                    }
            return image.copy(left, top, 200, 20);
        };
        const QImage whole = inked(0.0);
        for (const double dy : {0.25, 0.5, 0.75})
            QVERIFY2(inked(dy) == whole, qPrintable(QString("moved by %1 px").arg(dy)));
    }

    void aLabelAtTheViewsEdgeIsMovedInWhole()
    {
        // The side shot puts the foot's label at the view's bottom edge: drawn centred on its
        // point, half of it would fall outside. Moved in, every pixel of its red text lies
        // inside with the halo's margin: the rows touching the edges hold none.
        const QSize size(600, 300);
        const OrbitCamera camera = frontOfCube(size);
        QVector3D at(5, 5, 5);
        QPointF pixel;
        for (float y = 5.0f; y > -50.0f; y -= 0.01f) // down to the last point still in view
            if (QPointF p; camera.project({5, y, 5}, size, p) && p.y() <= size.height() - 1.0)
                at.setY(y), pixel = p;
        QVERIFY(pixel.y() > size.height() - 3.0);
        SceneGeometry geometry;
        geometry.labels.push_back({at, QStringLiteral("foot"), QColor(0xd0, 0, 0)});
        const QImage image = paintedLabels(camera, size, geometry);
        QFont font;
        font.setPointSizeF(14.0);
        int top = size.height(), bottom = -1;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x)
                if (const QColor c = image.pixelColor(x, y); c.red() > 150 && c.green() < 100 && c.blue() < 100)
                    top = std::min(top, y), bottom = std::max(bottom, y);
        QVERIFY(bottom >= 0); // drawn
        QVERIFY2(bottom <= size.height() - 3, qPrintable(QStringLiteral("red text down to row %1").arg(bottom)));
        QVERIFY2(bottom - top >= QFontMetrics(font).ascent() / 2,
                 qPrintable(QStringLiteral("%1 rows").arg(bottom - top)));
    }

    void aLabelWhosePointIsOutOfViewIsNotDrawn()
    {
        // The flood shot looks down the street from below its top: the top's label point lies
        // above the picture. Moved into a corner, the label would name the wrong place.
        const QSize size(600, 300);
        const OrbitCamera camera = frontOfCube(size);
        SceneGeometry geometry;
        for (const QVector3D at : {QVector3D(5, 40, 5), QVector3D(5, -30, 5)}) { // above, below the view
            QPointF p;
            QVERIFY(!camera.project(at, size, p) || p.y() < 0.0 || p.y() > size.height());
            geometry.labels.push_back({at, QStringLiteral("top"), QColor(0xd0, 0, 0)});
        }
        const QImage image = paintedLabels(camera, size, geometry);
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x)
                QVERIFY2(image.pixelColor(x, y) == QColor(Qt::white),
                         qPrintable(QString("drawn at %1,%2").arg(x).arg(y)));
    }

    void aBallCountedGoneIsNeverDrawnAndOneOnTheStreetAlwaysIs()
    {
        // The view hides a ball by its frame's float x; the census and the charts count it
        // gone by that x read back as a double (hasLeft). They agree for balls a few
        // micrometres either side of the foot, where the engine retires them, on streets whose
        // foot rounds up as a float (the default's 257.5131414 to 257.5131531) and down.
        int roundedUp = 0;
        for (const double length : {80.0, 60.0, 100.0, 123.4, 75.0}) {
            RunSpec spec = streetSpec();
            spec.params.parse("block_length", QString::number(length).toStdString());
            const street::Layout s = street::Layout::fromParams(spec.params);
            roundedUp += double(float(s.xFoot)) > s.xFoot ? 1 : 0;
            const float threshold = footAsFloat(s.xFoot);
            for (int k = -60; k <= 60; ++k) {
                const float x = float(s.xFoot + 1e-6 * k);
                QCOMPARE(x > threshold, street::hasLeft(s, double(x)));
            }
        }
        QVERIFY(roundedUp >= 1); // the case a float threshold of float(xFoot) got wrong
    }
};

QTEST_MAIN(UiStreetReadings)
#include "test_ui_street_readings.moc"
