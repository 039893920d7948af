// SPDX-License-Identifier: MIT
#include "number_field.h"

#include <QEvent>
#include <QKeyEvent>
#include <QLineEdit>
#include <QRegularExpression>

namespace ab::ui {

namespace {

// A real as parseReal reads it: sign, digits with one point, an exponent.
const QString real = QStringLiteral("[+-]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][+-]?\\d+)?");

const QRegularExpression& patternOf(NumberKind kind)
{
    static const QRegularExpression realRe("\\A" + real + "\\z");
    static const QRegularExpression integerRe(QStringLiteral("\\A[+-]?\\d+\\z"));
    static const QRegularExpression vectorRe("\\A" + real + "," + real + "," + real + "\\z");
    switch (kind) {
    case NumberKind::Integer:
        return integerRe;
    case NumberKind::Vector:
        return vectorRe;
    case NumberKind::Real:
        break;
    }
    return realRe;
}

} // namespace

NumberValidator::NumberValidator(NumberKind kind, QObject* parent) : QValidator(parent), kind_(kind) {}

QValidator::State NumberValidator::validate(QString& input, int&) const
{
    if (input.isEmpty())
        return Acceptable;
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
