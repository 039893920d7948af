// SPDX-License-Identifier: MIT
#include "parameter_panel.h"

#include "equation_rows.h"
#include "number_field.h"

#include "ui/i18n/core_text.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

// "m/s^2" -> "m/s²": the tables write powers the way a command line can.
QString prettyUnit(const std::string& unit)
{
    QString u = coreText(unit);
    u.replace("^2", QString::fromUtf8("\u00b2"));
    u.replace("^3", QString::fromUtf8("\u00b3"));
    return u == "1" ? QString() : u;
}

// A refusal's closing range and unit, "(0, 60] deg", kept on one line: a narrow column
// broke it before the unit or inside the interval.
QString keepRangeWhole(QString text)
{
    static const QRegularExpression range(QStringLiteral("[\\[(][^\\[\\]()]*[\\])](?: \\S+)?$"));
    const QRegularExpressionMatch m = range.match(text);
    if (m.hasMatch())
        text.replace(m.capturedStart(), m.capturedLength(), m.captured().replace(QLatin1Char(' '), QChar(0x00A0)));
    return text;
}

QLabel* newErrorLabel(const QString& name)
{
    auto* label = new QLabel;
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setStyleSheet("color: #b03020;");
    label->hide();
    return label;
}

void setInvalid(QLineEdit* field, bool invalid)
{
    field->setStyleSheet(invalid ? QStringLiteral("QLineEdit { background: #fde2e2; border: 1px solid #c0392b; }")
                                 : QString());
    field->setProperty("refused", invalid);
}

} // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName("parameterPanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    form_ = new QFormLayout;
    form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // Each label above its field: the field and its unit get the column's whole width, so
    // that the longest choice reads whole in a 30 % column at 1280 px.
    form_->setRowWrapPolicy(QFormLayout::WrapAllRows);
    layout->addLayout(form_);
    error_ = newErrorLabel(QStringLiteral("parameterError"));
    layout->addWidget(error_);
    reportValues_ = new QPushButton(tr("Report values"));
    reportValues_->setObjectName("reportValues");
    reportValues_->setToolTip(tr("Restore every constant of this stage to the report's value"));
    reportValues_->setFocusPolicy(Qt::NoFocus);
    auto* row = new QHBoxLayout;
    row->addStretch(1);
    row->addWidget(reportValues_);
    layout->addLayout(row);
    connect(reportValues_, &QPushButton::clicked, this, &ParameterPanel::restoreReportValues);
}

QString ParameterPanel::tooltip(const ParamSpec& spec)
{
    const QString unit = prettyUnit(spec.unit);
    // "<b>v0</b> (v0)" said the name twice: the key follows the symbol only where they differ.
    QString name = QStringLiteral("<b>%1</b>").arg(formulaTypography(qs(spec.symbol)).toHtmlEscaped());
    if (spec.symbol != spec.key)
        name += QStringLiteral(" (%1)").arg(qs(spec.key).toHtmlEscaped());
    return QStringLiteral("%1: %2<br>%3 %4<br>%5 %6 %7<br>%8 %9")
        .arg(name, coreText(spec.meaning).toHtmlEscaped(), spec.reportDefault() ? tr("Report:") : tr("Source:"),
             coreText(spec.equation).toHtmlEscaped(), tr("Range:"), qs(formatRange(spec)).toHtmlEscaped(),
             unit.toHtmlEscaped(), spec.reportDefault() ? tr("Report value:") : tr("Default:"),
             qs(formatValue(spec, spec.defaultValue)).toHtmlEscaped());
}

void ParameterPanel::setScene(const SceneInfo& scene, ModelKind model, const ParamValues& values)
{
    scene_ = &scene;
    // The street's constants are this program's: the report never reached it.
    const bool report = anyReportDefault(scene.params);
    reportValues_->setText(report ? tr("Report values") : tr("Default values"));
    reportValues_->setToolTip(report ? tr("Restore every constant of this stage to the report's value")
                                     : tr("Restore every constant of this stage to its default"));
    refused_.clear(); // another stage or model: its own fields
    pending_.clear();
    while (form_->rowCount() > 0)
        form_->removeRow(0);
    fields_.clear();
    labels_.clear();
    notes_.clear();
    const unsigned mask = model == ModelKind::Report ? ReportModel : PhysicalModel;
    for (const ParamSpec& spec : scene.params) {
        if (!spec.usedBy(mask))
            continue; // the chosen model would ignore it
        // The symbol as the equations set it ("θ (slope)", "μ (mu)"), the key beside it where it differs.
        const QString name = spec.symbol == spec.key
                                 ? formulaTypography(qs(spec.key))
                                 : QStringLiteral("%1 (%2)").arg(formulaTypography(qs(spec.symbol)), qs(spec.key));
        auto* label = new QLabel(name);
        auto* field = new QLineEdit;
        field->setObjectName(QStringLiteral("param-%1").arg(qs(spec.key)));
        field->setPlaceholderText(qs(formatRange(spec)));
        auto* unit = new QLabel(prettyUnit(spec.unit));
        unit->setMinimumWidth(64);
        auto* row = new QHBoxLayout;
        row->addWidget(field, 1);
        row->addWidget(unit);
        // A refusal is explained under its field, where the eye is (not below the fold).
        auto* note = newErrorLabel(QStringLiteral("paramError-%1").arg(qs(spec.key)));
        auto* column = new QVBoxLayout;
        column->setSpacing(2);
        column->addLayout(row);
        column->addWidget(note);
        const QString tip = tooltip(spec);
        for (QWidget* w : {static_cast<QWidget*>(label), static_cast<QWidget*>(field), static_cast<QWidget*>(unit)})
            w->setToolTip(tip);
        form_->addRow(label, column);
        fields_[spec.key] = field;
        labels_[spec.key] = label;
        notes_[spec.key] = note;
        const std::string key = spec.key;
        connect(field, &QLineEdit::editingFinished, this, [this, key] { edited(key); });
        auto* number = new NumberField(field, spec.kind == ParamKind::Vector    ? NumberKind::Vector
                                              : spec.kind == ParamKind::Integer ? NumberKind::Integer
                                                                                : NumberKind::Real);
        connect(number, &NumberField::done, this, [this, key] {
            if (!refused_.count(key)) // a refused entry keeps the keys, to be fixed
                emit editDone();
        });
        connect(number, &NumberField::reverted, this, [this, key] { revert(key); });
    }
    showValues(values);
}

void ParameterPanel::showValues(const ParamValues& values)
{
    values_ = values;
    refused_.erase(std::string()); // the panel-wide refusal was of the values replaced now
    for (const auto& [key, field] : fields_) {
        const std::size_t i = *values.indexOf(key);
        const ParamSpec& spec = values.table()[i];
        if (!refused_.count(key)) { // a refused entry stays as typed, in red
            field->setText(qs(formatValue(spec, values.raw(i))));
            field->setCursorPosition(0);
        }
        QFont f = labels_[key]->font();
        f.setBold(!values.isDefault(i)); // a changed constant stands out
        labels_[key]->setFont(f);
    }
    showRefusals();
}

void ParameterPanel::showRefusals()
{
    for (const auto& [key, field] : fields_) {
        const auto refusal = refused_.find(key);
        const bool refused = refusal != refused_.end();
        setInvalid(field, refused);
        QLabel* note = notes_.at(key);
        note->setText(refused ? tr("Not applied: %1").arg(keepRangeWhole(refusal->second)) : QString());
        note->setVisible(refused);
    }
    const auto whole = refused_.find(std::string()); // the panel's, not one field's
    error_->setText(whole != refused_.end() ? tr("Not applied: %1").arg(keepRangeWhole(whole->second)) : QString());
    error_->setVisible(whole != refused_.end());
}

void ParameterPanel::revert(const std::string& key)
{
    refused_.erase(key);
    if (values_)
        showValues(*values_);
}

void ParameterPanel::refuse(const std::string& key, const QString& message)
{
    const std::string which = !key.empty() ? key : pending_;
    refused_[fields_.count(which) ? which : std::string()] = message;
    pending_.clear();
    showRefusals();
    // The reason scrolled into sight with its field, once the layout has made room for it.
    QLabel* note = notes_.count(which) ? notes_.at(which) : error_;
    QTimer::singleShot(0, note, [note] {
        for (QWidget* w = note->parentWidget(); w; w = w->parentWidget())
            if (auto* area = qobject_cast<QScrollArea*>(w)) {
                area->ensureWidgetVisible(note, 0, 8);
                return;
            }
    });
}

void ParameterPanel::edited(const std::string& key)
{
    if (!values_ || !scene_)
        return;
    QLineEdit* f = fields_.at(key);
    ParamValues proposed = *values_;
    try {
        proposed.parse(key, f->text().trimmed().toStdString());
        if (proposed == *values_) {
            refused_.erase(key);  // the applied value again: fixed
            showValues(*values_); // unchanged (perhaps retyped): show it in its own format
            return;
        }
        if (scene_->crossCheck)
            scene_->crossCheck(proposed);
    } catch (const InputError& e) {
        refuse(key, refusalText(e));
        return;
    }
    // Applied, the window shows the values (and this field is fixed); refused, it names
    // the field through pending_.
    refused_.erase(key);
    pending_ = key;
    emit valuesProposed(proposed);
    pending_.clear();
}

void ParameterPanel::restoreReportValues()
{
    refused_.clear();
    pending_.clear();
    emit reportValuesRequested();
    if (scene_)
        emit valuesProposed(scene_->defaults());
}

QLineEdit* ParameterPanel::field(const std::string& key) const
{
    const auto it = fields_.find(key);
    return it == fields_.end() ? nullptr : it->second;
}

std::vector<std::string> ParameterPanel::shownKeys() const
{
    std::vector<std::string> keys;
    if (!scene_)
        return keys;
    for (const ParamSpec& spec : scene_->params)
        if (fields_.count(spec.key))
            keys.push_back(spec.key);
    return keys;
}

QString ParameterPanel::errorText() const
{
    QStringList lines;
    for (const auto& [key, note] : notes_)
        if (!note->isHidden())
            lines << note->text();
    if (!error_->isHidden())
        lines << error_->text();
    return lines.join("\n");
}

} // namespace ab::ui
