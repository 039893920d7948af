// SPDX-License-Identifier: MIT
#include "parameter_panel.h"

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
             tr("Report:"), coreText(spec.equation).toHtmlEscaped(), tr("Range:"), qs(formatRange(spec)).toHtmlEscaped(),
             unit.toHtmlEscaped(), tr("Report value:"))
        .arg(qs(formatValue(spec, spec.defaultValue)).toHtmlEscaped());
}

void ParameterPanel::setScene(const SceneInfo& scene, ModelKind model, const ParamValues& values)
{
    scene_ = &scene;
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
        connect(field, &QLineEdit::textEdited, this, [field] { setInvalid(field, false); });
    }
    showValues(values);
}

void ParameterPanel::showValues(const ParamValues& values)
{
    values_ = values;
    for (const auto& [key, field] : fields_) {
        const std::size_t i = *values.indexOf(key);
        const ParamSpec& spec = values.table()[i];
        field->setText(qs(formatValue(spec, values.raw(i))));
        field->setCursorPosition(0);
        QFont f = labels_[key]->font();
        f.setBold(!values.isDefault(i)); // a changed constant stands out
        labels_[key]->setFont(f);
    }
    clearRefusal();
}

void ParameterPanel::clearRefusal()
{
    for (const auto& [key, field] : fields_)
        setInvalid(field, false);
    error_->clear();
    error_->hide();
}

void ParameterPanel::refuse(const std::string& key, const QString& message)
{
    if (QLineEdit* f = field(key))
        setInvalid(f, true);
    error_->setText(tr("Not applied: %1").arg(message));
    error_->show();
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
            showValues(*values_); // unchanged (perhaps retyped): show it in its own format
            return;
        }
        if (scene_->crossCheck)
            scene_->crossCheck(proposed);
    } catch (const InputError& e) {
        refuse(key, QString::fromUtf8(e.what()));
        return;
    }
    emit valuesProposed(proposed);
}

void ParameterPanel::restoreReportValues()
{
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
