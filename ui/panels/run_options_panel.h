// SPDX-License-Identifier: MIT
// How the run is computed: the model, the integrator and impact finding (whatever the
// core offers; the report model has one scheme per stage, so they apply to the physical
// model only), the time step and the number of steps; and a second run to compare with:
// the same scene, constants and start, computed by another model or integrator.
#pragma once

#include "core/simulation.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace ab::ui {

struct RunOptions {
    ModelKind model = ModelKind::Report;
    Integrator integrator = Integrator::SymplecticEuler;
    ImpactMode impacts = ImpactMode::Located;
    std::optional<double> dt; // unset: the model's default
    long long steps = 0;
    std::optional<RunVariant> compare; // unset: no comparison run
};

class RunOptionsPanel : public QWidget {
    Q_OBJECT
public:
    explicit RunOptionsPanel(QWidget* parent = nullptr);

    // Shows `options` for `scene` (already applied) and clears any refusal.
    void showOptions(const SceneInfo& scene, const RunOptions& options);
    // Marks the options as refused with `message` and shows the applied ones again.
    void refuse(const QString& message);
    QString errorText() const;

    QComboBox* modelBox() const { return model_; }
    QComboBox* integratorBox() const { return integrator_; }
    QComboBox* compareBox() const { return compare_; }
    QComboBox* compareImpactsBox() const { return compareImpacts_; }
    // The compare list's entry for `variant` (its dt aside); -1 when it has none.
    int compareIndex(const std::optional<RunVariant>& variant) const;

signals:
    void optionsProposed(const ab::ui::RunOptions& options);

private:
    void propose();
    void updateEnabled();

    const SceneInfo* scene_ = nullptr;
    RunOptions shown_;
    QComboBox* model_;
    QComboBox* integrator_;
    QComboBox* impacts_;
    QComboBox* compare_;
    QComboBox* compareImpacts_;
    QLineEdit* dt_;
    QLineEdit* steps_;
    QLabel* dtUnit_;
    QLabel* error_;
    bool updating_ = false;
};

} // namespace ab::ui
