// SPDX-License-Identifier: MIT
// The constants of the current scene, generated from its parameter table: one field per
// parameter the chosen model reads, with its unit, range and a tooltip naming the
// equation, and "Report values" to restore the report's constants. A typed value is
// checked against the table and the scene's cross-checks; a refused value is marked
// and explained, and never applied.
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
    // Shows `values` (already applied) and clears any refusal.
    void showValues(const ParamValues& values);
    // Marks `key` (or the whole panel when empty) as refused with `message`.
    void refuse(const std::string& key, const QString& message);

    QLineEdit* field(const std::string& key) const;
    std::vector<std::string> shownKeys() const;
    QString errorText() const;

signals:
    // A set of values that passed the table's and the scene's checks.
    void valuesProposed(const ab::ParamValues& values);

private:
    void edited(const std::string& key);
    void restoreReportValues();
    void clearRefusal();
    static QString tooltip(const ParamSpec& spec);

    const SceneInfo* scene_ = nullptr;
    std::optional<ParamValues> values_;
    QFormLayout* form_;
    QLabel* error_;
    QPushButton* reportValues_;
    std::map<std::string, QLineEdit*> fields_;
    std::map<std::string, QLabel*> labels_;
};

} // namespace ab::ui
