// SPDX-License-Identifier: MIT
// How the run is computed: the model, the integrator and impact finding (whatever the
// core offers; the report model has one scheme per stage, so they apply to the physical
// model only), the time step and the number of steps; and a second run to compare with:
// the same scene, constants and start, computed by another model or integrator.
#pragma once

#include "core/simulation.h"

#include <QWidget>

#include <map>
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

    // Shows `options` for `scene` (already applied). A refused step or run length stays as
    // typed, in red, with its reason, until it is fixed, reverted (Esc) or cleared.
    void showOptions(const SceneInfo& scene, const RunOptions& options);
    // The window refused the options last proposed: the choices go back to the applied
    // ones, a typed field that took part stays in red.
    void refuse(const QString& message);
    // Every refused entry back to the applied options ("Report values").
    void clearRefusals();
    QString errorText() const;
    // What the greyed integrator and impact boxes say for the report model of `scene`.
    static QString reportScheme(SceneId scene);
    static QString reportImpacts(SceneId scene);
    // Whether the report model exists for `scene`: not for the street, which the report's
    // rules never reached; the window then greys it out and says why (noReportModelReason).
    static bool reportModelOffered(SceneId scene);
    static QString noReportModelReason();

    QComboBox* modelBox() const { return model_; }
    QComboBox* integratorBox() const { return integrator_; }
    QComboBox* compareBox() const { return compare_; }
    QComboBox* compareImpactsBox() const { return compareImpacts_; }
    // The compare list's entry for `variant` (its dt aside); -1 when it has none.
    int compareIndex(const std::optional<RunVariant>& variant) const;

signals:
    void optionsProposed(const ab::ui::RunOptions& options);
    // Enter in a field: the keyboard goes back to the view.
    void editDone();

private:
    void propose();
    void updateEnabled();
    void showRefusals();
    // The report model's own scheme in the greyed boxes, the physical model's choices else.
    void showScheme();
    void offerReportModel(bool offered);
    // The integrators the stage's physical model steps with: the others greyed, saying why,
    // in the integrator and comparison lists (integratorOffered).
    void offerIntegrators(SceneId scene);

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
    QLabel* noReport_; // why the report model is greyed out, where it is
    bool updating_ = false;
    // Refused typed entries: the field and why; an empty message stands for the window's
    // refusal of a whole proposal (windowRefusal_).
    std::map<QLineEdit*, QString> refused_;
    QString windowRefusal_;
};

} // namespace ab::ui
