// SPDX-License-Identifier: MIT
#include "about_box.h"

#include <QCoreApplication>
#include <QMessageBox>

namespace ab::ui {

QString aboutText()
{
    return QCoreApplication::translate(
               "AboutBox", "<h3>Amazeballs %1</h3>"
                           "<p>Bouncing and colliding balls, stage by stage: a teaching tool that rebuilds the "
                           "student report beside textbook physics.</p>"
                           "<p>Built on the report <i>Amazeballs</i> (Modelling project TNM085, "
                           "Link\u00f6ping University, 13 March 2014) by <b>Sofie Lindblom</b>, "
                           "<b>Anton Arbring</b> and <b>David Lindh</b>; examiner Anna Lombardi. "
                           "Its four stages, equations, constants and Figures 2.5, 2.6, 2.7 and 3.1 are "
                           "reproduced here as the report gives them.</p>"
                           "<p>Licensed under the MIT licence.</p>")
        .arg(QCoreApplication::applicationVersion());
}

void showAboutBox(QWidget* parent)
{
    QMessageBox::about(parent, QCoreApplication::translate("AboutBox", "About Amazeballs"), aboutText());
}

} // namespace ab::ui
