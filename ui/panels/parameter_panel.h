// SPDX-License-Identifier: MIT
// The constants of the current scene, generated from its parameter table: one field per
// parameter the chosen model reads, with its unit, range and a tooltip naming the
// equation, and "Report values" to restore the report's constants. A typed value is
// checked against the table and the scene's cross-checks; a refused value is marked
// and explained under its field, and never applied.
#pragma once

#include "core/scene.h"

#include <QWidget>

#include <map>
#include <optional>
#include <string>

class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace ab::ui {

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(QWidget* parent = nullptr);

    // Rebuilds the fields for `scene` and `model` and shows `values`.
    void setScene(const SceneInfo& scene, ModelKind model, const ParamValues& values);
    // Shows `values` (already applied). A field whose entry was refused keeps that entry,
    // in red, with its reason, until it is fixed (an entry that applies, or the applied
    // value typed again), reverted (Esc) or "Report values" is pressed.
    void showValues(const ParamValues& values);
    // Marks `key` as refused with `message`; an empty key is the field last edited (the
    // window refuses what the panel proposed), or the whole panel when none was.
    void refuse(const std::string& key, const QString& message);

    QLineEdit* field(const std::string& key) const;
    std::vector<std::string> shownKeys() const;
    QString errorText() const;

signals:
    // A set of values that passed the table's and the scene's checks.
    void valuesProposed(const ab::ParamValues& values);
    // "Report values" was pressed: every refusal of the stage's panels clears.
    void reportValuesRequested();
    // Enter in a field: the edit is applied or refused; the keyboard goes back to the view.
    void editDone();

private:
    void edited(const std::string& key);
    void restoreReportValues();
    void revert(const std::string& key);
    void showRefusals();
    static QString tooltip(const ParamSpec& spec);

    const SceneInfo* scene_ = nullptr;
    std::optional<ParamValues> values_;
    QFormLayout* form_;
    QLabel* error_;
    QPushButton* reportValues_;
    std::map<std::string, QLineEdit*> fields_;
    std::map<std::string, QLabel*> labels_;
    std::map<std::string, QLabel*> notes_;   // under each field: why its entry was refused
    std::map<std::string, QString> refused_; // field key (or "" for the panel) -> reason
    std::string pending_;                    // the field whose edit the window is deciding on
};

} // namespace ab::ui
