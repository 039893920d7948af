// SPDX-License-Identifier: MIT
// The Tools dialogs on the offscreen platform: the accuracy study and the stability suite
// run a small configuration on their worker to the end and fill their tables row for row;
// Cancel stops them early, and then nothing can be exported; failed and degraded rows are
// coloured (readable on a dark palette too) and marked in text; a scene without a closed
// form says so instead of offering the study; a cancelled CSV export leaves no file.
#include "support/sim_helpers.h"

#include "ui/charts/chart_data_csv.h"
#include "ui/charts/motion_track.h"
#include "ui/export_files.h"
#include "ui/main_window.h"
#include "ui/tools/stability_dialog.h"
#include "ui/tools/study_dialog.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace ab;
using namespace ab::ui;

namespace {

QStringList readLines(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

// Every entry of the folder: a cancelled or refused export leaves not even a temporary file.
QStringList entries(const QTemporaryDir& dir)
{
    return QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
}

// Calls `cancel` as soon as the first progress arrives.
void cancelOnFirstProgress(BackgroundJob& job, const std::function<void()>& cancel)
{
    QObject::connect(&job, &BackgroundJob::progress, &job, [cancel](int done, int) {
        if (done >= 1)
            cancel();
    });
}

double luminance(const QColor& c)
{
    return 0.2126 * c.redF() + 0.7152 * c.greenF() + 0.0722 * c.blueF();
}

} // namespace

class ToolsTest : public QObject {
    Q_OBJECT

private slots:
    void studyDefaultsShowTheOrdersBesideStepEndImpacts()
    {
        // bounce1d has no drag: the study adds b = 0.01, where Verlet and RK4 are not exact
        // (a parabola they would follow to round-off). From dt = 10 to 1 the located
        // impacts' errors then fall by 10^2 and 10^4 (orders 2 and 4, measured with
        // amazeballs-cli study bounce1d --set b=0.01), the step-end impacts' by about 10^0.7.
        StudyDialog dialog(testing::spec(SceneId::Bounce1d, {}, ModelKind::Physical));
        QVERIFY(dialog.dragField());
        QCOMPARE(dialog.dragField()->text(), QString("0.01"));
        dialog.setSweep(600.0, 10.0, 1.0, 1, 1);
        dialog.start();
        dialog.job().waitForFinished();
        QVERIFY(dialog.result() && dialog.result()->complete);
        auto order = [&](ab::Integrator integrator, ab::ImpactMode impacts) {
            double coarse = 0.0, fine = 0.0;
            for (const study::Row& row : dialog.result()->rows)
                if (row.method.integrator == integrator && row.method.impacts == impacts)
                    (row.dt > 5.0 ? coarse : fine) = row.relativeError;
            return std::log10(coarse / fine); // one decade of dt
        };
        const double verlet = order(ab::Integrator::Verlet, ab::ImpactMode::Located);
        const double rk4 = order(ab::Integrator::Rk4, ab::ImpactMode::Located);
        const double stepEnd = order(ab::Integrator::Rk4, ab::ImpactMode::StepEnd);
        QVERIFY2(std::abs(verlet - 2.0) < 0.3, qPrintable(QString::number(verlet)));
        QVERIFY2(std::abs(rk4 - 4.0) < 0.3, qPrintable(QString::number(rk4)));
        QVERIFY2(stepEnd < 1.3, qPrintable(QString::number(stepEnd)));
        // The Zeno time as a reader takes it down: six significant digits and its unit.
        const QString reference = QString::fromStdString(dialog.result()->reference);
        const QRegularExpressionMatch zeno = QRegularExpression("Zeno time ([0-9.]+) step").match(reference);
        QVERIFY2(zeno.hasMatch(), qPrintable(reference));
        QVERIFY2(zeno.captured(1).remove('.').size() <= 6, qPrintable(reference));
    }

    void studyRunsASmallSweepToTheEndAndExportsIt()
    {
        const RunSpec spec = testing::spec(SceneId::Bounce1d, {}, ModelKind::Physical);
        StudyDialog dialog(spec);
        QVERIFY(dialog.available());
        QVERIFY(dialog.dragField());
        dialog.dragField()->setText("0"); // the scene as it is: the event integrator joins
        const std::size_t methods = study::allMethods(spec).size();
        QCOMPARE(dialog.sweep().methods.size(), methods);
        dialog.setSweep(200.0, 1.0, 0.1, 1, 1); // dt = 1 and 0.1: two steps per method
        dialog.start();
        QVERIFY(dialog.running());
        QVERIFY(!dialog.exportCsvButton()->isEnabled());
        dialog.job().waitForFinished();

        QVERIFY(dialog.result() && dialog.result()->complete);
        QCOMPARE(dialog.table()->rowCount(), static_cast<int>(2 * methods));
        QCOMPARE(dialog.table()->columnCount(), 7);
        QCOMPARE(dialog.table()->headerData(0, Qt::Horizontal).toString(), QString("integrator"));
        QCOMPARE(dialog.tableView()->model()->rowCount(), static_cast<int>(2 * methods));
        // Event-driven integration is exact: its error is round-off at any sampling interval.
        for (const study::Row& row : dialog.table()->rows())
            if (row.method.exact())
                QVERIFY2(row.relativeError <= 1e-12, qPrintable(QString::number(row.relativeError)));
        QVERIFY(!dialog.chartView()->chart()->series().isEmpty());
        QVERIFY(dialog.exportCsvButton()->isEnabled());

        QTemporaryDir dir;
        const QString csv = dir.filePath("study.csv"), png = dir.filePath("study.png");
        dialog.exportCsvTo(csv);
        dialog.exportChartTo(png);
        const QStringList lines = readLines(csv);
        QVERIFY(lines.value(0).startsWith("integrator,impacts,dt,max_error,cpu_seconds"));
        QCOMPARE(lines.size(), static_cast<int>(2 * methods) + 1);
        QVERIFY(QImage(png).width() > 0);
    }

    void cancellingTheStudyStopsEarlyAndExportsNothing()
    {
        const RunSpec spec = testing::spec(SceneId::Bounce1d, {}, ModelKind::Physical);
        const int total = 17 * static_cast<int>(study::allMethods(spec).size());
        StudyDialog dialog(spec);
        dialog.setSweep(2000.0, 1.0, 1e-4, 4, 1); // 17 steps per method, the finest 2e7 steps
        cancelOnFirstProgress(dialog.job(), [&] { dialog.cancel(); });
        dialog.start();
        dialog.job().waitForFinished();
        QVERIFY(dialog.result());
        QVERIFY(!dialog.result()->complete);
        QVERIFY(dialog.table()->rowCount() >= 1);
        QVERIFY(dialog.table()->rowCount() < total);
        QCOMPARE(static_cast<std::size_t>(dialog.table()->rowCount()), dialog.result()->rows.size());
        QVERIFY(!dialog.exportCsvButton()->isEnabled());
        QVERIFY(!dialog.exportChartButton()->isEnabled());
        QTemporaryDir dir;
        QVERIFY_THROWS_EXCEPTION(InputError, dialog.exportCsvTo(dir.filePath("study.csv")));
        QVERIFY(entries(dir).isEmpty());
    }

    void aSceneWithoutAClosedFormSaysSoInsteadOfOfferingTheStudy()
    {
        // Box3d with drag has no closed form.
        StudyDialog dialog(testing::spec(SceneId::Box3d, {"b=0.1"}, ModelKind::Physical));
        QVERIFY(!dialog.available());
        QVERIFY(!dialog.unavailableReason().isEmpty());
        bool said = false;
        for (QLabel* label : dialog.findChildren<QLabel*>())
            said = said || label->text().contains("No accuracy study");
        QVERIFY(said);
        const auto buttons = dialog.findChildren<QPushButton*>();
        QCOMPARE(buttons.size(), 1); // Close only
        dialog.start();              // nothing to start
        QVERIFY(!dialog.running());
    }

    void suiteRunsOneCaseToTheEndAndExportsIt()
    {
        StabilityDialog dialog(SceneId::Bounce1d);
        dialog.selectCase("coarse-step");
        dialog.start();
        dialog.job().waitForFinished();
        const std::size_t expected = stability::suiteRows({stability::findCase("coarse-step")}).size();
        QVERIFY(dialog.complete());
        QCOMPARE(static_cast<std::size_t>(dialog.table()->rowCount()), expected);
        QCOMPARE(dialog.table()->columnCount(), static_cast<int>(StabilityTableModel::ColumnCount));
        QCOMPARE(dialog.table()->headerData(StabilityTableModel::VerdictColumn, Qt::Horizontal).toString(),
                 QString("verdict"));
        // Verlet, RK4 and event-driven follow the constant-gravity parabola exactly (their
        // truncation error vanishes for a constant force): the flight error is round-off
        // (below 1e-9 of the scene's length unit) at every step tried.
        int exact = 0;
        for (const stability::RowResult& r : dialog.table()->rows())
            if (r.integrator == "verlet" || r.integrator == "rk4" || r.integrator == "event") {
                QVERIFY(r.referenceError);
                QVERIFY2(*r.referenceError < 1e-9, qPrintable(QString::fromStdString(r.setting)));
                ++exact;
            }
        QVERIFY(exact >= 3);

        QTemporaryDir dir;
        const QString csv = dir.filePath("suite.csv"), md = dir.filePath("suite.md");
        dialog.exportCsvTo(csv);
        dialog.exportMarkdownTo(md);
        QVERIFY(readLines(csv).value(0).startsWith(
            "case,model,integrator,max_energy_gain,max_penetration,escaped,nonfinite,verdict"));
        const QString markdown = readLines(md).join('\n');
        QVERIFY(markdown.contains("## Stability limits"));
        QVERIFY(markdown.contains("## Cases"));
        QVERIFY(markdown.contains("| rk4 | 2.829"));
    }

    void failedAndDegradedRowsAreHighlightedAndMarked()
    {
        // Stage 1 at 100 times the report's step fails, at its own step it is degraded.
        StabilityDialog dialog(SceneId::Bounce1d);
        dialog.selectCase("coarse-step");
        dialog.start();
        dialog.job().waitForFinished();
        QVERIFY(dialog.complete());
        const QColor base = QGuiApplication::palette().color(QPalette::Base);
        int failed = 0, degraded = 0;
        StabilityTableModel* model = dialog.table();
        for (int i = 0; i < model->rowCount(); ++i) {
            const Verdict v = verdictOf(model->rows()[static_cast<std::size_t>(i)]);
            const QVariant background = model->index(i, 0).data(Qt::BackgroundRole);
            const QString text = model->index(i, StabilityTableModel::VerdictColumn).data().toString();
            if (v == Verdict::Failed) {
                ++failed;
                QCOMPARE(background.value<QColor>(), verdictBackground(Verdict::Failed, base));
                QVERIFY(text.contains("failed"));
            } else if (v == Verdict::Degraded) {
                ++degraded;
                QCOMPARE(background.value<QColor>(), verdictBackground(Verdict::Degraded, base));
                QVERIFY(text.contains("degraded"));
            } else {
                QVERIFY(!background.isValid());
            }
        }
        QVERIFY(failed >= 1);
        QVERIFY(degraded >= 1);
        // Red leans red and amber leans yellow on a light and on a dark base, and the dark
        // theme's highlight stays dark enough for its light text.
        for (const QColor& b : {QColor(Qt::white), QColor(0x2b, 0x2b, 0x2b)}) {
            const QColor red = verdictBackground(Verdict::Failed, b), amber = verdictBackground(Verdict::Degraded, b);
            QVERIFY(red.red() > red.green() && red.red() > red.blue());
            QVERIFY(amber.red() > amber.blue() && amber.green() > amber.blue());
            QVERIFY(red != amber);
        }
        QVERIFY(luminance(verdictBackground(Verdict::Failed, QColor(0x2b, 0x2b, 0x2b))) < 0.35);
        QVERIFY(luminance(verdictBackground(Verdict::Degraded, QColor(0x2b, 0x2b, 0x2b))) < 0.45);

        // The verdict filter shows the failed rows only; the text filter matches the model.
        dialog.verdictChoice()->setCurrentIndex(dialog.verdictChoice()->findData(static_cast<int>(Verdict::Failed)));
        QCOMPARE(dialog.filter()->rowCount(), failed);
        dialog.verdictChoice()->setCurrentIndex(0);
        dialog.filterText()->setText("report");
        QVERIFY(dialog.filter()->rowCount() >= 1);
        for (int i = 0; i < dialog.filter()->rowCount(); ++i)
            QCOMPARE(dialog.filter()->index(i, StabilityTableModel::Model).data().toString(), QString("report"));
        // Sorting by verdict puts the worst last.
        dialog.filterText()->clear();
        dialog.tableView()->sortByColumn(StabilityTableModel::VerdictColumn, Qt::AscendingOrder);
        const int last = dialog.filter()->rowCount() - 1;
        QVERIFY(dialog.filter()->index(last, StabilityTableModel::VerdictColumn).data().toString().contains("failed"));
    }

    void cancellingTheSuiteStopsEarlyAndExportsNothing()
    {
        StabilityDialog dialog(SceneId::Bounce1d);
        dialog.scope()->setCurrentIndex(0); // every case
        cancelOnFirstProgress(dialog.job(), [&] { dialog.cancel(); });
        dialog.start();
        dialog.job().waitForFinished();
        QVERIFY(!dialog.complete());
        QVERIFY(static_cast<std::size_t>(dialog.table()->rowCount()) < stability::suiteRows().size());
        QVERIFY(!dialog.exportCsvButton()->isEnabled());
        QVERIFY(!dialog.exportMarkdownButton()->isEnabled());
        QTemporaryDir dir;
        QVERIFY_THROWS_EXCEPTION(InputError, dialog.exportCsvTo(dir.filePath("suite.csv")));
        QVERIFY_THROWS_EXCEPTION(InputError, dialog.exportMarkdownTo(dir.filePath("suite.md")));
        QVERIFY(entries(dir).isEmpty());
    }

    void aCancelledCsvExportLeavesNoFile()
    {
        // 20000 samples: progress every 4096 lines; cancelled at the first report.
        MotionTrack track;
        for (long long i = 0; i <= 20000; ++i)
            track.add(i, 0.01 * static_cast<double>(i), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1, 0),
                      ab::ConservationSample{});
        QTemporaryDir dir;
        const QString path = dir.filePath("track.csv");
        ab::ui::ChartData data;
        data.run = &track;
        data.axes = 1;
        int calls = 0;
        QVERIFY_THROWS_EXCEPTION(ExportCancelled, saveChartCsv(data, path, [&](std::size_t, std::size_t) {
                                     ++calls;
                                     return false;
                                 }));
        QCOMPARE(calls, 1);
        QVERIFY(entries(dir).isEmpty());

        std::size_t lastDone = 0, lastTotal = 0;
        bool increasing = true;
        saveChartCsv(data, path, [&](std::size_t done, std::size_t total) {
            increasing = increasing && done > lastDone;
            lastDone = done;
            lastTotal = total;
            return true;
        });
        QVERIFY(increasing);
        QCOMPARE(lastTotal, track.size() + 1);
        QCOMPARE(lastDone, lastTotal);
        QCOMPARE(readLines(path).size(), static_cast<int>(track.size()) + 1);
        QCOMPARE(entries(dir), QStringList{"track.csv"});
    }

    void theWindowHasAToolsMenuWithBothDialogs()
    {
        MainWindow window;
        QMenu* tools = nullptr;
        for (QAction* a : window.menuBar()->actions())
            if (a->menu() && a->text().remove('&') == "Tools")
                tools = a->menu();
        QVERIFY(tools);
        QCOMPARE(tools->actions().size(), 2);
        tools->actions()[1]->trigger();
        auto* suite = window.findChild<StabilityDialog*>();
        QVERIFY(suite);
        QCOMPARE(suite->scope()->itemText(1),
                 QString("The rows of %1").arg(QString::fromStdString(sceneInfo(window.scene()).key)));
        tools->actions()[0]->trigger();
        QVERIFY(window.findChild<StudyDialog*>());
    }
};

QTEST_MAIN(ToolsTest)
#include "test_ui_tools.moc"
