// SPDX-License-Identifier: MIT
#include "run_options_panel.h"

#include "ui/i18n/core_text.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

namespace ab::ui {

namespace {

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

constexpr ImpactMode impactModes[] = {ImpactMode::Located, ImpactMode::StepEnd};

void selectData(QComboBox* box, int value)
{
    const int i = box->findData(value);
    if (i >= 0)
        box->setCurrentIndex(i);
}

} // namespace

RunOptionsPanel::RunOptionsPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("runOptions");
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    model_ = new QComboBox;
    model_->setObjectName("modelCombo");
    for (ModelKind m : allModels()) {
        model_->addItem(QStringLiteral("%1: %2").arg(qs(modelKey(m)), coreText(modelTitle(m))), int(m));
        model_->setItemData(model_->count() - 1, coreText(modelSummary(m)), Qt::ToolTipRole);
    }
    form->addRow(tr("Model"), model_);

    integrator_ = new QComboBox;
    integrator_->setObjectName("integratorCombo");
    for (Integrator i : allIntegrators())
        integrator_->addItem(coreText(integratorTitle(i)) + " (" + qs(integratorKey(i)) + ")", int(i));
    form->addRow(tr("Integrator"), integrator_);

    impacts_ = new QComboBox;
    impacts_->setObjectName("impactsCombo");
    impacts_->addItem(tr("located inside the step"), int(ImpactMode::Located));
    impacts_->addItem(tr("at the step's end (as the report)"), int(ImpactMode::StepEnd));
    for (ImpactMode m : impactModes)
        impacts_->setItemData(impacts_->findData(int(m)), qs(impactModeKey(m)), Qt::ToolTipRole);
    form->addRow(tr("Impacts"), impacts_);

    dt_ = new QLineEdit;
    dt_->setObjectName("dtField");
    dtUnit_ = new QLabel;
    dtUnit_->setMinimumWidth(64);
    auto* dtRow = new QHBoxLayout;
    dtRow->addWidget(dt_, 1);
    dtRow->addWidget(dtUnit_);
    form->addRow(tr("Step dt"), dtRow);

    steps_ = new QLineEdit;
    steps_->setObjectName("stepsField");
    steps_->setToolTip(tr("Length of the run in steps; the report's value by default"));
    form->addRow(tr("Steps"), steps_);

    error_ = new QLabel;
    error_->setObjectName("runOptionsError");
    error_->setWordWrap(true);
    error_->setStyleSheet("color: #b03020;");
    error_->hide();
    form->addRow(error_);

    for (QComboBox* box : {model_, integrator_, impacts_})
        connect(box, &QComboBox::currentIndexChanged, this, [this] { propose(); });
    for (QLineEdit* field : {dt_, steps_})
        connect(field, &QLineEdit::editingFinished, this, [this] { propose(); });
}

void RunOptionsPanel::showOptions(const SceneInfo& scene, const RunOptions& options)
{
    updating_ = true;
    scene_ = &scene;
    shown_ = options;
    selectData(model_, int(options.model));
    selectData(integrator_, int(options.integrator));
    selectData(impacts_, int(options.impacts));
    dt_->setPlaceholderText(tr("%1 (the model's step)").arg(qs(formatNumber(defaultDt(scene.id, options.model)))));
    dt_->setText(options.dt ? qs(formatNumber(*options.dt)) : QString());
    dtUnit_->setText(coreText(scene.timeUnit));
    steps_->setText(QString::number(options.steps));
    error_->hide();
    updateEnabled();
    updating_ = false;
}

void RunOptionsPanel::updateEnabled()
{
    const bool physical = shown_.model == ModelKind::Physical;
    const QString why = tr("The report model has one scheme per stage, the report's own");
    integrator_->setEnabled(physical);
    impacts_->setEnabled(physical);
    integrator_->setToolTip(physical ? tr("How the physical model advances in time") : why);
    impacts_->setToolTip(physical ? tr("Where impacts are found") : why);
}

void RunOptionsPanel::refuse(const QString& message)
{
    if (scene_)
        showOptions(*scene_, shown_);
    error_->setText(tr("Not applied: %1").arg(message));
    error_->show();
}

QString RunOptionsPanel::errorText() const
{
    return error_->isHidden() ? QString() : error_->text();
}

void RunOptionsPanel::propose()
{
    if (updating_ || !scene_)
        return;
    RunOptions o;
    o.model = ModelKind(model_->currentData().toInt());
    o.integrator = Integrator(integrator_->currentData().toInt());
    o.impacts = ImpactMode(impacts_->currentData().toInt());
    try {
        const QString dt = dt_->text().trimmed();
        if (!dt.isEmpty()) {
            o.dt = parseReal(dt.toStdString(), "dt");
            if (*o.dt <= 0.0)
                throw InputError("dt: " + formatNumber(*o.dt) + " must be positive");
        }
        o.steps = parseInteger(steps_->text().trimmed().toStdString(), "steps");
        if (o.steps < 1 || o.steps > 4'000'000'000LL)
            throw InputError("steps: " + std::to_string(o.steps) + " is outside [1, 4000000000]");
    } catch (const InputError& e) {
        refuse(QString::fromUtf8(e.what()));
        return;
    }
    if (o.model == shown_.model && o.integrator == shown_.integrator && o.impacts == shown_.impacts &&
        o.dt == shown_.dt && o.steps == shown_.steps)
        return;
    emit optionsProposed(o);
}

} // namespace ab::ui
