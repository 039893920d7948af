// SPDX-License-Identifier: MIT
#include "lecture_mode.h"

#include "ui/panels/stage_navigator.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMainWindow>
#include <QPaintDeviceWindow>
#include <QPlainTextEdit>
#include <QSplitter>
#include <QTextEdit>

namespace ab::ui {

namespace {

bool typingInFocus()
{
    QWidget* w = QApplication::focusWidget();
    if (!w)
        return false;
    if (qobject_cast<QLineEdit*>(w) || qobject_cast<QAbstractSpinBox*>(w))
        return true;
    if (auto* edit = qobject_cast<QTextEdit*>(w))
        return !edit->isReadOnly();
    if (auto* edit = qobject_cast<QPlainTextEdit*>(w))
        return !edit->isReadOnly();
    return false;
}

// The 3D view (an OpenGL window in its container) holds the keys after a click: its arrows
// move the camera and its Esc gives the keys back, as the hint it draws says.
bool viewInFocus()
{
    return qobject_cast<QPaintDeviceWindow*>(QGuiApplication::focusObject()) != nullptr;
}

} // namespace

LectureMode::LectureMode(QObject* parent) : QObject(parent)
{
    qApp->installEventFilter(this); // F11 and Esc work in and out of lecture mode
}

LectureMode::~LectureMode()
{
    qApp->removeEventFilter(this);
}

void LectureMode::attach(QMainWindow* window, StageNavigator* navigator)
{
    window_ = window;
    navigator_ = navigator;
    desktopColumns_.clear();
    desktopLeft_.clear();
    if (navigator_)
        navigator_->setWalking(active_);
    if (active_) {
        setFullScreen(true);
        arrangePanels(true);
    }
}

void LectureMode::setActive(bool on)
{
    if (on == active_)
        return;
    active_ = on;
    if (navigator_)
        navigator_->setWalking(on);
    setFullScreen(on);
    arrangePanels(on);
    emit activeChanged(on);
}

namespace {

const QList<int> lectureColumns{2000, 4000, 4000};
const QList<int> lectureLeft{10000, 0}; // the settings folded away

// Shares as pixels of the splitter's width (or height): QSplitter takes larger numbers
// from the widgets without stretch, which left the left column most of the screen.
QList<int> pixels(const QSplitter* splitter, const QList<int>& shares)
{
    const bool across = splitter->orientation() == Qt::Horizontal;
    const int room = (across ? splitter->width() : splitter->height()) - splitter->handleWidth() * (shares.size() - 1);
    int sum = 0;
    for (int share : shares)
        sum += share;
    QList<int> out;
    for (int share : shares)
        out << std::max(0, room) * share / std::max(sum, 1);
    return out;
}

} // namespace

void LectureMode::arrangePanels(bool lecture)
{
    // The 3D view and the charts are the lecture: they take four fifths of the width in
    // equal shares, the left column a fifth, and in it the navigator (the walk's
    // equations) all of it; the settings below fold away (drag the handle up for them).
    // Proportions, not pixels: QSplitter shares its actual size out by them.
    auto save = [lecture](QSplitter* splitter, QList<int>& saved) {
        if (!splitter)
            return;
        if (lecture) {
            saved = splitter->sizes();
        } else if (!saved.isEmpty()) {
            splitter->setSizes(saved);
            saved.clear();
        }
    };
    save(columnSplitter(), desktopColumns_);
    save(leftSplitter(), desktopLeft_);
    if (lecture)
        applyShares();
}

QSplitter* LectureMode::columnSplitter() const
{
    return window_ ? qobject_cast<QSplitter*>(window_->centralWidget()) : nullptr;
}

QSplitter* LectureMode::leftSplitter() const
{
    return navigator_ ? qobject_cast<QSplitter*>(navigator_->parentWidget()) : nullptr;
}

void LectureMode::applyShares()
{
    if (!active_)
        return;
    for (auto [splitter, shares] :
         {std::pair{columnSplitter(), lectureColumns}, std::pair{leftSplitter(), lectureLeft}})
        if (splitter && splitter->count() == shares.size())
            splitter->setSizes(pixels(splitter, shares));
}

void LectureMode::next()
{
    if (navigator_)
        navigator_->stepForward();
}

void LectureMode::previous()
{
    if (navigator_)
        navigator_->stepBack();
}

void LectureMode::setFullScreen(bool on)
{
    if (!window_ || window_->isFullScreen() == on)
        return;
    if (on)
        window_->showFullScreen();
    else
        window_->showNormal();
    emit fullScreenChanged(on);
}

LectureMode::Command LectureMode::commandFor(const QKeyEvent& key) const
{
    if (key.modifiers() & ~Qt::KeypadModifier)
        return Command::None;
    switch (key.key()) {
    case Qt::Key_F11:
        return Command::FullScreen;
    case Qt::Key_Escape:
        return window_ && window_->isFullScreen() && !viewInFocus() ? Command::LeaveFullScreen : Command::None;
    case Qt::Key_PageDown:
        return active_ ? Command::Next : Command::None;
    case Qt::Key_PageUp:
        return active_ ? Command::Previous : Command::None;
    case Qt::Key_Space:
        return active_ && !typingInFocus() ? Command::Next : Command::None;
    case Qt::Key_Right:
        return active_ && !typingInFocus() && !viewInFocus() ? Command::Next : Command::None;
    case Qt::Key_Left:
        return active_ && !typingInFocus() && !viewInFocus() ? Command::Previous : Command::None;
    default:
        return Command::None;
    }
}

bool LectureMode::eventFilter(QObject* watched, QEvent* event)
{
    // Full screen arrives as a resize after the panels were arranged: keep the shares.
    if (event->type() == QEvent::Resize && active_ && watched == window_)
        QMetaObject::invokeMethod(
            this, [this] { applyShares(); }, Qt::QueuedConnection);
    if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
        return QObject::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    const Command command = commandFor(*key);
    if (command == Command::None || !window_ || !window_->isActiveWindow())
        return QObject::eventFilter(watched, event);
    key->accept();
    if (event->type() == QEvent::ShortcutOverride)
        return true; // claims the key from the window's shortcuts; it comes back as a KeyPress
    switch (command) {
    case Command::Next:
        next();
        break;
    case Command::Previous:
        previous();
        break;
    case Command::FullScreen:
        setFullScreen(!window_->isFullScreen());
        break;
    case Command::LeaveFullScreen:
        setFullScreen(false);
        break;
    case Command::None:
        break;
    }
    return true;
}

} // namespace ab::ui
