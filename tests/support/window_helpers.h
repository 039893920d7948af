// SPDX-License-Identifier: MIT
// Helpers shared by the window tests.
#pragma once

#include "ui/main_window.h"
#include "ui/panels/transport_bar.h"

#include <QLineEdit>
#include <QSlider>
#include <QTest>

#include <optional>

namespace testing {

// Types `text` into a field and finishes the edit (Return), as a user does.
inline void typeInto(QLineEdit* field, const QString& text)
{
    QVERIFY(field);
    field->setFocus();
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

// Takes `steps` single steps of the window's run, waits for them and brings the window up
// to date, then moves the time slider to numerator / denominator of its range, as a user
// looking back does. Returns the moment the window then shows; nothing if the steps did
// not come within QTest's usual five seconds.
inline std::optional<double> stepThenLookBack(ab::ui::MainWindow& w, long long steps, int numerator, int denominator)
{
    for (long long i = 0; i < steps; ++i)
        w.controller().stepOnce();
    if (!QTest::qWaitFor([&] { return w.controller().status().steps == steps; }))
        return std::nullopt;
    w.controller().poll();
    QSlider* time = w.transport()->timeSlider();
    time->setValue(time->maximum() * numerator / denominator);
    return w.transport()->viewTime();
}

} // namespace testing
