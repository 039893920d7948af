// SPDX-License-Identifier: MIT
// The status bar's readings of the moment on screen (live, or the moment the time slider
// looks back at): simulated time, the cost of one step, frames per second, the energy,
// and what the run says about that moment: a stopped run or a failed health check in red,
// the report's own rules at work (its bounce counter, balls that keep a velocity on the
// floor, a ball left below the floor) or a health warning in amber. Findings and notices
// are worded here, in the window's language and words, from the core's data; a message
// longer than the bar shows its first part, and Details opens the whole of it; where even
// that part would not fit the bar whole, the bar names the kind of message instead
// ("The report's rules at work"), so no message is ever cut mid-word.
#pragma once

#include "ui/sim/recording.h"
#include "ui/sim/run_engine.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

class QLabel;
class QStatusBar;
class QToolButton;
class QFrame;

namespace ab::ui {

class StatusReadout : public QObject {
    Q_OBJECT
public:
    explicit StatusReadout(QStatusBar* bar);
    bool eventFilter(QObject* watched, QEvent* event) override; // refits the message to its label

    // The run the readings are of: its scene's units, model and constants.
    void setRun(const RunSpec& spec);
    // `shown` is the frame on screen; with `lookingBack` its time and energy are read,
    // and only what the run had found by then is said.
    void show(const EngineStatus& status, const Frame* shown = nullptr, bool lookingBack = false);
    void setFrameRate(double fps); // negative: no 3D view
    QString warningText() const;   // the whole message (also what Details shows)
    QString warningShown() const;  // what the bar shows of it
    QString timeText() const;
    QString energyText() const;
    QToolButton* detailsButton() const { return details_; }

private:
    enum class Tone { Plain, Notice, Severe };
    struct Message {
        QString headline, full;
        Tone tone = Tone::Plain;
        QString brief;         // the kind of message, for a bar too narrow for the headline
        QStringList shorter{}; // shorter forms of the headline, longest first, tried before the brief
    };
    Message messageFor(const EngineStatus& s, const Frame* shown, bool lookingBack) const;
    std::optional<QString> reportRulesAt(const EngineStatus& s, const Frame* shown, bool lookingBack) const;
    // The street's census of the frame shown (on the street, past the first foot, left, the
    // fastest), whole and in two shorter forms for a narrower bar.
    Message streetCensus(const Frame& shown) const;
    void showDetails();
    void placeDetails(); // the Details popup's text, size and place, above the message
    void fitWarning();   // the headline where it fits whole, else the longest shorter form, else the brief
    // E/m (or E with the physical model's masses); on the street, a ball's mean.
    void showEnergy(double energy, bool perUnitMass, const QString& lengthUnit, const QString& timeUnit);

    QLabel* time_;
    QLabel* step_;
    QLabel* fps_;
    QLabel* energy_;
    QString energyTip_; // the energy's tooltip outside a crowd
    QLabel* warning_;
    QToolButton* details_;
    QFrame* popup_ = nullptr;
    Message message_; // the message of the moment shown (Details opens its whole text)
    std::optional<RunSpec> spec_;
    std::shared_ptr<const street::Layout> street_; // in stage 5
};

// "0.8 us", "12 ms", "1.3 s".
QString formatDuration(double seconds);

} // namespace ab::ui
