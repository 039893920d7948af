// SPDX-License-Identifier: MIT
#include "dialog_fit.h"

#include <QDialog>
#include <QGuiApplication>
#include <QScreen>
#include <QScrollArea>
#include <QVBoxLayout>

namespace ab::ui {

QVBoxLayout* scrollingContent(QDialog* dialog)
{
    auto* outer = new QVBoxLayout(dialog);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea;
    scroll->setObjectName("dialogScroll");
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    auto* content = new QWidget;
    content->setObjectName("dialogContent");
    scroll->setWidget(content);
    outer->addWidget(scroll);
    return new QVBoxLayout(content);
}

void fitToScreen(QDialog* dialog, QSize wanted)
{
    QScreen* screen = dialog->parentWidget() ? dialog->parentWidget()->screen() : QGuiApplication::primaryScreen();
    if (!screen)
        return;
    // A window manager adds a title bar and borders: leave them room.
    const QRect available = screen->availableGeometry().adjusted(8, 40, -8, -8);
    if (auto* scroll = dialog->findChild<QScrollArea*>("dialogScroll"))
        if (QWidget* content = scroll->widget())
            wanted = wanted.expandedTo(content->sizeHint());
    const QSize size = wanted.boundedTo(available.size());
    dialog->resize(size);
    dialog->move(available.center() - QPoint(size.width() / 2, size.height() / 2));
}

} // namespace ab::ui
