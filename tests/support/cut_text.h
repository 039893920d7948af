// SPDX-License-Identifier: MIT
// Text a window shows cut: a label, button, combo box, table header, tab or chart text whose
// width (by QFontMetrics, or the rich text's laid-out size) passes its rectangle, or that Qt
// shortened itself with an ellipsis (Qt Charts' axes, titles and legends).
#pragma once

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsTextItem>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QScrollArea>
#include <QStringList>
#include <QStyleOptionComboBox>
#include <QTabBar>
#include <QTextDocument>

#include <algorithm>

namespace testing {

// Qt Widgets elide with "…"; Qt Charts with three dots ("Export CSV..." is a whole text).
inline bool showsEllipsis(const QString& text)
{
    return text.contains(QChar(0x2026));
}

inline bool chartShowsEllipsis(const QString& text)
{
    return text.contains(QChar(0x2026)) || text.endsWith(QLatin1String("..."));
}

inline QString where(const QWidget* w)
{
    QStringList path;
    for (const QObject* o = w; o; o = o->parent())
        if (!o->objectName().isEmpty())
            path.prepend(o->objectName());
    return QStringLiteral("%1 [%2]").arg(QString::fromLatin1(w->metaObject()->className()), path.join('/'));
}

// The text as a button shows it: "&Run" reads "Run", "&&" an ampersand.
inline QString shown(QString text)
{
    text.replace(QLatin1String("&&"), QStringLiteral("\x01"));
    text.remove('&');
    text.replace(QChar(1), '&');
    return text;
}

inline void checkLabel(const QLabel* label, QStringList& cut)
{
    const QString text = label->buddy() ? shown(label->text()) : label->text(); // "&t end" reads "t end"
    if (text.isEmpty())
        return;
    const QRect room = label->contentsRect();
    bool fits = true;
    if (Qt::mightBeRichText(text) || label->textFormat() == Qt::RichText) {
        QTextDocument doc;
        doc.setDefaultFont(label->font());
        doc.setDocumentMargin(0);
        doc.setHtml(text);
        if (label->wordWrap()) {
            doc.setTextWidth(room.width());
            fits = doc.size().height() <= room.height() + 2;
        } else {
            fits = doc.idealWidth() <= room.width() + 2;
        }
    } else if (label->wordWrap()) {
        fits = label->heightForWidth(label->width()) <= label->height() + 2;
    } else {
        const QFontMetrics fm(label->font());
        int widest = 0;
        for (const QString& line : text.split('\n'))
            widest = std::max(widest, fm.horizontalAdvance(line));
        fits = widest <= room.width() + 1;
    }
    if (!fits || showsEllipsis(text))
        cut << QStringLiteral("%1: '%2' in %3x%4").arg(where(label), text).arg(room.width()).arg(room.height());
}

inline void checkButton(const QAbstractButton* button, QStringList& cut)
{
    const QString text = shown(button->text());
    if (text.isEmpty())
        return;
    const QFontMetrics fm(button->font());
    const int icon = button->icon().isNull() ? 0 : button->iconSize().width() + 4;
    // A check box's or radio button's indicator; a checkable push or tool button has none.
    const bool indicated = qobject_cast<const QCheckBox*>(button) || qobject_cast<const QRadioButton*>(button);
    const int indicator = indicated ? 20 : 0;
    const int need = fm.horizontalAdvance(text) + icon + indicator + 4;
    if (need > button->width() || showsEllipsis(text))
        cut << QStringLiteral("%1: '%2' needs %3 of %4").arg(where(button), text).arg(need).arg(button->width());
}

inline void checkCombo(const QComboBox* combo, QStringList& cut)
{
    QStyleOptionComboBox opt;
    opt.initFrom(combo);
    opt.editable = combo->isEditable();
    opt.rect = combo->rect();
    const QRect field = combo->style()->subControlRect(QStyle::CC_ComboBox, &opt, QStyle::SC_ComboBoxEditField, combo);
    const int need = QFontMetrics(combo->font()).horizontalAdvance(combo->currentText());
    if (need > field.width() + 1)
        cut << QStringLiteral("%1: '%2' needs %3 of %4")
                   .arg(where(combo), combo->currentText())
                   .arg(need)
                   .arg(field.width());
}

inline void checkHeader(const QHeaderView* header, QStringList& cut)
{
    if (!header->model() || header->orientation() != Qt::Horizontal)
        return;
    const QFontMetrics fm(header->font());
    const int margin = 2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
    for (int i = 0; i < header->count(); ++i) {
        if (header->isSectionHidden(i) || header->sectionSize(i) == 0)
            continue;
        const QString text = header->model()->headerData(i, Qt::Horizontal).toString();
        const int need = fm.horizontalAdvance(text) + margin;
        if (need > header->sectionSize(i) + 1)
            cut << QStringLiteral("%1: column '%2' needs %3 of %4")
                       .arg(where(header), text)
                       .arg(need)
                       .arg(header->sectionSize(i));
    }
}

inline void checkTabs(const QTabBar* tabs, QStringList& cut)
{
    // Tabs that run past the bar's edge are cut there, or behind its scroll arrows.
    if (tabs->count() > 0 && tabs->tabRect(tabs->count() - 1).right() > tabs->width())
        cut << QStringLiteral("%1: tabs past the edge").arg(where(tabs));
    const QFontMetrics fm(tabs->font());
    for (int i = 0; i < tabs->count(); ++i) {
        const QString text = shown(tabs->tabText(i));
        if (fm.horizontalAdvance(text) > tabs->tabRect(i).width() || showsEllipsis(text))
            cut << QStringLiteral("%1: tab '%2'").arg(where(tabs), text);
    }
}

inline void checkChart(const QChartView* view, QStringList& cut)
{
    if (!view->chart() || !view->scene())
        return;
    for (const QGraphicsItem* item : view->scene()->items()) {
        if (!item->isVisible())
            continue;
        QString text;
        if (const auto* t = dynamic_cast<const QGraphicsTextItem*>(item))
            text = t->toPlainText();
        else if (const auto* s = dynamic_cast<const QGraphicsSimpleTextItem*>(item))
            text = s->text();
        if (chartShowsEllipsis(text))
            cut << QStringLiteral("%1 '%2': '%3'").arg(where(view), view->chart()->title(), text);
    }
    if (view->chart()->plotArea().height() < 40)
        cut << QStringLiteral("%1 '%2': a plot %3 pixels high")
                   .arg(where(view), view->chart()->title())
                   .arg(view->chart()->plotArea().height());
}

// A widget the user sees part of. A scroll area's own region is covered whole by its viewport
// (a chart view's too): what shows of it is its viewport's region.
inline bool isShown(const QWidget* w)
{
    if (!w->isVisible())
        return false;
    const auto* area = qobject_cast<const QAbstractScrollArea*>(w);
    return !(area ? area->viewport()->visibleRegion() : w->visibleRegion()).isEmpty();
}

// Every visible text-bearing widget under `root` (a window or a dialog).
inline QStringList cutTexts(QWidget* root)
{
    QStringList cut;
    QList<QWidget*> all = root->findChildren<QWidget*>();
    all.prepend(root);
    for (QWidget* w : all) {
        if (!isShown(w))
            continue;
        if (auto* label = qobject_cast<QLabel*>(w))
            checkLabel(label, cut);
        else if (auto* button = qobject_cast<QAbstractButton*>(w))
            checkButton(button, cut);
        else if (auto* combo = qobject_cast<QComboBox*>(w))
            checkCombo(combo, cut);
        else if (auto* header = qobject_cast<QHeaderView*>(w))
            checkHeader(header, cut);
        else if (auto* tabs = qobject_cast<QTabBar*>(w))
            checkTabs(tabs, cut);
        else if (auto* view = qobject_cast<QChartView*>(w))
            checkChart(view, cut);
    }
    return cut;
}

// The settings' labels, fields and combo boxes that reach past the scroll area's viewport
// (hidden at its edge), or whose own text is cut.
inline QStringList cutAtViewport(QScrollArea* scroll)
{
    QStringList cut;
    const QRect port = scroll->viewport()->rect();
    for (QWidget* w : scroll->widget()->findChildren<QWidget*>()) {
        if (!w->isVisible() ||
            !(qobject_cast<QLabel*>(w) || qobject_cast<QComboBox*>(w) || qobject_cast<QLineEdit*>(w)))
            continue;
        const QRect at(w->mapTo(scroll->viewport(), QPoint(0, 0)), w->size());
        if (at.left() < port.left() || at.right() > port.right())
            cut << QStringLiteral("%1 at x %2-%3 of a %4 px viewport")
                       .arg(where(w))
                       .arg(at.left())
                       .arg(at.right())
                       .arg(port.width());
        if (auto* label = qobject_cast<QLabel*>(w))
            checkLabel(label, cut);
        else if (auto* combo = qobject_cast<QComboBox*>(w))
            checkCombo(combo, cut);
    }
    return cut;
}

} // namespace testing
