// SPDX-License-Identifier: MIT
#include "parameter_panel.h"

#include "number_field.h"

#include "ui/i18n/core_text.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
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
    error_ = new QLabel;
    error_->setObjectName("parameterError");
    error_->setWordWrap(true);
    error_->setStyleSheet("color: #b03020;");
    error_->hide();
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
    return QStringLiteral("<b>%1</b> (%2): %3<br>%4 %5<br>%6 %7 %8<br>%9 %10")
        .arg(qs(spec.symbol).toHtmlEscaped(), qs(spec.key).toHtmlEscaped(), coreText(spec.meaning).toHtmlEscaped(),
             tr("Report:"), coreText(spec.equation).toHtmlEscaped(), tr("Range:"),
             qs(formatRange(spec)).toHtmlEscaped(), unit.toHtmlEscaped(), tr("Report value:"))
        .arg(qs(formatValue(spec, spec.defaultValue)).toHtmlEscaped());
}

void ParameterPanel::setScene(const SceneInfo& scene, ModelKind model, const ParamValues& values)
{
    scene_ = &scene;
    refused_.clear(); // another stage or model: its own fields
    pending_.clear();
    while (form_->rowCount() > 0)
        form_->removeRow(0);
    fields_.clear();
    labels_.clear();
    const unsigned mask = model == ModelKind::Report ? ReportModel : PhysicalModel;
    for (const ParamSpec& spec : scene.params) {
        if (!spec.usedBy(mask))
            continue; // the chosen model would ignore it
        const QString name =
            spec.symbol == spec.key ? qs(spec.key) : QStringLiteral("%1 (%2)").arg(qs(spec.symbol), qs(spec.key));
        auto* label = new QLabel(name);
        auto* field = new QLineEdit;
        field->setObjectName(QStringLiteral("param-%1").arg(qs(spec.key)));
        field->setPlaceholderText(qs(formatRange(spec)));
        auto* unit = new QLabel(prettyUnit(spec.unit));
        unit->setMinimumWidth(64);
        auto* row = new QHBoxLayout;
        row->addWidget(field, 1);
        row->addWidget(unit);
        const QString tip = tooltip(spec);
        for (QWidget* w : {static_cast<QWidget*>(label), static_cast<QWidget*>(field), static_cast<QWidget*>(unit)})
            w->setToolTip(tip);
        form_->addRow(label, row);
        fields_[spec.key] = field;
        labels_[spec.key] = label;
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
    for (const auto& [key, field] : fields_)
        setInvalid(field, refused_.count(key) > 0);
    QStringList lines;
    for (const auto& [key, message] : refused_)
        lines << tr("Not applied: %1").arg(message);
    error_->setText(lines.join("\n"));
    error_->setVisible(!lines.isEmpty());
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
    return error_->isHidden() ? QString() : error_->text();
}

} // namespace ab::ui
