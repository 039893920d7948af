// SPDX-License-Identifier: MIT
#include "study_dialog.h"

#include "dialog_fit.h"

#include "ui/charts/chart_export.h"
#include "ui/charts/work_precision_chart.h"
#include "ui/i18n/core_text.h"

#include "core/io/atomic_file.h"
#include "core/reference/reference.h"

#include <QChart>
#include <QChartView>
#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QSplitter>
#include <QStandardPaths>
#include <QTableView>
#include <QVBoxLayout>

#include <cmath>

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

double positiveField(const QLineEdit* field, const char* name)
{
    bool ok = false;
    const double x = field->text().trimmed().toDouble(&ok);
    if (!ok || !(x > 0.0) || !std::isfinite(x))
        throw InputError(std::string(name) + ": '" + field->text().toStdString() + "' is not a positive number");
    return x;
}

QLineEdit* numberField(double value)
{
    auto* field = new QLineEdit(qs(formatNumber(value)));
    field->setMaximumWidth(90);
    return field;
}

} // namespace

StudyDialog::StudyDialog(const RunSpec& spec, QWidget* parent) : QDialog(parent), spec_(spec)
{
    const SceneInfo& info = sceneInfo(spec.scene);
    setWindowTitle(tr("Accuracy study: %1").arg(qs(info.key)));
    try {
        options_ = study::defaultOptions(spec);
    } catch (const InputError& e) {
        unavailable_ = refusalText(e);
    }
    auto* layout = scrollingContent(this);
    if (!options_) {
        layout->addWidget(buildUnavailable());
        fitToScreen(this, QSize(560, 220));
        return;
    }
    auto* intro = new QLabel(introText(spec));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    layout->addWidget(buildSweepRow());

    auto* progressRow = new QHBoxLayout;
    progress_ = new QProgressBar;
    progress_->setFormat(tr("%v of %m runs"));
    progress_->setTextVisible(false); // until a run gives the count
    status_ = new QLabel(tr("Press Run to start."));
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(status_, 2);
    layout->addLayout(progressRow);

    chart_ = new QChartView;
    chart_->setRenderHint(QPainter::Antialiasing);
    chart_->setMinimumHeight(420); // a log axis of 16 decades elides its labels when shorter
    model_ = new StudyTableModel(this);
    model_->setUnits(qs(info.timeUnit), qs(info.lengthUnit));
    auto* sorter = new QSortFilterProxyModel(this);
    sorter->setSourceModel(model_);
    sorter->setSortRole(Qt::UserRole);
    table_ = new QTableView;
    table_->setModel(sorter);
    table_->setSortingEnabled(true);
    table_->sortByColumn(-1, Qt::AscendingOrder); // the order they ran in until a header is clicked
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->verticalHeader()->setVisible(false);
    table_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    auto* split = new QSplitter(Qt::Vertical);
    split->addWidget(chart_);
    split->addWidget(table_);
    split->setSizes({480, 220});
    layout->addWidget(split, 1);

    auto* buttons = new QHBoxLayout;
    exportCsv_ = new QPushButton(tr("Export CSV..."));
    exportChart_ = new QPushButton(tr("Export chart..."));
    auto* close = new QPushButton(tr("Close"));
    buttons->addWidget(exportCsv_);
    buttons->addWidget(exportChart_);
    buttons->addStretch(1);
    buttons->addWidget(close);
    layout->addLayout(buttons);
    connect(exportCsv_, &QPushButton::clicked, this, [this] { exportInteractively(false); });
    connect(exportChart_, &QPushButton::clicked, this, [this] { exportInteractively(true); });
    connect(close, &QPushButton::clicked, this, &QDialog::close);
    connect(&job_, &BackgroundJob::progress, progress_, [this](int done, int total) {
        progress_->setMaximum(total);
        progress_->setValue(done);
    });
    clearChart();
    setRunning(false);
    fitToScreen(this, QSize(1000, 900));
}

QString StudyDialog::introText(const RunSpec& spec)
{
    const SceneInfo& info = sceneInfo(spec.scene);
    const QString what = tr("Error against run time of the physical model's integrators on %1, each run measured "
                            "against the scene's exact motion, with impacts located inside the step and found at "
                            "its end side by side. Lower left is better; where a line is straight its slope is the "
                            "order, and a steeper line is a higher order.")
                             .arg(qs(info.title));
    if (spec.scene == SceneId::Bounce1d)
        return what + " " +
               tr("In free fall the flight is a parabola, which Verlet and RK4 follow exactly; the linear drag b "
                  "below (%1 when the scene has none) gives every integrator an error to show. With b = 0 the "
                  "study is of the scene as it is.")
                   .arg(qs(formatNumber(kStudyDrag)));
    return what + " " +
           tr("Between impacts the flight is a parabola, which Verlet and RK4 follow exactly: their error is the "
              "impacts' alone, and round-off at the finest steps.");
}

QWidget* StudyDialog::buildUnavailable()
{
    const SceneInfo& info = sceneInfo(spec_.scene);
    auto* page = new QWidget;
    auto* layout = new QVBoxLayout(page);
    auto* text = new QLabel(
        tr("<p><b>No accuracy study for %1 with these constants.</b></p>"
           "<p>The study measures each integrator's error against the scene's exact motion, and here there is "
           "none: %2</p>"
           "<p>It applies to bounce1d (no drag, linear or quadratic drag), box3d without drag or friction, and "
           "two-balls in the symmetric head-on meeting. The stability suite (Tools menu) covers every scene.</p>")
            .arg(qs(info.key), unavailable_.toHtmlEscaped()));
    text->setWordWrap(true);
    text->setTextFormat(Qt::RichText);
    layout->addWidget(text);
    layout->addStretch(1);
    auto* close = new QPushButton(tr("Close"));
    connect(close, &QPushButton::clicked, this, &QDialog::close);
    auto* row = new QHBoxLayout;
    row->addStretch(1);
    row->addWidget(close);
    layout->addLayout(row);
    return page;
}

QWidget* StudyDialog::buildSweepRow()
{
    const SceneInfo& info = sceneInfo(spec_.scene);
    const QString unit = qs(info.timeUnit);
    auto* row = new QWidget;
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    tEnd_ = numberField(options_->tEnd);
    dtMax_ = numberField(options_->dts.front());
    dtMin_ = numberField(options_->dts.back());
    perDecade_ = new QSpinBox;
    perDecade_->setRange(1, 20);
    perDecade_->setValue(3);
    repeats_ = new QSpinBox;
    repeats_->setRange(1, 100);
    repeats_->setValue(options_->repeats);
    auto label = [&](const QString& text, QWidget* field, const QString& tip) {
        auto* l = new QLabel(text);
        l->setBuddy(field);
        field->setToolTip(tip);
        h->addWidget(l);
        h->addWidget(field);
    };
    label(tr("&t end (%1)").arg(unit), tEnd_, tr("Each run goes from t = 0 to this time."));
    label(tr("dt &from"), dtMax_, tr("The coarsest step (the sampling interval for event-driven)."));
    label(tr("&to"), dtMin_, tr("The finest step; steps between are spaced evenly on a log scale."));
    label(tr("&per decade"), perDecade_, tr("Steps tried per factor of ten."));
    label(tr("&repeats"), repeats_, tr("Timed repeats of each run; the median CPU time is shown."));
    if (spec_.scene == SceneId::Bounce1d && spec_.params.real("c") == 0.0) {
        const double b = spec_.params.real("b") > 0.0 ? spec_.params.real("b") : kStudyDrag;
        drag_ = numberField(b);
        drag_->setObjectName("studyDrag");
        label(tr("&drag b (%1)").arg(qs(spec_.params.spec("b").unit)), drag_,
              tr("Linear air drag, force -b v (report equation 3.1); 0: none, where Verlet and RK4 are exact."));
    }
    h->addStretch(1);
    run_ = new QPushButton(tr("Run"));
    run_->setDefault(true);
    cancel_ = new QPushButton(tr("Cancel"));
    h->addWidget(run_);
    h->addWidget(cancel_);
    connect(run_, &QPushButton::clicked, this, &StudyDialog::start);
    connect(cancel_, &QPushButton::clicked, this, &StudyDialog::cancel);
    return row;
}

study::Options StudyDialog::sweep() const
{
    study::Options o = *options_;
    o.tEnd = positiveField(tEnd_, "t end");
    const double dtMax = positiveField(dtMax_, "dt from");
    const double dtMin = positiveField(dtMin_, "dt to");
    // The same limits as `amazeballs-cli study`.
    if (dtMin > dtMax)
        throw InputError("dt to: " + formatNumber(dtMin) + " is larger than dt from " + formatNumber(dtMax));
    o.dts = study::logSweep(dtMax, dtMin, perDecade_->value());
    if (o.dts.size() > 200)
        throw InputError("dt to: the sweep has more than 200 steps to try");
    if (o.tEnd / o.dts.back() > 1e9)
        throw InputError("dt to: " + formatNumber(dtMin) + " needs more than 1e9 steps to reach t end " +
                         formatNumber(o.tEnd));
    o.repeats = repeats_->value();
    if (drag_) {
        o.base.params.parse("b", drag_->text().trimmed().toStdString()); // InputError naming b
        o.methods = study::allMethods(o.base);                           // the event integrator flies without drag only
        reference::makeReference(o.base, o.tEnd);
    }
    return o;
}

void StudyDialog::setSweep(double tEnd, double dtMax, double dtMin, int perDecade, int repeats)
{
    tEnd_->setText(qs(formatNumber(tEnd)));
    dtMax_->setText(qs(formatNumber(dtMax)));
    dtMin_->setText(qs(formatNumber(dtMin)));
    perDecade_->setValue(perDecade);
    repeats_->setValue(repeats);
}

void StudyDialog::start()
{
    if (!options_ || job_.running())
        return;
    study::Options o = *options_;
    try {
        o = sweep();
    } catch (const InputError& e) {
        status_->setText(refusalText(e));
        return;
    }
    result_.reset();
    model_->clear();
    clearChart();
    progress_->setMaximum(static_cast<int>(o.dts.size() * o.methods.size()));
    progress_->setTextVisible(true);
    progress_->setValue(0);
    status_->setText(tr("Running..."));
    auto out = std::make_shared<study::Result>();
    connect(
        &job_, &BackgroundJob::finished, this, [this, out] { finished(out); }, Qt::SingleShotConnection);
    job_.start([this, o, out](BackgroundJob& job) {
        *out = study::runStudy(
            o,
            [this, &job](std::size_t done, std::size_t total, const study::Row& row) {
                const int d = static_cast<int>(done), t = static_cast<int>(total);
                QMetaObject::invokeMethod(
                    this, [this, row, d, t] { rowDone(row, d, t); }, Qt::QueuedConnection);
                job.report(done, total);
            },
            [&job] { return job.cancelled(); });
    });
    setRunning(true);
}

void StudyDialog::cancel()
{
    if (!job_.running())
        return;
    job_.cancel();
    status_->setText(tr("Cancelling..."));
}

void StudyDialog::rowDone(const study::Row& row, int done, int total)
{
    model_->append(row);
    status_->setText(
        tr("%1 of %2: %3 at dt %4").arg(done).arg(total).arg(qs(row.method.label()), qs(formatNumber(row.dt))));
}

void StudyDialog::finished(const std::shared_ptr<study::Result>& result)
{
    setRunning(false);
    if (job_.error()) {
        try {
            std::rethrow_exception(job_.error());
        } catch (const std::exception& e) {
            status_->setText(tr("The study stopped: %1").arg(QString::fromUtf8(e.what())));
        }
        return;
    }
    result_ = *result; // its rows are in the table already: they were queued before the end
    showChart(*result_);
    status_->setText(
        result_->complete
            ? tr("Done: %1 runs against %2.").arg(result_->rows.size()).arg(qs(result_->reference))
            : tr("Cancelled after %1 runs; nothing to export from a partial study.").arg(result_->rows.size()));
    setRunning(false);
}

void StudyDialog::showChart(const study::Result& result)
{
    QChart* old = chart_->chart();
    chart_->setChart(makeWorkPrecisionChart(result).release()); // the view owns it now
    delete old;
}

void StudyDialog::clearChart()
{
    QChart* old = chart_->chart();
    auto* empty = new QChart;
    empty->setTitle(tr("The chart appears when the study is done."));
    chart_->setChart(empty);
    delete old;
}

void StudyDialog::setRunning(bool running)
{
    run_->setEnabled(!running);
    cancel_->setEnabled(running);
    for (QWidget* w : std::initializer_list<QWidget*>{tEnd_, dtMax_, dtMin_, perDecade_, repeats_, drag_})
        if (w)
            w->setEnabled(!running);
    const bool exportable = !running && result_ && result_->complete && !result_->rows.empty();
    exportCsv_->setEnabled(exportable);
    exportChart_->setEnabled(exportable);
}

void StudyDialog::exportCsvTo(const QString& path) const
{
    if (!result_ || !result_->complete)
        throw InputError(path.toStdString() + ": no complete study to export");
    writeFileAtomically(path.toStdString(), [this](std::ostream& out) { study::writeCsv(out, *result_); });
}

void StudyDialog::exportChartTo(const QString& path) const
{
    if (!result_ || !result_->complete)
        throw InputError(path.toStdString() + ": no complete study to export");
    exportChart(chart_->chart(), path, QSize(1200, 800));
}

void StudyDialog::exportInteractively(bool chart)
{
    if (lastDirectory_.isEmpty())
        lastDirectory_ = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString base = lastDirectory_ + "/" + qs(sceneInfo(spec_.scene).key) + "-study";
    const QString path =
        chart ? QFileDialog::getSaveFileName(this, tr("Export chart"), base + ".png",
                                             tr("PNG image (*.png);;SVG image (*.svg)"))
              : QFileDialog::getSaveFileName(this, tr("Export CSV"), base + ".csv", tr("CSV table (*.csv)"));
    if (path.isEmpty())
        return;
    lastDirectory_ = QFileInfo(path).absolutePath();
    try {
        chart ? exportChartTo(path) : exportCsvTo(path);
        status_->setText(tr("Saved %1").arg(path));
    } catch (const InputError& e) {
        QMessageBox::warning(this, tr("Export failed"), QString::fromUtf8(e.what()));
    }
}

void StudyDialog::closeEvent(QCloseEvent* event)
{
    job_.cancel(); // the job's destructor waits for the worker, which stops within a few thousand steps
    QDialog::closeEvent(event);
}

} // namespace ab::ui
