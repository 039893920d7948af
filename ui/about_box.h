// SPDX-License-Identifier: MIT
// The About box: the program and its version, and the report it rebuilds with its authors.
#pragma once

#include <QString>

class QWidget;

namespace ab::ui {

// The About text (rich text), also shown by the box.
QString aboutText();
void showAboutBox(QWidget* parent);

} // namespace ab::ui
