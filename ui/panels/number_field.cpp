// SPDX-License-Identifier: MIT
#include "number_field.h"

#include "ui/i18n/language.h"

#include <QEvent>
#include <QKeyEvent>
#include <QKeySequence>
#include <QLineEdit>
#include <QRegularExpression>

#include <algorithm>
#include <iterator>

namespace ab::ui {

namespace {

// A real as parseReal reads it: sign, digits with one point, an exponent.
const QString real = QStringLiteral("[+-]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][+-]?\\d+)?");

const QRegularExpression& patternOf(NumberKind kind)
{
    // A count takes what a real does: a point typed into it is named by the parser ("1.5" is no
    // integer), where refused as a keystroke it vanished and 1.5 balls became 15.
    static const QRegularExpression realRe("\\A" + real + "\\z");
    static const QRegularExpression vectorRe("\\A" + real + "," + real + "," + real + "\\z");
    return kind == NumberKind::Vector ? vectorRe : realRe;
}

// The keys with Ctrl that edit a field's text everywhere: clipboard, undo, select all, and
// moving or deleting by words. Home and End move along the line without Ctrl.
bool isEditingKey(const QKeyEvent& key)
{
    static const QKeySequence::StandardKey editing[] = {QKeySequence::Copy,
                                                        QKeySequence::Cut,
                                                        QKeySequence::Paste,
                                                        QKeySequence::Undo,
                                                        QKeySequence::Redo,
                                                        QKeySequence::SelectAll,
                                                        QKeySequence::MoveToNextWord,
                                                        QKeySequence::MoveToPreviousWord,
                                                        QKeySequence::SelectNextWord,
                                                        QKeySequence::SelectPreviousWord,
                                                        QKeySequence::DeleteStartOfWord,
                                                        QKeySequence::DeleteEndOfWord};
    return std::any_of(std::begin(editing), std::end(editing),
                       [&](QKeySequence::StandardKey k) { return key.matches(k); });
}

} // namespace

NumberValidator::NumberValidator(NumberKind kind, QObject* parent) : QValidator(parent), kind_(kind) {}

QValidator::State NumberValidator::validate(QString& input, int&) const
{
    if (input.isEmpty())
        return Acceptable;
    // A comma outside a vector was refused as a keystroke: "9,81" became "981" unseen, g a
    // hundred times too large. In Swedish it is the decimal comma, read as the point and shown
    // so; in English it may group thousands ("2,000"), so it stays and the parser names the
    // text ("g: '9,81' is not a number") rather than the field guessing. In a vector the comma
    // parts the components.
    if (kind_ != NumberKind::Vector && input.contains(QLatin1Char(','))) {
        if (installedLanguage() != Language::Swedish)
            return Acceptable;
        input.replace(QLatin1Char(','), QLatin1Char('.'));
    }
    // A partial match is a beginning of a number; Acceptable (not Intermediate) so that
    // Enter and leaving the field always hand the text on: the parser names what is wrong.
    const QRegularExpressionMatch m = patternOf(kind_).match(input, 0, QRegularExpression::PartialPreferCompleteMatch);
    return m.hasMatch() || m.hasPartialMatch() ? Acceptable : Invalid;
}

NumberField::NumberField(QLineEdit* field, NumberKind kind) : QObject(field), field_(field)
{
    field->setValidator(new NumberValidator(kind, field));
    field->installEventFilter(this);
}

bool NumberField::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != field_ || (event->type() != QEvent::KeyPress && event->type() != QEvent::ShortcutOverride))
        return QObject::eventFilter(watched, event);
    const auto* key = static_cast<QKeyEvent*>(event);
    if (event->type() == QEvent::ShortcutOverride && (key->modifiers() & Qt::ControlModifier) && !isEditingKey(*key)) {
        // Ctrl with a letter is the window's (Ctrl+E exports the chart), not the line's: X11's
        // emacs keys (Ctrl+E to the end of the line) would swallow it while a value is typed.
        event->ignore();
        return true;
    }
    if (key->modifiers() & ~Qt::KeypadModifier)
        return false;
    if (key->key() == Qt::Key_Escape) {
        event->accept(); // the field's key, not the window's (full screen stays)
        if (event->type() == QEvent::KeyPress)
            emit reverted();
        return true;
    }
    if (event->type() == QEvent::KeyPress && (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter)) {
        field_->event(event); // editingFinished: the edit is applied or refused
        emit done();
        return true;
    }
    return false;
}

} // namespace ab::ui
