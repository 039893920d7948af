// SPDX-License-Identifier: MIT
#include "stability_dialog.h"

#include "dialog_fit.h"

#include "core/io/atomic_file.h"

#include <QCloseEvent>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableView>
#include <QVBoxLayout>

#include <sstream>

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

// The rows of a scope (see StabilityDialog::scope), built on the worker: some cases make
// large start states.
std::vector<stability::CaseRow> rowsOf(int scope, const std::string& caseName, SceneId scene)
{
    if (scope == 0)
        return stability::suiteRows();
    if (scope == 1) {
        std::vector<stability::CaseRow> rows;
        for (stability::CaseRow& row : stability::suiteRows())
            if (row.scene == scene)
                rows.push_back(std::move(row));
        return rows;
    }
    return stability::suiteRows({stability::findCase(caseName)});
}

} // namespace

StabilityDialog::StabilityDialog(SceneId scene, QWidget* parent) : QDialog(parent), scene_(scene)
{
    setWindowTitle(tr("Stability suite"));
    auto* layout = scrollingContent(this);
    auto* intro = new QLabel(tr("Stiff and extreme runs of both models, each checked every step for energy gained, "
                                "penetration, escaped balls and non-finite values. Hover a row for its note."));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    model_ = new StabilityTableModel(this);
    filter_ = new StabilityFilter(this);
    filter_->setSourceModel(model_);
    layout->addWidget(buildControls());

    auto* progressRow = new QHBoxLayout;
    progress_ = new QProgressBar;
    progress_->setFormat(tr("%v of %m rows"));
    progress_->setTextVisible(false); // until a run gives the count
    status_ = new QLabel(tr("Choose what to run and press Run."));
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(status_, 2);
    layout->addLayout(progressRow);

    table_ = new QTableView;
    table_->setModel(filter_);
    table_->setSortingEnabled(true);
    table_->sortByColumn(-1, Qt::AscendingOrder); // the suite's order until a header is clicked
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    // Every column as wide as its widest cell or header, so nothing is cut to "..."; the
    // table scrolls sideways where the dialog is narrower than all of them.
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(false);
    table_->setTextElideMode(Qt::ElideNone);
    table_->verticalHeader()->setVisible(false);
    table_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    table_->setWordWrap(false);
    layout->addWidget(table_, 1);
    layout->addWidget(buildLegend());

    auto* buttons = new QHBoxLayout;
    exportCsv_ = new QPushButton(tr("Export CSV..."));
    exportMarkdown_ = new QPushButton(tr("Export Markdown..."));
    auto* close = new QPushButton(tr("Close"));
    buttons->addWidget(exportCsv_);
    buttons->addWidget(exportMarkdown_);
    buttons->addStretch(1);
    buttons->addWidget(close);
    layout->addLayout(buttons);
    connect(exportCsv_, &QPushButton::clicked, this, [this] { exportInteractively(false); });
    connect(exportMarkdown_, &QPushButton::clicked, this, [this] { exportInteractively(true); });
    connect(close, &QPushButton::clicked, this, &QDialog::close);
    connect(&job_, &BackgroundJob::progress, progress_, [this](int done, int total) {
        progress_->setMaximum(total);
        progress_->setValue(done);
    });
    setRunning(false);
    fitToScreen(this, QSize(1560, 760));
}

QWidget* StabilityDialog::buildControls()
{
    auto* row = new QWidget;
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    scope_ = new QComboBox;
    scope_->addItem(tr("Every case"));
    scope_->addItem(tr("The rows of %1").arg(qs(sceneInfo(scene_).key)));
    for (const stability::StabilityCase& c : stability::stabilityCases()) {
        scope_->addItem(tr("Case %1").arg(qs(c.name)), qs(c.name));
        scope_->setItemData(scope_->count() - 1, qs(c.summary), Qt::ToolTipRole);
    }
    scope_->setCurrentIndex(1);
    auto* runLabel = new QLabel(tr("R&un:"));
    runLabel->setBuddy(scope_);
    run_ = new QPushButton(tr("Run"));
    run_->setDefault(true);
    cancel_ = new QPushButton(tr("Cancel"));
    filterText_ = new QLineEdit;
    filterText_->setPlaceholderText(tr("Filter by case, model, integrator, setting"));
    filterText_->setClearButtonEnabled(true);
    verdict_ = new QComboBox;
    verdict_->addItem(tr("All verdicts"));
    for (Verdict v : {Verdict::Failed, Verdict::Degraded, Verdict::Ok, Verdict::NotRun})
        verdict_->addItem(verdictText(v), static_cast<int>(v));
    h->addWidget(runLabel);
    h->addWidget(scope_);
    h->addWidget(run_);
    h->addWidget(cancel_);
    h->addSpacing(24);
    h->addWidget(filterText_, 1);
    h->addWidget(verdict_);
    connect(run_, &QPushButton::clicked, this, &StabilityDialog::start);
    connect(cancel_, &QPushButton::clicked, this, &StabilityDialog::cancel);
    connect(filterText_, &QLineEdit::textChanged, this, [this](const QString& text) { filter_->setText(text); });
    connect(verdict_, &QComboBox::currentIndexChanged, this, [this](int index) {
        filter_->setVerdict(index <= 0
                                ? std::nullopt
                                : std::optional<Verdict>(static_cast<Verdict>(verdict_->itemData(index).toInt())));
    });
    return row;
}

QWidget* StabilityDialog::buildLegend()
{
    // Two columns of swatch and meaning, the meanings wrapped: a single row ran off a
    // 1600-pixel screen in lecture mode.
    auto* box = new QWidget;
    auto* grid = new QGridLayout(box);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Legend:")), 0, 0, Qt::AlignTop);
    const QColor base = palette().color(QPalette::Base);
    const std::pair<Verdict, QString> entries[] = {
        {Verdict::Failed, tr("energy grew past the limit, a ball escaped, or a value became non-finite")},
        {Verdict::Degraded, tr("within bounds but off: energy gained or penetration beyond tolerance")},
        {Verdict::Ok, tr("held")},
        {Verdict::NotRun, tr("not in this build or not run")},
    };
    int index = 0;
    for (const auto& [verdict, meaning] : entries) {
        auto* swatch = new QLabel(verdictText(verdict));
        const QColor c = verdictBackground(verdict, base);
        swatch->setStyleSheet(QString("QLabel { background: %1; border: 1px solid palette(mid); padding: 1px 6px; }")
                                  .arg((c.isValid() ? c : base).name()));
        auto* text = new QLabel(meaning);
        text->setWordWrap(true);
        const int row = index / 2, column = 1 + 2 * (index % 2);
        grid->addWidget(swatch, row, column, Qt::AlignTop);
        grid->addWidget(text, row, column + 1);
        ++index;
    }
    grid->setColumnStretch(2, 1);
    grid->setColumnStretch(4, 1);
    return box;
}

void StabilityDialog::selectCase(const QString& name)
{
    const int index = scope_->findData(name);
    if (index >= 0)
        scope_->setCurrentIndex(index);
}

void StabilityDialog::start()
{
    if (job_.running())
        return;
    const int scope = scope_->currentIndex();
    const std::string caseName = scope_->currentData().toString().toStdString();
    const SceneId scene = scene_;
    complete_ = false;
    limits_.clear();
    model_->clear();
    progress_->setValue(0);
    progress_->setMaximum(0); // busy until the rows are known
    progress_->setTextVisible(true);
    status_->setText(tr("Running..."));
    auto out = std::make_shared<Outcome>();
    connect(
        &job_, &BackgroundJob::finished, this, [this, out] { finished(out); }, Qt::SingleShotConnection);
    job_.start([this, out, scope, caseName, scene](BackgroundJob& job) {
        const std::vector<stability::CaseRow> rows = rowsOf(scope, caseName, scene);
        job.report(0, rows.size());
        out->suite = stability::runSuite(
            rows,
            [this, &job](std::size_t done, std::size_t total, const stability::RowResult& row) {
                QMetaObject::invokeMethod(
                    this, [this, row] { model_->append(row); }, Qt::QueuedConnection);
                job.report(done, total);
            },
            [&job] { return job.cancelled(); });
        if (out->suite.complete) {
            std::ostringstream limits;
            stability::writeLimits(limits);
            out->limits = limits.str();
        }
    });
    setRunning(true);
}

void StabilityDialog::cancel()
{
    if (!job_.running())
        return;
    job_.cancel();
    status_->setText(tr("Cancelling..."));
}

void StabilityDialog::finished(const std::shared_ptr<Outcome>& outcome)
{
    if (job_.error()) {
        try {
            std::rethrow_exception(job_.error());
        } catch (const std::exception& e) {
            status_->setText(tr("The suite stopped: %1").arg(QString::fromUtf8(e.what())));
        }
        setRunning(false);
        return;
    }
    complete_ = outcome->suite.complete; // its rows are in the table already: queued before the end
    limits_ = outcome->limits;
    if (progress_->maximum() == 0)
        progress_->setMaximum(1); // stop the busy bar of a run cancelled before its rows were known
    status_->setText(complete_ ? tr("Done: %1").arg(tally())
                               : tr("Cancelled: %1. Nothing to export from a partial run.").arg(tally()));
    setRunning(false);
}

QString StabilityDialog::tally() const
{
    int counts[4] = {0, 0, 0, 0};
    for (const stability::RowResult& r : model_->rows())
        ++counts[static_cast<int>(verdictOf(r))];
    return tr("%1 rows, %2 ok, %3 degraded, %4 failed, %5 not run")
        .arg(model_->rows().size())
        .arg(counts[static_cast<int>(Verdict::Ok)])
        .arg(counts[static_cast<int>(Verdict::Degraded)])
        .arg(counts[static_cast<int>(Verdict::Failed)])
        .arg(counts[static_cast<int>(Verdict::NotRun)]);
}

void StabilityDialog::setRunning(bool running)
{
    run_->setEnabled(!running);
    scope_->setEnabled(!running);
    cancel_->setEnabled(running);
    const bool exportable = !running && complete_ && !model_->rows().empty();
    exportCsv_->setEnabled(exportable);
    exportMarkdown_->setEnabled(exportable);
}

void StabilityDialog::exportCsvTo(const QString& path) const
{
    if (!complete_)
        throw InputError(path.toStdString() + ": no complete run of the suite to export");
    writeFileAtomically(path.toStdString(), [this](std::ostream& out) { stability::writeCsv(out, model_->rows()); });
}

void StabilityDialog::exportMarkdownTo(const QString& path) const
{
    if (!complete_)
        throw InputError(path.toStdString() + ": no complete run of the suite to export");
    // The same sections as `amazeballs-cli stability --markdown`.
    writeFileAtomically(path.toStdString(), [this](std::ostream& out) {
        out << "## Stability limits of dt omega0 on the undamped oscillator\n\n" << limits_ << "\n## Cases\n\n";
        stability::writeMarkdown(out, model_->rows());
    });
}

void StabilityDialog::exportInteractively(bool markdown)
{
    if (lastDirectory_.isEmpty())
        lastDirectory_ = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString base = lastDirectory_ + "/stability";
    const QString path =
        markdown ? QFileDialog::getSaveFileName(this, tr("Export Markdown"), base + ".md", tr("Markdown (*.md)"))
                 : QFileDialog::getSaveFileName(this, tr("Export CSV"), base + ".csv", tr("CSV table (*.csv)"));
    if (path.isEmpty())
        return;
    lastDirectory_ = QFileInfo(path).absolutePath();
    try {
        markdown ? exportMarkdownTo(path) : exportCsvTo(path);
        status_->setText(tr("Saved %1").arg(path));
    } catch (const InputError& e) {
        QMessageBox::warning(this, tr("Export failed"), QString::fromUtf8(e.what()));
    }
}

void StabilityDialog::closeEvent(QCloseEvent* event)
{
    job_.cancel(); // rows poll between steps: the worker stops at once
    QDialog::closeEvent(event);
}

} // namespace ab::ui
