// SPDX-License-Identifier: MIT
#include "equation_rows.h"

#include <QRegularExpression>
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

// A character that may stand beside a Greek name without making it part of a longer word.
bool nameBoundary(const QString& s, qsizetype at)
{
    return at < 0 || at >= s.size() || !s[at].isLetterOrNumber(); // "mu_s" is mu with a subscript
}

// Greek letters named as words in the ASCII formulas, and their symbols.
struct GreekName {
    const char* name;
    char16_t symbol;
};
constexpr GreekName kGreek[] = {{"theta", u'\u03b8'}, {"omega", u'\u03c9'}, {"alpha", u'\u03b1'},  {"beta", u'\u03b2'},
                                {"Delta", u'\u0394'}, {"delta", u'\u03b4'}, {"lambda", u'\u03bb'}, {"sigma", u'\u03c3'},
                                {"rho", u'\u03c1'},   {"phi", u'\u03c6'},   {"tau", u'\u03c4'},    {"mu", u'\u03bc'},
                                {"pi", u'\u03c0'}};

QString greekLetters(const QString& in)
{
    QString out = in;
    for (const GreekName& g : kGreek) {
        const QString name = QLatin1String(g.name);
        for (qsizetype at = out.indexOf(name); at >= 0; at = out.indexOf(name, at + 1)) {
            // A whole word, or the d of a derivative before it ("domega/dt").
            const bool derivative = at >= 1 && out[at - 1] == 'd' && nameBoundary(out, at - 2);
            if ((nameBoundary(out, at - 1) || derivative) && nameBoundary(out, at + name.size()))
                out.replace(at, name.size(), QChar(g.symbol));
        }
    }
    return out;
}

// "-" as a sign or an operation: at the start, after a space, a bracket or another operation
// ("-k v", "(-(n.x", "a - b"); between two characters of a name it is a hyphen ("S9-S10").
QString minusSigns(const QString& in)
{
    QString out = in;
    for (qsizetype i = 0; i < out.size(); ++i) {
        if (out[i] != '-')
            continue;
        const QChar before = i > 0 ? out[i - 1] : QChar(' ');
        if (before.isSpace() || QStringLiteral("([=+*/,").contains(before))
            out[i] = QChar(0x2212);
    }
    return out;
}

} // namespace

QString formulaTypography(const QString& formula)
{
    QString out = greekLetters(formula);
    // Relations before the minus signs: "->" is an arrow before its hyphen could become a minus.
    out.replace(QLatin1String("<="), QString(QChar(0x2264)))
        .replace(QLatin1String(">="), QString(QChar(0x2265)))
        .replace(QLatin1String("!="), QString(QChar(0x2260)))
        .replace(QLatin1String("->"), QString(QChar(0x2192)));
    out = minusSigns(out);
    static const QRegularExpression square(QStringLiteral("\\^2(?![0-9])")), cube(QStringLiteral("\\^3(?![0-9])")),
        root(QStringLiteral("\\bsqrt\\("));
    out.replace(square, QString(QChar(0x00b2))).replace(cube, QString(QChar(0x00b3)));
    return out.replace(root, QString(QChar(0x221a)) + QLatin1Char('('));
}

QString formulaHtml(const QString& ascii)
{
    const QString formula = formulaTypography(ascii);
    // Relations and the signs of a sum or a quotient as formulaTypography sets them (a hyphen
    // after a space is a minus sign by then, "<=" an at-most sign, "->" an arrow).
    static const QStringList breakBefore = {"=",      "+",      "/",      "<",      ">",      "~",
                                            "\u2212", "\u2248", "\u2264", "\u2265", "\u2260", "\u2192"};
    const std::vector<bool> held = inShortBrackets(formula, 16);
    QString out;
    for (qsizetype i = 0; i < formula.size(); ++i) {
        const QChar c = formula[i];
        if (c != ' ') {
            out += QString(c).toHtmlEscaped();
            // Unicode's line breaking may end a line after a hyphen or a solidus even before a
            // no-break space ("v[new] = -" | "k v[old]", "dw/" | "dt"): a word joiner holds.
            if (c == '-' || c == '/' || c == QChar(0x2212))
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
