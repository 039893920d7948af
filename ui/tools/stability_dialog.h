// SPDX-License-Identifier: MIT
// Tools > Stability suite: the stiff and extreme cases (core/stability) run on a worker
// thread, every case, the current scene's rows or one case, rows filling the table as they
// finish. Failed rows are red and degraded ones amber (with a text marker beside the
// colour, and a legend); the table sorts by any column and filters by text and verdict.
// A complete run exports as CSV (the contract's columns) and Markdown; a cancelled one
// keeps its finished rows on screen and exports nothing.
#pragma once

#include "background_job.h"
#include "result_tables.h"

#include "core/stability/suite.h"

#include <QDialog>

#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableView;

namespace ab::ui {

class StabilityDialog : public QDialog {
    Q_OBJECT
public:
    explicit StabilityDialog(SceneId scene, QWidget* parent = nullptr);

    // The scopes offered: 0 every case, 1 the current scene's rows, then one per case.
    QComboBox* scope() const { return scope_; }
    void selectCase(const QString& name);

    void start();
    void cancel();
    bool running() const { return job_.running(); }
    BackgroundJob& job() { return job_; }
    bool complete() const { return complete_; }

    StabilityTableModel* table() const { return model_; }
    StabilityFilter* filter() const { return filter_; }
    QTableView* tableView() const { return table_; }
    QLineEdit* filterText() const { return filterText_; }
    QComboBox* verdictChoice() const { return verdict_; }
    QPushButton* exportCsvButton() const { return exportCsv_; }
    QPushButton* exportMarkdownButton() const { return exportMarkdown_; }
    QLabel* status() const { return status_; }

    // Each throws InputError naming the path and the reason.
    void exportCsvTo(const QString& path) const;
    void exportMarkdownTo(const QString& path) const;

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    struct Outcome {
        stability::SuiteResult suite;
        std::string limits; // markdown lines of the measured stability limits
    };

    QWidget* buildControls();
    QWidget* buildLegend();
    std::vector<stability::CaseRow> selectedRows() const;
    void finished(const std::shared_ptr<Outcome>& outcome);
    void setRunning(bool running);
    void exportInteractively(bool markdown);
    QString tally() const;

    SceneId scene_;
    BackgroundJob job_;
    bool complete_ = false;
    std::string limits_;
    StabilityTableModel* model_ = nullptr;
    StabilityFilter* filter_ = nullptr;
    QTableView* table_ = nullptr;
    QComboBox* scope_ = nullptr;
    QLineEdit* filterText_ = nullptr;
    QComboBox* verdict_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* exportCsv_ = nullptr;
    QPushButton* exportMarkdown_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QString lastDirectory_;
};

} // namespace ab::ui
