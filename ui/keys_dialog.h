// SPDX-License-Identifier: MIT
// Help > Keys and mouse: the keys as they act now (lecture mode takes Space and the arrows
// for its walk through the equations) and what the mouse does in the 3D view, in a box
// that fits the screen it opens on, scrolling where the text is taller (lecture mode's
// large text at 1280x720).
#pragma once

#include <QString>

class QDialog;
class QWidget;

namespace ab::ui {

// The keys and the mouse as rich text, for lecture mode or the window's own keys.
QString keysText(bool lecture);
// The box, not yet shown: at most the available height of `parent`'s screen.
QDialog* makeKeysDialog(QWidget* parent, bool lecture);

} // namespace ab::ui
