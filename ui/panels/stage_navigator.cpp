// SPDX-License-Identifier: MIT
#include "stage_navigator.h"

#include <QButtonGroup>
#include <QHBoxLayout>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace ab::ui {

namespace {

QString html(const std::string& s)
{
    return QString::fromStdString(s).toHtmlEscaped();
}

int indexOf(SceneId id)
{
    const auto& scenes = allScenes();
    for (std::size_t i = 0; i < scenes.size(); ++i)
        if (scenes[i]->id == id)
            return static_cast<int>(i);
    throw std::logic_error("scene missing from allScenes()");
}

} // namespace

StageNavigator::StageNavigator(QWidget* parent) : QWidget(parent), buttons_(new QButtonGroup(this))
{
    setObjectName("stageNavigator");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    row->setSpacing(2);
    const auto& scenes = allScenes();
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const SceneInfo& s = *scenes[i];
        auto* b = new QPushButton(QStringLiteral("%1  %2").arg(s.stage).arg(QString::fromStdString(s.key)));
        b->setCheckable(true);
        b->setFocusPolicy(Qt::NoFocus);
        b->setObjectName(QStringLiteral("stage-%1").arg(QString::fromStdString(s.key)));
        b->setToolTip(tr("Stage %1: %2 (key %1)").arg(s.stage).arg(QString::fromStdString(s.title)));
        buttons_->addButton(b, static_cast<int>(i));
        row->addWidget(b);
    }
    buttons_->setExclusive(true);
    layout->addLayout(row);

    text_ = new QTextBrowser;
    text_->setObjectName("stageText");
    text_->setOpenLinks(false);
    layout->addWidget(text_, 1);

    auto* nav = new QHBoxLayout;
    previous_ = new QPushButton(tr("< Previous stage"));
    next_ = new QPushButton(tr("Next stage >"));
    for (QPushButton* b : {previous_, next_})
        b->setFocusPolicy(Qt::NoFocus);
    nav->addWidget(previous_);
    nav->addStretch(1);
    nav->addWidget(next_);
    layout->addLayout(nav);

    connect(buttons_, &QButtonGroup::idClicked, this, &StageNavigator::request);
    connect(previous_, &QPushButton::clicked, this, &StageNavigator::previous);
    connect(next_, &QPushButton::clicked, this, &StageNavigator::next);
    setCurrent(SceneId::Bounce1d);
}

QString StageNavigator::describe(const SceneInfo& s)
{
    QString out =
        QStringLiteral("<h3 style='margin-bottom:2px'>%1 %2: %3</h3>").arg(tr("Stage")).arg(s.stage).arg(html(s.title));
    out += QStringLiteral("<p style='color:#555;margin-top:0'>%1 %2</p>").arg(tr("Report:"), html(s.reportRef));
    out += QStringLiteral("<p>%1</p>").arg(html(s.summary));
    out += QStringLiteral("<p><b>%1</b></p><table cellspacing='0' cellpadding='2'>").arg(tr("Equations"));
    for (const Equation& e : s.equations)
        out += QStringLiteral("<tr><td style='color:#555'>(%1)</td><td><tt>%2</tt></td></tr>"
                              "<tr><td></td><td style='color:#444'><i>%3</i></td></tr>")
                   .arg(html(e.number), html(e.text), html(e.meaning));
    out += QStringLiteral("</table>");
    if (!s.notes.empty()) {
        out += QStringLiteral("<p><b>%1</b></p><ul style='margin-left:-20px'>").arg(tr("Notes on the report"));
        for (const ReportNote& n : s.notes)
            out += QStringLiteral("<li><b>%1</b>: %2</li>").arg(html(n.where), html(n.text));
        out += QStringLiteral("</ul>");
    }
    return out;
}

void StageNavigator::setCurrent(SceneId scene)
{
    current_ = scene;
    const int i = indexOf(scene);
    buttons_->button(i)->setChecked(true);
    text_->setHtml(describe(sceneInfo(scene)));
    previous_->setEnabled(i > 0);
    next_->setEnabled(i + 1 < static_cast<int>(allScenes().size()));
}

QString StageNavigator::text() const
{
    return text_->toPlainText();
}

void StageNavigator::request(int index)
{
    const auto& scenes = allScenes();
    if (index < 0 || index >= static_cast<int>(scenes.size()))
        return;
    // The window decides (it may keep the current stage); show the current one until then.
    buttons_->button(indexOf(current_))->setChecked(true);
    emit sceneRequested(scenes[static_cast<std::size_t>(index)]->id);
}

void StageNavigator::previous()
{
    request(indexOf(current_) - 1);
}

void StageNavigator::next()
{
    request(indexOf(current_) + 1);
}

} // namespace ab::ui
