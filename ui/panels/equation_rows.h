// SPDX-License-Identifier: MIT
// Equations as the navigator and the run's own equation panels set them: a formula that a
// narrow column (lecture mode's large text) breaks only between its parts, and a row of
// number, formula and meaning.
#pragma once

#include <QString>

namespace ab::ui {

// `formula`, typed in ASCII as the core and the panels keep it ("mu >= q tan(theta) / (1 + q)",
// "g t^2 / 2"), with its symbols as a page prints them ("μ ≥ q tan(θ) / (1 + q)", "g t² / 2"):
// Greek letters named as whole words (and after the d of a derivative, "domega/dt" is "dω/dt"),
// the powers ^2 and ^3, a minus sign where "-" stands as a sign or an operation (not between
// two characters of a name, "S9-S10"), <=, >=, != and ->, and sqrt.
QString formulaTypography(const QString& formula);

// formulaTypography(`formula`) as HTML that breaks only after a comma ending one relation ("a = ..., r w = v")
// and before a relation or the sign of a sum or a quotient ("= ...", "+ ...", "/ ..."), and
// between words of prose beside it or before a note in brackets ("(normalised)"); never
// inside a bracket of 16 characters or fewer.
// Every other space holds (a no-break space, and a word joiner after "-" and "/"): "mu g
// cos(theta)" and "(q r)" stay whole.
QString formulaHtml(const QString& formula);

// One equation: its number, the formula (formulaHtml) and, on the line below, what it means.
QString equationRow(const QString& number, const QString& formula, const QString& meaning);

} // namespace ab::ui
