// SPDX-License-Identifier: MIT
// The street (stage 5) on the window's side, without OpenGL: the counts and speeds its
// charts draw from hand-made states, the foot-rate chart's balls per second, the street
// drawn as road, crossings, houses and cars, its camera shots, the flood's front, the
// report model greyed out with its reason, and the navigator's equations with numbers.
#include "support/street_states.h"

#include "core/street/street_census.h"
#include "ui/charts/chart_data_csv.h"
#include "ui/charts/motion_chart.h"
#include "ui/charts/scene_layout.h"
#include "ui/charts/street_sample.h"
#include "ui/panels/chart_panel.h"
#include "ui/panels/parameter_panel.h"
#include "ui/panels/run_options_panel.h"
#include "ui/panels/street_equations.h"
#include "ui/view/scene_geometry.h"
#include "ui/view/street_camera.h"
#include "ui/view/street_geometry.h"

#include <QApplication>
#include <QChartView>
#include <QComboBox>
#include <QEnterEvent>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QLineSeries>
#include <QPushButton>
#include <QStandardItemModel>
#include <QTabBar>
#include <QtTest>

#include <cmath>
#include <sstream>

using namespace ab;
using namespace ab::ui;
using testing::defaultStreet;
using testing::stateAt;
using testing::streetSpec;

namespace {

// The camera of `shot` over a view of `size`.
OrbitCamera cameraAt(const street::Layout& s, StreetShot shot, QSize size)
{
    const CameraPose pose = streetPose(s, shot, float(size.width()) / float(size.height()));
    OrbitCamera camera;
    camera.setPose(pose.target, pose.yaw, pose.pitch, pose.distance, 400.0f);
    return camera;
}

bool onScreen(const QPointF& p, QSize size)
{
    return p.x() >= 0 && p.y() >= 0 && p.x() <= size.width() && p.y() <= size.height();
}

// The street's own run options: the physical model, stepping by events.
RunOptions streetOptions()
{
    RunOptions options;
    options.model = ModelKind::Physical;
    options.integrator = Integrator::Event;
    options.steps = 100;
    return options;
}

// The entry of `box` whose data is `data`.
QStandardItem* itemOf(QComboBox* box, int data)
{
    return qobject_cast<QStandardItemModel*>(box->model())->item(box->findData(data));
}

} // namespace

class UiStreet : public QObject {
    Q_OBJECT

private slots:
    void streetSampleCountsBallsPastEachFootAndLeavesOutTheGoneBalls()
    {
        const street::Layout s = defaultStreet();
        const double foot1 = s.blockFootX[0], foot2 = s.blockFootX[1];
        // Two on block 1, one past foot 1, one past foot 2, one gone beyond the open foot.
        const State st = stateAt(s, {10.0, 20.0, foot1 + 5.0, foot2 + 5.0, s.xFoot + 1.0}, {1, 2, 3, 4, 50}, 0.0);
        const StreetSample sample = measureStreet(s, st);
        QCOMPARE(footBlocks(s.blocks), (std::vector<int>{0, 1, 2}));
        QCOMPARE(sample.pastFoot[0], 3.0); // foot2 + 5 and the gone ball are past foot 1 too
        QCOMPARE(sample.pastFoot[1], 2.0);
        QCOMPARE(sample.pastFoot[2], 1.0); // the gone ball is past the street's foot
        // Speeds of the four on the street, 1 2 3 4: ranks floor(q * 3) = 0, 1, 2; fastest 4 (not 50).
        QCOMPARE(sample.speed[0], 1.0);
        QCOMPARE(sample.speed[1], 2.0);
        QCOMPARE(sample.speed[2], 3.0);
        QCOMPARE(sample.speed[3], 4.0);
    }

    void footBlocksKeepTheStreetsOwnFootOnALongStreet()
    {
        QCOMPARE(footBlocks(1), std::vector<int>{0});
        QCOMPARE(footBlocks(12), (std::vector<int>{0, 1, 2, 3, 11}));
    }

    void footRateChartCountsAHandMadeFlood()
    {
        // Ten balls pass the first block's foot between t = 1 and t = 2 (five a half second),
        // none before or after: the rate over a 0.5 s window is 10 balls/s in that second.
        const street::Layout s = defaultStreet();
        const double foot = s.blockFootX[0];
        MotionTrack track;
        const std::vector<double> times = {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0};
        const std::vector<int> past = {0, 0, 0, 5, 10, 10, 10};
        for (std::size_t k = 0; k < times.size(); ++k) {
            std::vector<double> xs(10, foot - 3.0), vs(10, 1.0);
            for (int i = 0; i < past[k]; ++i)
                xs[std::size_t(i)] = foot + 1.0;
            const State st = stateAt(s, xs, vs, times[k]);
            track.add((long long)k, st.t, st.p.col(0), st.v.col(0), Eigen::Vector3d::Zero(), ConservationSample{},
                      measureStreet(s, st));
        }
        MotionChart chart(ChartKind::FootRate);
        ChartUnits units;
        units.streetBlocks = s.blocks;
        chart.configure(sceneInfo(SceneId::Street), 0, units);
        chart.setTimeSpan(30.0); // the rate's window is 30 / 60 = 0.5 s
        chart.showTrack(track, 600);
        QCOMPARE(chart.shownAxes(), (std::vector<int>{0, 1, 2}));
        const QList<QPointF> points = chart.line(0)->points();
        QCOMPARE(points.size(), qsizetype(times.size()));
        const std::vector<double> expected = {0.0, 0.0, 0.0, 10.0, 10.0, 0.0, 0.0};
        for (std::size_t k = 0; k < expected.size(); ++k)
            QCOMPARE(points[qsizetype(k)].y(), expected[k]);
        QVERIFY(chart.line(1)->points().size() > 0);
        for (const QPointF& p : chart.line(1)->points())
            QCOMPARE(p.y(), 0.0); // nobody reached the second foot
    }

    void trackThinningKeepsTheStreetColumnsWithTheirTimes()
    {
        MotionTrack track(4);
        for (long long k = 0; k < 20; ++k) {
            StreetSample sample;
            sample.pastFoot[0] = double(k);
            track.add(k, double(k), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                      ConservationSample{}, sample);
        }
        QCOMPARE(track.pastFoot(0).size(), track.t().size());
        for (std::size_t i = 0; i < track.t().size(); ++i)
            QCOMPARE(track.pastFoot(0)[i], track.t()[i]);
    }

    void chartDataCsvCarriesTheStreetsCountsAndSpeeds()
    {
        MotionTrack track;
        StreetSample sample;
        sample.pastFoot = {7, 3, 1, 0, 0};
        sample.speed = {0.5, 2.0, 6.5, 11.25};
        sample.onStreet = 5;
        ConservationSample scene;
        scene.energy.left = 1234.5;
        const Eigen::Vector3d p(1.0, 2.0, 3.0), v(4.0, 5.0, 6.0);
        track.add(0, 0.0, p, v, Eigen::Vector3d::Zero(), scene, sample);
        // Then the selected ball and the last on the street leave at the foot: the ball's own
        // cells and the speeds' are empty, not a ball at rest at the foot or speeds of 0.
        track.markBallGone(1);
        sample.pastFoot = {12, 12, 12, 0, 0};
        sample.speed = {};
        sample.onStreet = 0;
        scene.energy.left = 2000.0;
        track.add(1, 0.5, Eigen::Vector3d(99.0, 0.03, 0.0), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), scene,
                  sample);
        ChartData data;
        data.run = &track;
        data.streetBlocks = 3;
        std::ostringstream out;
        writeChartCsv(out, data);
        std::istringstream lines(out.str());
        std::string header, row, gone;
        std::getline(lines, header);
        std::getline(lines, row);
        std::getline(lines, gone);
        QVERIFY(header.ends_with(",past_foot_1 [balls],past_foot_2 [balls],past_foot_3 [balls],speed_p10 [m/s],"
                                 "speed_median [m/s],speed_p90 [m/s],speed_max [m/s],energy_left [m^2/s^2]"));
        QVERIFY(row.starts_with("0,1,1,2,3,4,5,6,"));
        QVERIFY(row.ends_with(",7,3,1,0.5,2,6.5,11.25,1234.5"));
        QVERIFY2(gone.starts_with("0.5,1,,,,,,,"), gone.c_str());
        QVERIFY2(gone.ends_with(",12,12,12,,,,,2000"), gone.c_str());
        data.streetBlocks = 0; // another stage: no street columns
        std::ostringstream plain;
        writeChartCsv(plain, data);
        QVERIFY(plain.str().find("past_foot") == std::string::npos);
    }

    void theStreetsConstantsRestoreToItsDefaultsNotTheReports()
    {
        // The report never reached the street: its button and tooltips name the defaults.
        ParameterPanel panel;
        const SceneInfo& street = sceneInfo(SceneId::Street);
        panel.setScene(street, ModelKind::Physical, street.defaults());
        auto* restore = panel.findChild<QPushButton*>("reportValues");
        QVERIFY(restore);
        QCOMPARE(restore->text(), QString("Default values"));
        const QString tip = panel.field("slope")->toolTip();
        QVERIFY2(tip.contains("Default: 17") && !tip.contains("Report"), qPrintable(tip));
        // The key follows the symbol only where they differ ("r (r)" said it twice).
        QVERIFY2(panel.field("r")->toolTip().startsWith("<b>r</b>: "), qPrintable(panel.field("r")->toolTip()));
        QVERIFY2(panel.field("n")->toolTip().startsWith("<b>N</b> (n): "), qPrintable(panel.field("n")->toolTip()));
        // Greek symbols as the equations set them: "theta (slope)" read as code beside St1's θ.
        QVERIFY2(panel.field("slope")->toolTip().startsWith(QString::fromUtf8("<b>\u03b8</b> (slope): ")),
                 qPrintable(panel.field("slope")->toolTip()));
        QVERIFY2(panel.field("mu")->toolTip().startsWith(QString::fromUtf8("<b>\u03bc</b>")),
                 qPrintable(panel.field("mu")->toolTip()));
        QStringList labels;
        for (const QLabel* l : panel.findChildren<QLabel*>())
            labels << l->text();
        QVERIFY2(labels.contains(QString::fromUtf8("\u03b8 (slope)")), qPrintable(labels.join(" | ")));
        // A refusal's range and unit stay on one line: "(0, 60] deg" broke before "deg".
        panel.refuse("slope", "slope: 70 is outside the allowed range (0, 60] deg");
        const QString refused = panel.findChild<QLabel*>("paramError-slope")->text();
        const QChar nbsp(0x00A0);
        QVERIFY2(refused.endsWith(QString("(0,") + nbsp + "60]" + nbsp + "deg"), qPrintable(refused));
        // Stage 2 is the report's: its g, and its button, are the report's; its friction is not.
        const SceneInfo& box = sceneInfo(SceneId::Box3d);
        panel.setScene(box, ModelKind::Physical, box.defaults());
        QCOMPARE(restore->text(), QString("Report values"));
        QVERIFY(panel.field("g")->toolTip().contains("Report value: 9.82"));
        QVERIFY(panel.field("mu")->toolTip().contains("Default: 0"));
    }

    void streetChartsBelongToTheStreetOnly()
    {
        for (const SceneInfo* s : allScenes()) {
            const bool street = s->id == SceneId::Street;
            QCOMPARE(chartApplies(ChartKind::FootRate, s->id), street);
            QCOMPARE(chartApplies(ChartKind::Speeds, s->id), street);
        }
        QCOMPARE(parseChartKind("foot-rate"), std::optional(ChartKind::FootRate));
        QCOMPARE(parseChartKind("speeds"), std::optional(ChartKind::Speeds));
    }

    void chartPanelShowsTheStreetsChartsAtAReadableHeight()
    {
        ChartPanel panel;
        panel.resize(600, 4000); // room for every chart on one page
        ChartUnits units;
        units.streetBlocks = 3;
        panel.configure(sceneInfo(SceneId::Street), 10, 0, 30.0, units);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        for (ChartKind kind : {ChartKind::Energy, ChartKind::FootRate, ChartKind::Speeds}) {
            QVERIFY(panel.chartShown(kind));
            QVERIFY2(panel.chartView(kind)->height() >= 200, chartKey(kind).data());
        }
        QVERIFY(!panel.chartShown(ChartKind::Activity) || !panel.chartView(ChartKind::Activity)->isVisible());
    }

    void theCurrentChartIsOneOnThePageShown()
    {
        // "Export current chart" exports the chart last pointed at only while its page is
        // shown: pointed at on one page, another page shown, it is that page's first chart.
        ChartPanel panel;
        panel.resize(600, 330); // one chart a page
        ChartUnits units;
        units.streetBlocks = 3;
        panel.configure(sceneInfo(SceneId::Street), 10, 0, 30.0, units);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QCOMPARE_GT(panel.pages()->count(), 2);
        panel.pages()->setCurrentIndex(1);
        ChartKind pointed = panel.currentChart();
        QVERIFY(panel.onCurrentPage(pointed));
        QTest::mouseClick(panel.chartView(pointed)->viewport(), Qt::LeftButton);
        QCOMPARE(panel.currentChart(), pointed);
        panel.pages()->setCurrentIndex(0);
        const ChartKind now = panel.currentChart();
        QVERIFY(now != pointed);
        QVERIFY(panel.onCurrentPage(now));
        QCOMPARE(now, panel.shownCharts().front());
        panel.pages()->setCurrentIndex(1);
        QCOMPARE(panel.currentChart(), pointed);
        // The pointer passing over another chart on its way does not choose it: a click does.
        panel.resize(600, 4000); // every chart on one page
        QTRY_VERIFY(panel.onCurrentPage(ChartKind::Energy) && panel.onCurrentPage(ChartKind::Speeds));
        QTest::mouseClick(panel.chartView(ChartKind::Energy)->viewport(), Qt::LeftButton);
        QEnterEvent enter(QPointF(5, 5), QPointF(5, 5), QPointF(5, 5));
        QApplication::sendEvent(panel.chartView(ChartKind::Speeds)->viewport(), &enter);
        QCOMPARE(panel.currentChart(), ChartKind::Energy);
    }

    void chartPagesWhoseTabsDoNotFitAreChosenFromAList()
    {
        // A panel short enough for one chart a page and too narrow for the pages' tabs
        // (as the street's panel in lecture mode at 1280x720): a list names the pages whole.
        ChartPanel panel;
        panel.resize(300, 330);
        ChartUnits units;
        units.streetBlocks = 3;
        panel.configure(sceneInfo(SceneId::Street), 10, 0, 30.0, units);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTabBar* pages = panel.pages();
        QComboBox* menu = panel.pagesMenu();
        QCOMPARE_GT(pages->count(), 2);
        QVERIFY(pages->sizeHint().width() > panel.layout()->contentsRect().width());
        QVERIFY(menu->isVisible());
        QVERIFY(!pages->isVisible());
        QCOMPARE(menu->count(), pages->count());
        for (int page = menu->count() - 1; page >= 0; --page) {
            menu->setCurrentIndex(page);
            QCOMPARE(pages->currentIndex(), page);
            QCOMPARE(menu->currentText(), pages->tabText(page));
            // The charts shown are the ones the page's name lists.
            int shown = 0;
            for (ChartKind kind : panel.shownCharts())
                shown += panel.onCurrentPage(kind) ? 1 : 0;
            QCOMPARE(shown, int(menu->currentText().split(" + ").size()));
            // And nothing else takes room on the page: no chart's place is left empty.
            for (ChartKind kind : allChartKinds()) {
                const QWidget* view = panel.chartView(kind);
                QVERIFY2(!view->parentWidget()->isVisibleTo(&panel) || view->isVisibleTo(&panel),
                         qPrintable(QString("page %1: an empty place for %2").arg(page).arg(chartKey(kind).data())));
            }
        }
        // Where the tabs fit whole, they are the pages again.
        panel.resize(3000, 330);
        QTRY_VERIFY(pages->isVisible());
        QVERIFY(!menu->isVisible());
        QVERIFY(pages->tabRect(pages->count() - 1).right() <= pages->width());
    }

    void reportModelIsNotOfferedForTheStreet()
    {
        RunOptionsPanel panel;
        const RunOptions options = streetOptions();
        const auto reportItem = itemOf;
        panel.showOptions(sceneInfo(SceneId::Street), options);
        auto* reason = panel.findChild<QLabel*>("noReportModel");
        QVERIFY(reason);
        QVERIFY(!reason->isHidden());
        QCOMPARE(reason->text(), RunOptionsPanel::noReportModelReason());
        QVERIFY(reason->text().contains("3.1"));
        QVERIFY(!reportItem(panel.modelBox(), int(ModelKind::Report))->isEnabled());
        QVERIFY(!reportItem(panel.compareBox(), int(ModelKind::Report) * 100)->isEnabled());
        // Back in a stage of the report the model is offered again, with no reason shown.
        panel.showOptions(sceneInfo(SceneId::ManyBalls), options);
        QVERIFY(reason->isHidden());
        QVERIFY(reportItem(panel.modelBox(), int(ModelKind::Report))->isEnabled());
        QVERIFY(!RunOptionsPanel::reportModelOffered(SceneId::Street));
        QVERIFY(RunOptionsPanel::reportModelOffered(SceneId::ManyBalls));
    }

    void onlyTheIntegratorsAStageStepsWithAreOffered()
    {
        // The street's flight is exact between events: the other integrators are greyed, saying
        // why (choosing one drew a refusal in the command line's words, "--integrator: ...").
        // Many-balls steps with the four explicit ones.
        RunOptionsPanel panel;
        RunOptions options = streetOptions();
        const auto item = itemOf;
        auto integrators = panel.findChild<QComboBox*>("integratorCombo");
        QVERIFY(integrators);
        panel.showOptions(sceneInfo(SceneId::Street), options);
        for (Integrator i : allIntegrators()) {
            const bool event = i == Integrator::Event;
            QCOMPARE(item(integrators, int(i))->isEnabled(), event);
            QCOMPARE(item(panel.compareBox(), int(ModelKind::Physical) * 100 + int(i))->isEnabled(), event);
            if (!event)
                QVERIFY(
                    integrators->itemData(integrators->findData(int(i)), Qt::ToolTipRole).toString().contains("exact"));
        }
        options.integrator = Integrator::SymplecticEuler;
        panel.showOptions(sceneInfo(SceneId::ManyBalls), options);
        for (Integrator i : allIntegrators())
            QCOMPARE(item(integrators, int(i))->isEnabled(),
                     i != Integrator::Event && i != Integrator::ImplicitEuler && i != Integrator::ImplicitMidpoint);
        panel.showOptions(sceneInfo(SceneId::Box3d), options);
        for (Integrator i : allIntegrators())
            QVERIFY(item(integrators, int(i))->isEnabled());
    }

    void streetIsDrawnAsRoadHousesAndCars()
    {
        const SceneLayout plain = layoutFor(streetSpec(10, 0));
        QVERIFY(plain.street);
        QCOMPARE(plain.balls, 10);
        QCOMPARE(plain.region.min().x(), plain.street->xTop);
        QCOMPARE(plain.region.max().x(), plain.street->xFoot);
        const SceneGeometry g = buildSceneGeometry(plain, "m");
        QVERIFY(g.floor.size() > 36 * plain.street->boxes.size() / 2); // the road, crossings, sidewalks, wall
        QVERIFY(!g.cutaway.empty());                                   // the near houses
        QVERIFY(g.walls.empty());                                      // no box around the street
        bool foot = false;
        for (const SceneLabel& l : g.labels)
            foot = foot || (l.text == "foot" && std::abs(l.at.x() - float(plain.street->xFoot)) < 1e-3f);
        QVERIFY(foot);
        // Six parked cars: six boxes of 12 triangles more.
        const SceneGeometry withCars = buildSceneGeometry(layoutFor(streetSpec(10, 6)), "m");
        QCOMPARE(withCars.floor.size(), g.floor.size() + 6 * 36);
        for (const FlatVertex& v : withCars.floor)
            QVERIFY(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.r));
    }

    void footShotLooksUpTheWholeStreetFromBeyondTheFoot()
    {
        const street::Layout s = defaultStreet();
        const QSize view(800, 600);
        const OrbitCamera camera = cameraAt(s, StreetShot::Foot, view);
        QVERIFY(camera.eye().x() > float(s.xFoot)); // past the foot
        QVERIFY(camera.eye().y() < 3.0f);           // low on the road
        QPointF top, foot;
        QVERIFY(camera.project(QVector3D(float(s.xTop) + 2.0f, float(s.height), 0.0f), view, top));
        QVERIFY(camera.project(QVector3D(float(s.xFoot) - 1.0f, 0.0f, 0.0f), view, foot));
        QVERIFY(onScreen(top, view));
        QVERIFY(onScreen(foot, view));
        QVERIFY(top.y() < foot.y()); // the top of the hill above the foot in the picture
    }

    void sideShotShowsTheWholeStreetTopLeftFootRightFromAbove()
    {
        const street::Layout s = defaultStreet();
        const QSize view(800, 600);
        const OrbitCamera camera = cameraAt(s, StreetShot::Side, view);
        QVERIFY(camera.eye().z() > float(s.width)); // out beside the street
        QPointF top, foot;
        QVERIFY(camera.project(QVector3D(float(s.xTop), float(s.height), 0.0f), view, top));
        QVERIFY(camera.project(QVector3D(float(s.xFoot), 0.0f, 0.0f), view, foot));
        QVERIFY(onScreen(top, view) && onScreen(foot, view));
        QVERIFY(top.x() < foot.x() && top.y() < foot.y());
        // From above and a little downhill: the roadway shows its width, so the flood is seen on
        // it, not only its profile (a level view drew the road as a line).
        QVERIFY(camera.pitch() >= 20.0f);
        QVERIFY(camera.eye().x() > 0.5f * float(s.xTop + s.xFoot));
        const float mid = 0.5f * float(s.xTop + s.xFoot), road = float(s.roadY(mid));
        QPointF nearKerb, farKerb;
        QVERIFY(camera.project(QVector3D(mid, road, 0.5f * float(s.width)), view, nearKerb));
        QVERIFY(camera.project(QVector3D(mid, road, -0.5f * float(s.width)), view, farKerb));
        QVERIFY2(nearKerb.y() - farKerb.y() > 6.0, qPrintable(QString::number(nearKerb.y() - farKerb.y())));
        // Framed on the street, not its bounding box, in a wide view and in the window's tall
        // one: the road from the top to 20 m past the foot, and the top's label, are in the
        // picture, and the road spans most of its width (a tenth of the picture was used). So
        // are the back wall's corners across the top: lecture mode's view at 1280x720, 485 px by
        // 500, cut it and the first house at its left edge.
        for (const QSize size : {view, QSize(840, 990), QSize(485, 500)}) {
            const OrbitCamera c = cameraAt(s, StreetShot::Side, size);
            QPointF top2, run, label;
            QVERIFY(c.project(QVector3D(float(s.xTop), float(s.height), 0.0f), size, top2));
            QVERIFY(c.project(QVector3D(float(s.xFoot) + 20.0f, 0.0f, 0.0f), size, run));
            QVERIFY(c.project(QVector3D(float(s.xTop), float(s.height + ab::ui::kTopLabelHeight), 0.0f), size, label));
            QVERIFY(onScreen(top2, size) && onScreen(run, size) && onScreen(label, size));
            QVERIFY2(run.x() - top2.x() > 0.75 * size.width(), qPrintable(QString::number(run.x() - top2.x())));
            for (const street::Box& b : s.boxes)
                if (b.kind == street::ItemKind::BackWall)
                    for (const float z : {-1.0f, 1.0f})
                        for (const float y : {-1.0f, 1.0f}) {
                            const QVector3D corner(float(b.centre.x() - b.half.x()),
                                                   float(b.centre.y() + y * b.half.y()), z * float(b.half.z()));
                            QPointF at;
                            QVERIFY(c.project(corner, size, at));
                            // Inside the fit's margin (2.5 % of the width and height): not at the edge.
                            const QRectF inner = QRectF(QPointF(0, 0), QSizeF(size))
                                                     .adjusted(0.02 * size.width(), 0.02 * size.height(),
                                                               -0.02 * size.width(), -0.02 * size.height());
                            QVERIFY2(inner.contains(at), qPrintable(QString("%1, %2").arg(at.x()).arg(at.y())));
                        }
        }
    }

    void floodShotFollowsTheFrontAndIgnoresGoneBallsAndALoneRunaway()
    {
        const street::Layout s = defaultStreet();
        std::vector<float> xyz;
        for (int i = 0; i < 400; ++i) // the flood: x from 0 to 39.9
            xyz.insert(xyz.end(), {float(i) * 0.1f, 60.0f, 0.0f});
        xyz.insert(xyz.end(), {200.0f, 10.0f, 0.0f});                // one runaway far ahead
        xyz.insert(xyz.end(), {float(s.xFoot) + 1.0f, 0.03f, 0.0f}); // one gone past the foot
        const std::optional<float> front = floodFront(s, xyz);
        QVERIFY(front);
        QVERIFY(*front > 38.0f && *front < 40.0f);
        const CameraPose near = streetPose(s, StreetShot::Flood, 1.3f, 40.0f);
        const CameraPose far = streetPose(s, StreetShot::Flood, 1.3f, 150.0f);
        QVERIFY(far.target.x() - near.target.x() > 100.0f); // the camera moved down with the front
        QVERIFY(ballHidden(s, float(s.xFoot) + 0.01f));
        QVERIFY(!ballHidden(s, float(s.xFoot) - 0.01f));
        QVERIFY(!floodFront(s, {float(s.xFoot) + 1.0f, 0.0f, 0.0f})); // nobody on the street
    }

    void navigatorShowsTheStreetsEquationsWithNumbers()
    {
        RunSpec spec = streetSpec();
        spec.params.parse("mu", "0");
        const QString smooth = StreetEquations::html(spec);
        // Smooth (mu = 0): sliding, a = g sin(17 deg) = 9.82 * 0.2924 = 2.87 m/s^2.
        QVERIFY(smooth.contains("St2"));
        QVERIFY(smooth.contains("2.87"));
        QVERIFY(smooth.contains(RunOptionsPanel::noReportModelReason().toHtmlEscaped()));
        // mu = 0.5 >= q tan(theta) / (1 + q) = 0.0874: rolling, a = 2.87 / 1.4 = 2.05 m/s^2.
        spec.params.parse("mu", "0.5");
        const QString rough = StreetEquations::html(spec);
        QVERIFY(rough.contains("St1"));
        QVERIFY(rough.contains("2.05"));
        QVERIFY(rough.contains("0.0874"));
        QVERIFY(StreetEquations::html(RunSpec(SceneId::ManyBalls)).isEmpty());
    }
};

QTEST_MAIN(UiStreet)
#include "test_ui_street.moc"
