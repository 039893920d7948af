// SPDX-License-Identifier: MIT
// Dialogs that open inside the screen: their content sits in a scroll area, so that a
// dialog smaller than its content (lecture mode's large fonts on a 1280x720 projector)
// scrolls inside instead of running off the screen, and the dialog is sized and placed
// within the available geometry of the screen its parent is on.
#pragma once

#include <QSize>

class QDialog;
class QVBoxLayout;
class QWidget;

namespace ab::ui {

// The layout to build the dialog's content in: inside a frameless scroll area that fills
// the dialog.
QVBoxLayout* scrollingContent(QDialog* dialog);
// `wanted` (or the content's size hint, when larger) bounded by the available geometry
// of the parent's screen, centred on it.
void fitToScreen(QDialog* dialog, QSize wanted);

} // namespace ab::ui
