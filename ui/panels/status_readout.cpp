// SPDX-License-Identifier: MIT
#include "status_readout.h"

#include "ui/i18n/core_text.h"
#include "ui/i18n/health_text.h"

#include "core/street/street_census.h"

#include <QApplication>
#include <QEvent>
#include <QFrame>
#include <QLabel>

#include <QLayout>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

enum class Shade { Severe, Notice };

// A colour through the palette, not a style sheet: a style sheet would fix the label's
// font at the size it had when set, and lecture mode's text size would stay after it.
// Red and amber are darker on light themes and lighter on dark ones (4.5:1 either way).
void setColour(QLabel* label, std::optional<Shade> shade)
{
    QPalette p; // only the text colour is the label's own; the theme gives the rest
    if (shade) {
        const bool dark = QApplication::palette().color(QPalette::Window).lightness() < 128;
        const QColor colour = *shade == Shade::Severe ? (dark ? QColor(0xff, 0x8a, 0x80) : QColor(0xb0, 0x30, 0x20))
                                                      : (dark ? QColor(0xff, 0xcc, 0x66) : QColor(0x8a, 0x5a, 0x00));
        p.setColor(QPalette::WindowText, colour);
    }
    label->setPalette(p);
    QFont bold; // only the weight: the size stays the application's, lecture mode's or not
    bold.setBold(shade == Shade::Severe);
    label->setFont(bold);
}

// A reading keeps at least its base width, so that the bar does not jitter as digits come
// and go, and never less than its text: the warning beside it takes the rest (lecture
// mode's larger text included), and a reading is never cut.
// Queued: a new minimum relays out the window at once, and the readings are shown while
// the run's recording is locked (MainWindow::refreshReadings), which a relayout's chart
// refresh would lock again.
void fitText(QLabel* label)
{
    QTimer::singleShot(0, label, [label] {
        label->setMinimumWidth(std::max(label->property("baseWidth").toInt(), label->sizeHint().width()));
    });
}

} // namespace

QString formatDuration(double seconds)
{
    if (!std::isfinite(seconds) || seconds <= 0.0)
        return QStringLiteral("\u2013"); // no figure yet: a dash, not a minus sign
    if (seconds < 1e-3)
        return QStringLiteral("%1 \u00b5s").arg(seconds * 1e6, 0, 'g', 3);
    if (seconds < 1.0)
        return QStringLiteral("%1 ms").arg(seconds * 1e3, 0, 'g', 3);
    return QStringLiteral("%1 s").arg(seconds, 0, 'g', 3);
}

StatusReadout::StatusReadout(QStatusBar* bar) : QObject(bar)
{
    auto label = [bar](const char* name, int width) {
        auto* l = new QLabel;
        l->setObjectName(QString::fromLatin1(name));
        l->setProperty("baseWidth", width);
        l->setMinimumWidth(width);
        l->setContentsMargins(8, 0, 0, 0); // readings wider than their base width stay apart
        bar->addPermanentWidget(l);
        return l;
    };
    warning_ = new QLabel;
    warning_->setObjectName("statusWarning");
    // The bar shows a message's first part; Details opens the whole of it.
    warning_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    warning_->setMinimumWidth(120);
    bar->addWidget(warning_, 1);
    warning_->installEventFilter(this); // a new width may fit the headline, or no longer
    details_ = new QToolButton;
    details_->setObjectName("statusDetails");
    details_->setText(tr("Details"));
    details_->setToolTip(tr("The whole message: what happened, the rule behind it and what to change"));
    details_->setFocusPolicy(Qt::NoFocus);
    details_->hide();
    bar->addWidget(details_);
    connect(details_, &QToolButton::clicked, this, &StatusReadout::showDetails);
    time_ = label("statusTime", 130);
    step_ = label("statusStep", 120);
    fps_ = label("statusFps", 70);
    energy_ = label("statusEnergy", 190);
    energy_->setContentsMargins(8, 0, 8, 0); // the bar's last reading stands clear of the screen's edge
    step_->setToolTip(tr("Wall time of one simulation step"));
    fps_->setToolTip(tr("Frames drawn per second by the 3D view"));
    energyTip_ = tr("Kinetic plus potential energy, summed over the balls, with the height measured "
                    "from the floor: per unit mass in the report model, with the masses in the physical one");
    energy_->setToolTip(energyTip_);
}

void StatusReadout::setRun(const RunSpec& spec)
{
    spec_ = spec;
    street_.reset();
    if (spec.scene == SceneId::Street)
        street_ = std::make_shared<const street::Layout>(street::Layout::fromParams(spec.params));
}

StatusReadout::Message StatusReadout::streetCensus(const Frame& shown) const
{
    // Counted from the frame on screen: a ball beyond the open foot has left the run.
    int left = 0, firstFoot = 0;
    double fastest = 0.0;
    for (int i = 0; i < shown.balls(); ++i) {
        const auto k = std::size_t(3 * i);
        const auto x = double(shown.p[k]);
        firstFoot += x > street_->blockFootX.front() ? 1 : 0;
        if (street::hasLeft(*street_, x)) {
            ++left;
            continue;
        }
        if (k + 2 < shown.v.size())
            fastest = std::max(fastest, std::hypot(double(shown.v[k]), double(shown.v[k + 1]), double(shown.v[k + 2])));
    }
    if (left == shown.balls()) { // none on the street: no fastest ball to name
        const QString gone =
            left == 1 ? tr("The ball has left at the foot") : tr("All %1 balls have left at the foot").arg(left);
        return {gone, gone, Tone::Plain, tr("Balls on the street"), {tr("All have left at the foot")}};
    }
    const QString speed = QString::number(fastest, 'f', 1);
    if (shown.balls() == 1) { // one ball (the one-ball preset): where it is and how fast
        const QString text = firstFoot > 0 ? tr("The ball is past the first block's foot at %1 m/s").arg(speed)
                                           : tr("The ball is on the first block at %1 m/s").arg(speed);
        return {text, text, Tone::Plain, tr("The ball on the street"), {tr("%1 m/s").arg(speed)}};
    }
    const QString text =
        tr("%1 balls on the street, %2 past the first block's foot, %3 out at the foot; fastest %4 m/s")
            .arg(shown.balls() - left)
            .arg(firstFoot)
            .arg(left)
            .arg(speed);
    // A lecture hall's bar holds a few words: the balls gone and the fastest say most.
    const QStringList shorter = {
        tr("%1 on the street, %2 out at the foot; fastest %3 m/s").arg(shown.balls() - left).arg(left).arg(speed),
        tr("%1 out at the foot; fastest %2 m/s").arg(left).arg(speed), tr("fastest %1 m/s").arg(speed)};
    return {text, text, Tone::Plain, tr("Balls on the street"), shorter};
}

void StatusReadout::show(const EngineStatus& s, const Frame* shown, bool lookingBack)
{
    const bool back = lookingBack && shown;
    const double t = back ? shown->t : s.t;
    const double energy = back ? shown->scene.energy.total() : s.energy;
    const SceneInfo* info = spec_ ? &sceneInfo(spec_->scene) : nullptr;
    const QString timeUnit = info ? coreText(info->timeUnit) : QString();
    const QString lengthUnit = info ? coreText(info->lengthUnit) : QString();
    time_->setText(tr("t = %1 %2").arg(QString::number(t, 'f', t < 100 ? 2 : 1), timeUnit));
    step_->setText(tr("%1 per step").arg(formatDuration(s.stepSeconds))); // "t = 855 step step 2 us" read as one
    showEnergy(energy, s.energyPerUnitMass, lengthUnit, timeUnit);
    for (QLabel* reading : {time_, step_, energy_})
        fitText(reading);
    const Message m = messageFor(s, shown, back);
    message_ = m;
    if (popup_ && popup_->isVisible() && m.full != popup_->findChild<QLabel*>("statusDetailsText")->text())
        placeDetails(); // open Details follow the moment shown (the street's census)
    warning_->setToolTip(m.full);
    setColour(warning_, m.tone == Tone::Severe   ? std::optional(Shade::Severe)
                        : m.tone == Tone::Notice ? std::optional(Shade::Notice)
                                                 : std::nullopt);
    fitWarning();
}

void StatusReadout::showEnergy(double energy, bool perUnitMass, const QString& lengthUnit, const QString& timeUnit)
{
    const QString sq = QString::fromUtf8("\u00b2");
    const QString unit = QStringLiteral("%1%2/%3%2").arg(lengthUnit, sq, timeUnit);
    const long long n = street_ ? spec_->params.integer("n") : 0;
    if (!std::isfinite(energy)) {
        energy_->setText(perUnitMass ? tr("E/m = -") : tr("E = -"));
    } else if (n > 2 && perUnitMass) {
        // The street's sum over 10,000 balls runs to millions of m^2/s^2, which a lecture
        // hall cannot read; the mean a ball, sum/n, reads the same for any crowd, and the
        // energy chart draws it too. The tooltip gives the sum. (Stage 4's 150 balls sum
        // to a readable figure, and its long units leave the bar no room for "a ball".)
        energy_->setText(tr("E/m = %1 %2 a ball").arg(QString::number(energy / double(n), 'g', 4), unit));
        energy_->setToolTip(tr("Kinetic plus potential energy per unit mass, with the height measured from the "
                               "street's foot, and what the balls that left at the foot took with them: the mean over "
                               "the %1 balls, as the energy chart draws it. All balls together: %2 %3")
                                .arg(n)
                                .arg(QString::number(energy, 'g', 5), unit));
        return;
    } else if (perUnitMass) {
        energy_->setText(tr("E/m = %1 %2").arg(QString::number(energy, 'g', 5), unit));
    } else { // the physical model's masses are in kg
        energy_->setText(tr("E = %1 kg %2").arg(QString::number(energy, 'g', 5), unit));
    }
    energy_->setToolTip(energyTip_);
}

void StatusReadout::fitWarning()
{
    const Message& m = message_;
    const int room = warning_->contentsRect().width();
    const QFontMetrics fm = warning_->fontMetrics();
    QString text = m.brief.isEmpty() ? m.headline : m.brief;
    for (const QStringList forms = QStringList{m.headline} + m.shorter; const QString& form : forms)
        if (fm.horizontalAdvance(form) <= room) {
            text = form;
            break;
        }
    if (warning_->text() != text)
        warning_->setText(text);
    details_->setVisible(m.full != text);
}

bool StatusReadout::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == warning_ && (event->type() == QEvent::Resize || event->type() == QEvent::FontChange))
        fitWarning();
    return QObject::eventFilter(watched, event);
}

StatusReadout::Message StatusReadout::messageFor(const EngineStatus& s, const Frame* shown, bool back) const
{
    if (!spec_)
        return {};
    const SceneInfo& info = sceneInfo(spec_->scene);
    const double t = back ? shown->t : s.t;
    // Only what the run had found by the moment shown.
    const bool finding = s.health != diagnostics::Health::Ok && (!back || s.worst.t <= t + 1e-12);
    const FindingText found = finding ? HealthText::describe(s.worst, info) : FindingText{};
    // The most serious first: a run that stopped, a failure the health check found (the
    // run paused on it), the report's own rules at work, then a warning of the check.
    if (!s.warning.empty() && !back) {
        if (finding && s.worst.finding.kind == diagnostics::FindingKind::NonFinite)
            return {tr("Stopped: %1").arg(found.headline()), tr("Stopped: %1").arg(found.full()), Tone::Severe,
                    tr("The run stopped")};
        const QString text = tr("Stopped: %1").arg(QString::fromStdString(s.warning));
        return {text, text, Tone::Severe, tr("The run stopped")};
    }
    if (finding && s.worst.level == diagnostics::Health::Failed) {
        const bool paused = s.pausedOnHealth && !back;
        const QString form = paused ? tr("Paused: %1") : QStringLiteral("%1");
        return {form.arg(found.headline()), form.arg(found.full()), Tone::Severe,
                paused ? tr("Paused: the health check failed") : tr("The health check failed")};
    }
    if (const auto rules = reportRulesAt(s, shown, back))
        return {rules->section(QStringLiteral(": "), 0, 0), *rules, Tone::Notice, tr("The report's rules at work")};
    // A finding the report's own rule explains (stage 1's explicit Euler adds energy from its
    // first step) is the model at work, not a fault: a class's first run said "A health check
    // warning" where the headline did not fit.
    // Where the bar has room the headline says it is the rule's doing, so that stage 2's
    // "The energy is 0.0116% above its start" does not read as a fault of the program.
    if (finding && s.worst.finding.rule != diagnostics::ReportRule::None)
        return {tr("%1: the report's own rule").arg(found.headline()),
                found.full(),
                Tone::Notice,
                tr("The report's rules at work"),
                {found.headline()}};
    if (finding)
        return {found.headline(), found.full(), Tone::Notice, tr("A health check warning")};
    if (s.finished && !back && s.emptiedAt && shown) {
        // The street's run ends when its last ball has left: the rest would be an empty street.
        const QString at = QString::number(*s.emptiedAt, 'f', 2);
        const bool one = shown->balls() == 1;
        const QString text =
            one ? tr("The ball has left at the foot at t = %1 s; the run ends there, and Play starts it again").arg(at)
                : tr("All %1 balls have left at the foot by t = %2 s; the run ends there, and Play starts it again")
                      .arg(shown->balls())
                      .arg(at);
        return {text,
                text,
                Tone::Plain,
                tr("The run is complete"),
                {one ? tr("The ball has left at t = %1 s; the run is complete").arg(at)
                     : tr("All %1 balls have left by t = %2 s; the run is complete").arg(shown->balls()).arg(at),
                 // Lecture mode's large text at 1280x720 holds only these: they still say the run ended.
                 one ? tr("Run complete: the ball left at t = %1 s").arg(at)
                     : tr("Run complete: all have left by t = %1 s").arg(at),
                 tr("Run complete at t = %1 s").arg(at)}};
    }
    if (s.finished && !back) {
        const QString text = tr("The run is complete; Play starts it again");
        return {text, text, Tone::Plain, tr("The run is complete")};
    }
    if (street_ && shown)
        return streetCensus(*shown);
    return {};
}

std::optional<QString> StatusReadout::reportRulesAt(const EngineStatus& s, const Frame* shown, bool back) const
{
    if (spec_->model != ModelKind::Report)
        return std::nullopt;
    const SceneInfo& info = sceneInfo(spec_->scene);
    const double t = back ? shown->t : s.t;
    QStringList parts;
    if (s.haltedAt && *s.haltedAt <= t + 1e-12)
        parts << HealthText::halted(info, spec_->params, *s.haltedAt);
    if (shown && spec_->scene == SceneId::TwoBalls && s.haltedAt && *s.haltedAt <= t + 1e-12) {
        // After the counter the positions go on from the zeroed velocities: the floor rule
        // p = v dt, v = -k 0 + g dt (Appendix B) leaves a ball g dt^2 below the floor.
        int lowest = -1;
        for (int i = 0; i < shown->balls(); ++i)
            if (shown->p[std::size_t(3 * i + 1)] < 0.0f &&
                (lowest < 0 || shown->p[std::size_t(3 * i + 1)] < shown->p[std::size_t(3 * lowest + 1)]))
                lowest = i;
        if (lowest >= 0)
            parts << tr("ball %1 rests %2 %3 below the floor, where the floor rule of Appendix B put it in the step "
                        "the velocities were zeroed, so its potential energy, and E/m, are below zero")
                         .arg(lowest + 1)
                         .arg(figure(-double(shown->p[std::size_t(3 * lowest + 1)])), coreText(info.lengthUnit));
    }
    if (shown && spec_->scene == SceneId::ManyBalls) {
        // Appendix D updates only balls above the floor: one that reaches it keeps the
        // velocity it had, which the energy and momentum charts go on counting.
        const float floor = float(-(spec_->params.real("box") / 2.0 - spec_->params.real("r")));
        int kept = 0;
        for (int i = 0; i < shown->balls(); ++i) {
            const std::size_t k = std::size_t(3 * i);
            if (shown->p[k + 1] <= floor && (shown->v[k] != 0.0f || shown->v[k + 1] != 0.0f || shown->v[k + 2] != 0.0f))
                ++kept;
        }
        if (kept > 0)
            parts << tr("%1 of %2 balls lie on the floor with a velocity but do not move: Appendix D updates only "
                        "balls above the floor, so a ball keeps the velocity it reached the floor with, and the "
                        "kinetic energy and momentum charts go on counting it")
                         .arg(kept)
                         .arg(shown->balls());
    }
    if (parts.isEmpty())
        return std::nullopt;
    return parts.join(QStringLiteral("; "));
}

void StatusReadout::showDetails()
{
    if (!popup_) {
        popup_ = new QFrame(warning_->window(), Qt::Popup);
        popup_->setObjectName("statusDetailsPopup");
        popup_->setFrameShape(QFrame::Box);
        auto* layout = new QVBoxLayout(popup_);
        auto* text = new QLabel;
        text->setObjectName("statusDetailsText");
        text->setWordWrap(true);
        text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout->addWidget(text);
    }
    placeDetails();
    popup_->show();
}

void StatusReadout::placeDetails()
{
    auto* text = popup_->findChild<QLabel*>("statusDetailsText");
    text->setText(message_.full);
    QWidget* window = warning_->window();
    const int width = std::max(320, window->width() / 2);
    popup_->setFixedWidth(width);
    popup_->layout()->activate();
    popup_->setFixedHeight(popup_->layout()->totalHeightForWidth(width));
    const QPoint corner = warning_->mapToGlobal(QPoint(0, 0));
    popup_->move(corner.x(), corner.y() - popup_->height() - 4);
}

void StatusReadout::setFrameRate(double fps)
{
    // %n: Swedish has "1 bild/s" and "2 bilder/s". Below 10 a frame a second shows a tenth:
    // the view of 250,000 balls draws a frame for each step of over a second, and "0 fps"
    // read as a view that had stopped.
    const double tenths = std::round(fps * 10.0) / 10.0;
    if (fps < 0.0)
        fps_->setText(tr("no 3D view"));
    else if (fps == 0.0)
        fps_->setText(tr("\u2013 fps"));
    else if (tenths < 0.1)
        fps_->setText(tr("< 0.1 fps"));
    else if (tenths < 10.0 && tenths != std::floor(tenths))
        fps_->setText(tr("%1 fps").arg(tenths, 0, 'f', 1));
    else
        fps_->setText(tr("%n fps", nullptr, static_cast<int>(std::lround(fps))));
    fitText(fps_);
}

QString StatusReadout::warningText() const
{
    return message_.full;
}

QString StatusReadout::warningShown() const
{
    return warning_->text();
}

QString StatusReadout::timeText() const
{
    return time_->text();
}

QString StatusReadout::energyText() const
{
    return energy_->text();
}

} // namespace ab::ui
