// SPDX-License-Identifier: MIT
// A numeric field of the side panels. It takes only what can become a number of its kind
// (a real, an integer, or three reals "x,y,z"), so a single-key shortcut (Space, [ ])
// never types into it; Enter applies the edit and hands the keyboard back to the view,
// Esc puts the applied value back.
#pragma once

#include <QObject>
#include <QString>
#include <QValidator>

class QLineEdit;

namespace ab::ui {

enum class NumberKind { Real, Integer, Vector };

// Acceptable: the text is a number of its kind or the beginning of one ("", "-", "1e",
// "2,"); Invalid: no number starts so. The whole text is judged by the parser on Enter.
// Outside a vector a comma is, in Swedish, the decimal comma and becomes a point; in English
// it is kept for the parser to name. An integer field takes a real's characters too, so that
// the parser names "1.5" instead of a dropped keystroke turning it into 15.
class NumberValidator : public QValidator {
    Q_OBJECT
public:
    NumberValidator(NumberKind kind, QObject* parent);
    State validate(QString& input, int& pos) const override;

private:
    NumberKind kind_;
};

// Makes `field` a numeric field of `kind`: the validator above, Enter (after the field's
// own editingFinished) emits done(), Esc emits reverted() and keeps the key from the
// window (it does not leave full screen while a field is being edited). Ctrl with a key the
// field does not edit by (clipboard, undo, select all, words) goes to the window's shortcuts.
class NumberField : public QObject {
    Q_OBJECT
public:
    NumberField(QLineEdit* field, NumberKind kind);

signals:
    void done();
    void reverted();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QLineEdit* field_;
};

} // namespace ab::ui
