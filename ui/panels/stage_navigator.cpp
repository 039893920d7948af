// SPDX-License-Identifier: MIT
#include "stage_navigator.h"

#include "equation_rows.h"

#include "ui/i18n/core_text.h"

#include <QButtonGroup>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollBar>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <QRegularExpression>

#include <algorithm>

namespace ab::ui {

namespace {

QString html(const std::string& s)
{
    // A quotient in the prose ("dv/dt") and a sign before its term ("= -g") hold together:
    // Qt would end a line after the solidus or the hyphen-minus.
    static const QRegularExpression quotient(QStringLiteral("(?<=\\S)/(?=\\S)")),
        sign(QStringLiteral("(?<=\\s)-(?=[\\w(])"));
    return coreText(s)
        .toHtmlEscaped()
        .replace(quotient, QStringLiteral("/\u2060"))
        .replace(sign, QStringLiteral("-\u2060"));
}

// Marks the newest equation of the walk (showText scrolls it into sight).
constexpr char kNewestAnchor[] = "newest-equation";

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
    // Two by two: four in a row made the lecture font's left column half the screen wide.
    auto* row = new QGridLayout;
    row->setSpacing(2);
    const auto& scenes = allScenes();
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const SceneInfo& s = *scenes[i];
        // The scene keys are the contract's names, the same in every language.
        auto* b = new QPushButton(QStringLiteral("%1  %2").arg(s.stage).arg(QString::fromStdString(s.key)));
        b->setCheckable(true);
        b->setFocusPolicy(Qt::NoFocus);
        b->setObjectName(QStringLiteral("stage-%1").arg(QString::fromStdString(s.key)));
        buttons_->addButton(b, static_cast<int>(i));
        row->addWidget(b, int(i) / 2, int(i) % 2);
    }
    buttons_->setExclusive(true);
    layout->addLayout(row);

    text_ = new QTextBrowser;
    text_->setObjectName("stageText");
    text_->setOpenLinks(false);
    text_->viewport()->installEventFilter(this);
    layout->addWidget(text_, 1);

    progress_ = new QLabel;
    progress_->setObjectName("walkProgress");
    progress_->setWordWrap(true);
    progress_->hide();
    layout->addWidget(progress_);

    auto* nav = new QHBoxLayout;
    previous_ = new QPushButton;
    previous_->setObjectName("walkBack");
    next_ = new QPushButton;
    next_->setObjectName("walkNext");
    for (QPushButton* b : {previous_, next_})
        b->setFocusPolicy(Qt::NoFocus);
    nav->addWidget(previous_);
    nav->addStretch(1);
    nav->addWidget(next_);
    layout->addLayout(nav);

    connect(buttons_, &QButtonGroup::idClicked, this, &StageNavigator::request);
    connect(previous_, &QPushButton::clicked, this, &StageNavigator::stepBack);
    connect(next_, &QPushButton::clicked, this, &StageNavigator::stepForward);
    retranslate();
    setCurrent(SceneId::Bounce1d);
}

QString StageNavigator::describe(const SceneInfo& s, int revealed)
{
    const int shown =
        revealed < 0 ? static_cast<int>(s.equations.size()) : std::min(revealed, static_cast<int>(s.equations.size()));
    QString out =
        QStringLiteral("<h3 style='margin-bottom:2px'>%1: %2</h3>").arg(tr("Stage %1").arg(s.stage), html(s.title));
    out += QStringLiteral("<p style='margin-top:0'><i>%1 %2</i></p>").arg(tr("Report:"), html(s.reportRef));
    out += QStringLiteral("<p>%1</p>").arg(html(s.summary));
    // The walk opens a stage with none of its equations shown: no heading over nothing.
    if (shown > 0)
        out += QStringLiteral("<p><b>%1</b></p>").arg(tr("Equations"));
    out += QStringLiteral("<table cellspacing='0' cellpadding='2'>");
    for (int i = 0; i < shown; ++i) {
        const Equation& e = s.equations[static_cast<std::size_t>(i)];
        // In the walk the newest equation stands out; the formulas are the report's own.
        const bool newest = revealed >= 0 && i + 1 == shown;
        const QString formula = newest ? QStringLiteral("<b><tt>%1</tt></b>") : QStringLiteral("<tt>%1</tt>");
        const QString anchor =
            newest ? QStringLiteral("<a name='%1'></a>").arg(QLatin1String(kNewestAnchor)) : QString();
        out += QStringLiteral("<tr><td>%1(%2)</td><td>%3</td></tr><tr><td></td><td><i>%4</i></td></tr>")
                   .arg(anchor, QString::fromStdString(e.number).toHtmlEscaped(),
                        formula.arg(formulaHtml(QString::fromStdString(e.text))), html(e.meaning));
    }
    out += QStringLiteral("</table>");
    if (!s.notes.empty() && shown == static_cast<int>(s.equations.size())) {
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
    revealed_ = 0;
    const int i = indexOf(scene);
    buttons_->button(i)->setChecked(true);
    showText();
}

QString StageNavigator::text() const
{
    // The formulas hold together with no-break spaces and word joiners (formulaHtml): plain
    // spaces, and nothing, to read.
    return text_->toPlainText().replace(QChar(0x00A0), QLatin1Char(' ')).remove(QChar(0x2060));
}

void StageNavigator::setWalking(bool on)
{
    walking_ = on;
    retranslate();
    setCurrent(current_);
}

int StageNavigator::revealed() const
{
    return walking_ ? revealed_ : equationCount();
}

void StageNavigator::setRevealed(int count)
{
    if (!walking_)
        return;
    revealed_ = std::clamp(count, 0, equationCount());
    showText();
}

int StageNavigator::equationCount() const
{
    return static_cast<int>(sceneInfo(current_).equations.size());
}

void StageNavigator::stepForward()
{
    if (walking_ && revealed_ < equationCount()) {
        ++revealed_;
        showText();
        return;
    }
    next();
}

void StageNavigator::stepBack()
{
    if (walking_ && revealed_ > 0) {
        --revealed_;
        showText();
        return;
    }
    const SceneId before = current_;
    previous();
    if (walking_ && current_ != before) { // the window opened the previous stage
        revealed_ = equationCount();
        showText();
    }
}

void StageNavigator::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        showText();
    }
    QWidget::changeEvent(event);
}

void StageNavigator::retranslate()
{
    const auto& scenes = allScenes();
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const SceneInfo& s = *scenes[i];
        buttons_->button(static_cast<int>(i))
            ->setToolTip(tr("Stage %1: %2 (key %1)").arg(s.stage).arg(coreText(s.title)));
    }
    previous_->setText(walking_ ? tr("< Back") : tr("< Previous stage"));
    next_->setText(walking_ ? tr("Next >") : tr("Next stage >"));
}

void StageNavigator::setPreset(SceneId scene, const QString& name, const QString& description)
{
    presetScene_ = scene;
    presetName_ = name;
    presetDescription_ = description;
    showText();
}

void StageNavigator::setRunSection(const QString& html)
{
    if (html == runSection_)
        return;
    runSection_ = html;
    showText();
}

void StageNavigator::showText()
{
    const SceneInfo& info = sceneInfo(current_);
    QString preset;
    if (!presetName_.isEmpty() && presetScene_ == current_)
        preset = QStringLiteral("<h3 style='margin-bottom:2px'>%1</h3><p style='margin-top:0'>%2</p><hr>")
                     .arg(tr("Preset: %1").arg(coreText(presetName_.toStdString()).toHtmlEscaped()),
                          coreText(presetDescription_.toStdString()).toHtmlEscaped());
    // In the walk the run's section comes once the stage's own equations are all shown.
    const bool all = !walking_ || revealed_ >= equationCount();
    text_->setHtml(preset + describe(info, walking_ ? revealed_ : -1) + (all ? runSection_ : QString()));
    // Back and Next go nowhere before the first stage's start and after the last one's end.
    const int index = indexOf(current_);
    const bool last = index + 1 >= static_cast<int>(allScenes().size());
    previous_->setEnabled(index > 0 || (walking_ && revealed_ > 0));
    next_->setEnabled(!last || (walking_ && revealed_ < equationCount()));
    progress_->setVisible(walking_);
    if (!walking_)
        return;
    const int count = equationCount();
    progress_->setText(revealed_ == 0 ? tr("No equation shown yet, %1 to come. Next shows the first.").arg(count)
                       : revealed_ < count
                           ? tr("Equation %1 of %2. Next shows the next equation.").arg(revealed_).arg(count)
                       : last ? tr("All %1 equations shown: the last stage's walk is over.").arg(count)
                              : tr("All %1 equations shown. Next opens the next stage.").arg(count));
    keepInSight();
}

void StageNavigator::keepInSight()
{
    // In the walk the newest equation stands at the top of the text, the ones before it above
    // (scrolled away) and its meaning, the notes and the run below; before the first one the
    // stage's title and summary are read from their first line.
    if (!walking_)
        return;
    if (revealed_ == 0)
        text_->verticalScrollBar()->setValue(0);
    else
        text_->scrollToAnchor(QLatin1String(kNewestAnchor)); // once shown, where it is not shown yet
}

bool StageNavigator::eventFilter(QObject* watched, QEvent* event)
{
    // A resize re-wraps the text and moves what was kept in sight (a window first shown at its
    // size, lecture mode's larger fonts, a splitter dragged).
    if (watched == text_->viewport() && event->type() == QEvent::Resize)
        keepInSight();
    return QWidget::eventFilter(watched, event);
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
