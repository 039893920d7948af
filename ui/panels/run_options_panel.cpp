// SPDX-License-Identifier: MIT
#include "run_options_panel.h"

#include "number_field.h"

#include "ui/i18n/core_text.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QStandardItemModel>

#include <algorithm>
#include <tuple>

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

// The compare list's item data: -1 for off, else model * 100 + integrator.
constexpr int compareOff = -1;
// The greyed boxes' entry naming the report model's own scheme.
constexpr int reportOwn = -2;

void setInvalid(QLineEdit* field, bool invalid)
{
    field->setStyleSheet(invalid ? QStringLiteral("QLineEdit { background: #fde2e2; border: 1px solid #c0392b; }")
                                 : QString());
    field->setProperty("refused", invalid);
}
int compareCode(ModelKind m, Integrator i)
{
    return int(m) * 100 + (m == ModelKind::Report ? 0 : int(i));
}

// The keys of the scene's constants that one model reads and the other does not.
QStringList onlyUsedBy(const SceneInfo& scene, unsigned model)
{
    QStringList keys;
    for (const ParamSpec& p : scene.params)
        if (p.models == model)
            keys << qs(p.key);
    return keys;
}

} // namespace

RunOptionsPanel::RunOptionsPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("runOptions");
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // Each label above its field: the field and its unit get the column's whole width, so
    // that the longest choice reads whole in a 30 % column at 1280 px.
    form->setRowWrapPolicy(QFormLayout::WrapAllRows);

    model_ = new QComboBox;
    model_->setObjectName("modelCombo");
    for (ModelKind m : allModels()) {
        model_->addItem(QStringLiteral("%1: %2").arg(qs(modelKey(m)), coreText(modelTitle(m))), int(m));
        model_->setItemData(model_->count() - 1, coreText(modelSummary(m)), Qt::ToolTipRole);
    }
    form->addRow(tr("Model"), model_);

    noReport_ = new QLabel;
    noReport_->setObjectName("noReportModel");
    noReport_->setWordWrap(true);
    noReport_->hide();
    form->addRow(noReport_);

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

    compare_ = new QComboBox;
    compare_->setObjectName("compareCombo");
    compare_->addItem(tr("off"), compareOff);
    for (ModelKind m : allModels()) {
        if (m == ModelKind::Report) {
            compare_->addItem(QStringLiteral("%1: %2").arg(qs(modelKey(m)), coreText(modelTitle(m))),
                              compareCode(m, Integrator::SymplecticEuler));
            continue;
        }
        for (Integrator i : allIntegrators())
            compare_->addItem(
                QStringLiteral("%1, %2 (%3)").arg(qs(modelKey(m)), coreText(integratorTitle(i)), qs(integratorKey(i))),
                compareCode(m, i));
    }
    form->addRow(tr("Compare with"), compare_);

    compareImpacts_ = new QComboBox;
    compareImpacts_->setObjectName("compareImpactsCombo");
    compareImpacts_->addItem(tr("located inside the step"), int(ImpactMode::Located));
    compareImpacts_->addItem(tr("at the step's end (as the report)"), int(ImpactMode::StepEnd));
    compareImpacts_->setToolTip(tr("Where the comparison run finds impacts"));
    form->addRow(tr("Its impacts"), compareImpacts_);

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

    for (QComboBox* box : {model_, integrator_, impacts_, compare_, compareImpacts_}) {
        // The longest entry ("physical, Symplectic Euler (symplectic-euler)") must not
        // widen the panel past its column: the box is elided, the list shows it whole.
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(12);
        connect(box, &QComboBox::currentIndexChanged, this, [this] { propose(); });
    }
    for (QLineEdit* field : {dt_, steps_}) {
        connect(field, &QLineEdit::editingFinished, this, [this] { propose(); });
        auto* number = new NumberField(field, field == dt_ ? NumberKind::Real : NumberKind::Integer);
        connect(number, &NumberField::done, this, [this, field] {
            if (!refused_.count(field) && windowRefusal_.isEmpty()) // a refused entry keeps the keys
                emit editDone();
        });
        connect(number, &NumberField::reverted, this, [this, field] {
            refused_.erase(field);
            if (scene_)
                showOptions(*scene_, shown_);
        });
    }
}

QString RunOptionsPanel::reportScheme(SceneId scene)
{
    switch (scene) {
    case SceneId::Bounce1d:
        return tr("report: explicit Euler (eqs 2.12-2.16)");
    case SceneId::Box3d:
    case SceneId::TwoBalls:
        return tr("report: semi-implicit Euler step (eqs 2.18-2.22)");
    case SceneId::ManyBalls:
        return tr("report: one update per frame (Appendix D)");
    case SceneId::Street: // the report model is not offered (reportModelOffered)
        return {};
    }
    return {};
}

QString RunOptionsPanel::reportImpacts(SceneId scene)
{
    switch (scene) {
    case SceneId::Bounce1d:
        return tr("report: at the step's end (Appendix A)");
    case SceneId::Box3d:
    case SceneId::TwoBalls:
        return tr("report: at the step's end, one face a step (Appendix B)");
    case SceneId::ManyBalls:
        return tr("report: at the end of each frame (Appendix D)");
    case SceneId::Street:
        return {};
    }
    return {};
}

bool RunOptionsPanel::reportModelOffered(SceneId scene)
{
    switch (scene) {
    case SceneId::Bounce1d:
    case SceneId::Box3d:
    case SceneId::TwoBalls:
    case SceneId::ManyBalls:
        return true;
    case SceneId::Street: // the report built the box and stopped there (report 3.1)
        return false;
    }
    return false;
}

QString RunOptionsPanel::noReportModelReason()
{
    return tr("The report's rules stop at the box; the street is the physical model's (report 3.1)");
}

void RunOptionsPanel::offerReportModel(bool offered)
{
    // The report's entries stay in the lists, greyed, with the reason as their tooltip and
    // in a line under the model: the reader sees what is missing and why.
    const QString why = offered ? QString() : noReportModelReason();
    for (QComboBox* box : {model_, compare_}) {
        auto* items = qobject_cast<QStandardItemModel*>(box->model());
        const int at = box->findData(box == model_ ? int(ModelKind::Report)
                                                   : compareCode(ModelKind::Report, Integrator::SymplecticEuler));
        if (!items || at < 0)
            continue;
        items->item(at)->setEnabled(offered);
        box->setItemData(at, offered ? coreText(modelSummary(ModelKind::Report)) : why, Qt::ToolTipRole);
    }
    noReport_->setText(why);
    noReport_->setVisible(!offered);
}

void RunOptionsPanel::offerIntegrators(SceneId scene)
{
    const QString why = scene == SceneId::Street
                            ? tr("Not offered on the street: its flight is exact between events (event)")
                            : tr("Not offered for many balls: their contacts are resolved at each substep's end, "
                                 "without spring contacts");
    for (Integrator i : allIntegrators()) {
        const bool offered = integratorOffered(scene, i);
        for (auto [box, code] :
             {std::pair{integrator_, int(i)}, std::pair{compare_, compareCode(ModelKind::Physical, i)}}) {
            auto* items = qobject_cast<QStandardItemModel*>(box->model());
            const int at = box->findData(code);
            if (!items || at < 0)
                continue;
            items->item(at)->setEnabled(offered);
            box->setItemData(at, offered ? QVariant() : QVariant(why), Qt::ToolTipRole);
        }
    }
}

void RunOptionsPanel::showScheme()
{
    const bool report = shown_.model == ModelKind::Report;
    const bool reportCompared = shown_.compare && shown_.compare->model == ModelKind::Report;
    const QString scheme = scene_ ? reportScheme(scene_->id) : QString();
    const QString impacts = scene_ ? reportImpacts(scene_->id) : QString();
    for (auto [box, own, text] : {std::tuple{integrator_, report, scheme}, std::tuple{impacts_, report, impacts},
                                  std::tuple{compareImpacts_, reportCompared, impacts}}) {
        const int at = box->findData(reportOwn);
        if (own) {
            // The report's reference ("(eqs 2.18-2.22)") goes to the tooltip: the entry then
            // reads whole in the narrow column of a 1280 px window.
            const QString entry = text.section(QStringLiteral(" ("), 0, 0);
            if (at < 0)
                box->insertItem(0, entry, reportOwn);
            else
                box->setItemText(at, entry);
            box->setItemData(0, text, Qt::ToolTipRole);
            box->setCurrentIndex(0);
        } else if (at >= 0) {
            box->removeItem(at);
        }
    }
}

void RunOptionsPanel::showOptions(const SceneInfo& scene, const RunOptions& options)
{
    updating_ = true;
    scene_ = &scene;
    shown_ = options;
    offerReportModel(reportModelOffered(scene.id));
    offerIntegrators(scene.id);
    showScheme(); // the report's entries go where the physical choices now show
    selectData(model_, int(options.model));
    selectData(integrator_, int(options.integrator));
    selectData(impacts_, int(options.impacts));
    compare_->setCurrentIndex(std::max(compareIndex(options.compare), 0));
    selectData(compareImpacts_, int(options.compare ? options.compare->impacts : ImpactMode::Located));
    // Both runs read this stage's constants, each only the ones its model has.
    const QStringList physicalOnly = onlyUsedBy(scene, PhysicalModel);
    const QStringList reportOnly = onlyUsedBy(scene, ReportModel);
    QString why = tr("Runs the same stage again beside this run, from the same start and with the same constants, "
                     "computed another way: ghosted in the 3D view, dotted on the charts.");
    if (!physicalOnly.isEmpty())
        why += "\n" + tr("The report model ignores the physical-only constants (%1). When this run is the report's, a "
                         "physical comparison reads them as this stage holds them: their defaults unless they were "
                         "set while the physical model was chosen.")
                          .arg(physicalOnly.join(", "));
    if (!reportOnly.isEmpty())
        why += "\n" + tr("The physical model ignores the report-only constants (%1).").arg(reportOnly.join(", "));
    compare_->setToolTip(why);
    // Six digits: the hint reads 0.0166667 for 1/60 s rather than all seventeen that read back.
    dt_->setPlaceholderText(
        tr("%1 (the model's step)").arg(qs(formatSignificant(defaultDt(scene.id, options.model), 6))));
    if (!refused_.count(dt_)) // a refused entry stays as typed, in red
        dt_->setText(options.dt ? qs(formatNumber(*options.dt)) : QString());
    dtUnit_->setText(coreText(scene.timeUnit));
    if (!refused_.count(steps_))
        steps_->setText(QString::number(options.steps));
    windowRefusal_.clear();
    showScheme();
    showRefusals();
    updateEnabled();
    updating_ = false;
}

void RunOptionsPanel::showRefusals()
{
    QStringList lines;
    for (QLineEdit* field : {dt_, steps_}) {
        const auto it = refused_.find(field);
        setInvalid(field, it != refused_.end());
        if (it != refused_.end())
            lines << tr("Not applied: %1").arg(it->second);
    }
    if (!windowRefusal_.isEmpty())
        lines << tr("Not applied: %1").arg(windowRefusal_);
    error_->setText(lines.join("\n"));
    error_->setVisible(!lines.isEmpty());
}

void RunOptionsPanel::clearRefusals()
{
    refused_.clear();
    windowRefusal_.clear();
    if (scene_)
        showOptions(*scene_, shown_);
}

void RunOptionsPanel::updateEnabled()
{
    const bool physical = shown_.model == ModelKind::Physical;
    const QString why = tr("The report model has one scheme per stage, the report's own");
    integrator_->setEnabled(physical);
    impacts_->setEnabled(physical);
    integrator_->setToolTip(physical ? tr("How the physical model advances in time") : why);
    impacts_->setToolTip(physical ? tr("Where impacts are found") : why);
    compareImpacts_->setEnabled(shown_.compare && shown_.compare->model == ModelKind::Physical &&
                                shown_.compare->integrator != Integrator::Event);
}

int RunOptionsPanel::compareIndex(const std::optional<RunVariant>& variant) const
{
    return compare_->findData(variant ? compareCode(variant->model, variant->integrator) : compareOff);
}

void RunOptionsPanel::refuse(const QString& message)
{
    // A typed field whose text differs from the applied options took part: it stays red.
    const QString appliedDt = shown_.dt ? qs(formatNumber(*shown_.dt)) : QString();
    if (dt_->text().trimmed() != appliedDt)
        refused_[dt_] = message;
    else if (steps_->text().trimmed() != QString::number(shown_.steps))
        refused_[steps_] = message;
    if (scene_)
        showOptions(*scene_, shown_);
    if (!refused_.count(dt_) && !refused_.count(steps_))
        windowRefusal_ = message;
    showRefusals();
}

QString RunOptionsPanel::errorText() const
{
    return error_->isHidden() ? QString() : error_->text();
}

void RunOptionsPanel::propose()
{
    if (updating_ || !scene_)
        return;
    RunOptions o = shown_;
    const int integrator = integrator_->currentData().toInt(), impacts = impacts_->currentData().toInt();
    o.model = ModelKind(model_->currentData().toInt());
    // The report's own entry stands for the physical choices kept for later.
    if (integrator != reportOwn)
        o.integrator = Integrator(integrator);
    if (impacts != reportOwn)
        o.impacts = ImpactMode(impacts);
    o.compare.reset();
    if (const int code = compare_->currentData().toInt(); code != compareOff) {
        RunVariant v;
        v.model = ModelKind(code / 100);
        v.integrator = v.model == ModelKind::Report ? Integrator::SymplecticEuler : Integrator(code % 100);
        const int impactsCode = compareImpacts_->currentData().toInt();
        v.impacts =
            v.model == ModelKind::Report || impactsCode == reportOwn ? ImpactMode::Located : ImpactMode(impactsCode);
        // A step the comparison was given (a preset's) stays while its model stays.
        if (shown_.compare && shown_.compare->model == v.model)
            v.dt = shown_.compare->dt;
        o.compare = v;
    }
    // Each typed field on its own: a refused one stays as typed and the applied value
    // stands in for it, so the other choices still apply.
    try {
        const QString dt = dt_->text().trimmed();
        o.dt.reset();
        if (!dt.isEmpty()) {
            o.dt = parseReal(dt.toStdString(), "dt");
            if (*o.dt <= 0.0)
                throw InputError(Refusal{refusal::stepNotPositive, {formatNumber(*o.dt)}});
        }
        refused_.erase(dt_);
    } catch (const InputError& e) {
        refused_[dt_] = refusalText(e);
        o.dt = shown_.dt;
    }
    try {
        o.steps = parseInteger(steps_->text().trimmed().toStdString(), "steps");
        if (o.steps < 1 || o.steps > 4'000'000'000LL)
            throw InputError(Refusal{refusal::stepsOutside, {std::to_string(o.steps), "4000000000"}});
        refused_.erase(steps_);
    } catch (const InputError& e) {
        refused_[steps_] = refusalText(e);
        o.steps = shown_.steps;
    }
    windowRefusal_.clear();
    showRefusals();
    if (o.model == shown_.model && o.integrator == shown_.integrator && o.impacts == shown_.impacts &&
        o.dt == shown_.dt && o.steps == shown_.steps && o.compare == shown_.compare) {
        if (scene_ && !updating_) // a field typed back to its applied value shows in its own format
            showOptions(*scene_, shown_);
        return;
    }
    emit optionsProposed(o);
}

} // namespace ab::ui
