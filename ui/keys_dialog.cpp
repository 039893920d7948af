// SPDX-License-Identifier: MIT
#include "keys_dialog.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QGuiApplication>
#include <QPushButton>
#include <QScreen>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>

namespace ab::ui {

namespace {

// The words are the window's (Help > Keys and mouse is its menu): its translation context.
struct KeysWords {
    Q_DECLARE_TR_FUNCTIONS(MainWindow)
};

QString row(const QString& keys, const QString& what)
{
    return QStringLiteral("<tr><td style='padding-right:12px'><b>%1</b></td><td>%2</td></tr>").arg(keys, what);
}

} // namespace

QString keysText(bool lecture)
{
    QString rows;
    if (lecture) {
        rows += row(KeysWords::tr("Space, Right, PgDn"),
                    KeysWords::tr("lecture mode: the next equation, then the next stage"));
        rows += row(KeysWords::tr("Left, PgUp"), KeysWords::tr("lecture mode: back one equation"));
        rows += row(KeysWords::tr("Play"),
                    KeysWords::tr("the Play button runs the stage (Space walks the equations here)"));
        rows += row(KeysWords::tr("F11"), KeysWords::tr("full screen; Esc leaves it"));
    } else {
        rows += row(KeysWords::tr("Space"), KeysWords::tr("play / pause"));
        rows += row(KeysWords::tr("Right"), KeysWords::tr("one step"));
    }
    rows += row(KeysWords::tr("R"), KeysWords::tr("reset the run"));
    rows += row(KeysWords::tr("[ ]"), KeysWords::tr("slower / faster"));
    rows += row(KeysWords::tr("1 - 5"),
                lecture ? KeysWords::tr("the report's four stages and the street")
                        : KeysWords::tr("the report's four stages and the street; PgUp / PgDn: previous / next"));
    rows += row(KeysWords::tr("Ctrl+E"), KeysWords::tr("export the current chart (Ctrl+Shift+E: its data as CSV)"));
    rows += row(KeysWords::tr("Home"), KeysWords::tr("reset the 3D view; T: turntable"));
    rows += row(KeysWords::tr("F S G"),
                KeysWords::tr("the street's camera: from the foot, from the side, following the flood"));
    const QString mouse = KeysWords::tr(
        "<b>3D view</b>: left drag orbits, right or middle drag (or Shift+left) pans, the wheel zooms (on the "
        "street towards what is under the pointer, and the camera stops short of the road, the houses and the "
        "cars), a click selects a ball, a double click on empty space resets the view. After a click in the "
        "view the arrow keys move the camera as in the report's WebGL program; Esc gives them back.");
    return QStringLiteral("<table cellspacing='0' cellpadding='2'>%1</table><p>%2</p>").arg(rows, mouse);
}

QDialog* makeKeysDialog(QWidget* parent, bool lecture)
{
    auto* dialog = new QDialog(parent);
    dialog->setObjectName("keysDialog");
    dialog->setWindowTitle(KeysWords::tr("Keys and mouse"));
    auto* text = new QTextBrowser;
    text->setObjectName("keysText");
    text->setFrameShape(QFrame::NoFrame);
    text->viewport()->setAutoFillBackground(false);
    text->setHtml(keysText(lecture));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok);
    QObject::connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(text, 1);
    layout->addWidget(buttons);
    // As wide as 62 characters of the text's font (at most the screen), as tall as the text
    // then is, and at most the screen's free height: beyond it the text scrolls.
    const QRect screen =
        (parent && parent->screen() ? parent->screen() : QGuiApplication::primaryScreen())->availableGeometry();
    const int width = std::min(text->fontMetrics().averageCharWidth() * 62, screen.width() - 40);
    text->document()->setTextWidth(width);
    const int chrome = buttons->sizeHint().height() + 3 * layout->spacing() + 2 * layout->contentsMargins().top();
    const int wanted = int(text->document()->size().height()) + 8 + chrome;
    dialog->resize(width + 2 * layout->contentsMargins().left(), std::min(wanted, screen.height() - 60));
    return dialog;
}

} // namespace ab::ui
