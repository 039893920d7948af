// SPDX-License-Identifier: MIT
#include "equation_rows.h"

#include <QStringList>

#include <algorithm>
#include <vector>

namespace ab::ui {

namespace {

// A word of prose beside the formula ("Walton's tangential impulse"), not a symbol: four
// letters or more, apostrophes allowed.
bool isWord(const QString& token)
{
    return token.size() >= 4 &&
           std::all_of(token.begin(), token.end(), [](QChar c) { return c.isLetter() || c == '\''; });
}

// For each character of `formula`, whether it lies in a bracket no longer than `shortest`
// characters, brackets included: "(1 + q)" is read as one term and never broken.
std::vector<bool> inShortBrackets(const QString& formula, qsizetype shortest)
{
    std::vector<bool> held(std::size_t(formula.size()), false);
    std::vector<qsizetype> open;
    for (qsizetype i = 0; i < formula.size(); ++i) {
        if (formula[i] == '(' || formula[i] == '[')
            open.push_back(i);
        else if ((formula[i] == ')' || formula[i] == ']') && !open.empty()) {
            const qsizetype from = open.back();
            open.pop_back();
            if (i - from + 1 <= shortest)
                std::fill(held.begin() + from, held.begin() + i + 1, true);
        }
    }
    return held;
}

} // namespace

QString formulaHtml(const QString& formula)
{
    // Relations and the signs of a sum or a quotient, ASCII and as the run's panels write them
    // (minus, approximately, at most, at least, not equal).
    static const QStringList breakBefore = {
        "=", "+", "-", "/", "<", ">", "<=", ">=", "->", "~", "\u2212", "\u2248", "\u2264", "\u2265", "\u2260"};
    const std::vector<bool> held = inShortBrackets(formula, 16);
    QString out;
    for (qsizetype i = 0; i < formula.size(); ++i) {
        const QChar c = formula[i];
        if (c != ' ') {
            out += QString(c).toHtmlEscaped();
            // Unicode's line breaking may end a line after a hyphen or a solidus even before a
            // no-break space ("v[new] = -" | "k v[old]", "dw/" | "dt"): a word joiner holds.
            if (c == '-' || c == '/')
                out += QChar(0x2060);
            continue;
        }
        if (i + 1 < formula.size() && formula[i + 1] == ' ')
            continue; // a run of spaces is one: a no-break space before a break began the next line
        const qsizetype end = formula.indexOf(' ', i + 1);
        const QString next = formula.mid(i + 1, end < 0 ? -1 : end - i - 1);
        qsizetype run = i; // the run of spaces this one ends
        while (run > 0 && formula[run - 1] == ' ')
            --run;
        const qsizetype start = formula.lastIndexOf(' ', run - 1) + 1;
        const QString previous = formula.mid(start, run - start);
        const bool afterComma = run > 0 && formula[run - 1] == ',';
        // A note in brackets after the formula, "(normalised)", may go to the next line.
        const bool note =
            next.size() > 2 && next.startsWith('(') && next.endsWith(')') && isWord(next.mid(1, next.size() - 2));
        const bool breaks = !held[std::size_t(i)] &&
                            (afterComma || breakBefore.contains(next) || note || (isWord(previous) && isWord(next)));
        out += breaks ? QStringLiteral(" ") : QStringLiteral("&nbsp;");
    }
    return out;
}

QString equationRow(const QString& number, const QString& formula, const QString& meaning)
{
    return QStringLiteral("<tr><td>(%1)</td><td><tt>%2</tt></td></tr><tr><td></td><td><i>%3</i></td></tr>")
        .arg(number, formulaHtml(formula), meaning.toHtmlEscaped());
}

} // namespace ab::ui
