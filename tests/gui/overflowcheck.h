#pragma once

// For the GUI tests that check a window fits its screen: every visible widget lies inside
// its parent and is not squeezed below what it needs to show its text; no horizontal scroll
// bar, no tab bar scrolling its tabs, no tool bar folding buttons away.

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QScrollBar>
#include <QTabBar>
#include <QTextDocument>
#include <QTextLayout>
#include <QToolBar>
#include <QWidget>
#include <algorithm>

namespace overflowcheck {

inline QString describe(const QWidget *w)
{
    QString path;
    for (const QWidget *p = w; p; p = p->parentWidget()) {
        const QString name = p->objectName().isEmpty() ? QString::fromLatin1(p->metaObject()->className())
                                                       : p->objectName();
        path = path.isEmpty() ? name : name + QLatin1Char('/') + path;
        if (p->inherits("dd::DrivePanel"))
            break;
    }
    if (auto *b = qobject_cast<const QAbstractButton *>(w))
        path += QStringLiteral(" \"%1\"").arg(b->text());
    else if (auto *l = qobject_cast<const QLabel *>(w))
        path += QStringLiteral(" \"%1\"").arg(l->text().left(60));
    return path;
}

// Inside a scroll area's viewport (placed by scrolling, not by a layout), or a part Qt
// places itself outside its parent on purpose.
inline bool scrolled(const QWidget *w, const QWidget *top)
{
    for (const QWidget *p = w->parentWidget(); p && p != top; p = p->parentWidget()) {
        auto *area = qobject_cast<const QAbstractScrollArea *>(p->parentWidget());
        if (area && area->viewport() == p)
            return true;
    }
    return false;
}

// A word-wrapping label cut: lower than its text needs at its width (the last lines
// clipped), or a piece of text that cannot be broken (a path, a long number) wider than it.
inline QStringList wrappedLabelProblems(QLabel *label)
{
    QStringList out;
    const int room = label->contentsRect().width() - 2 * label->margin() - std::max(0, label->indent());
    const int needHeight = label->heightForWidth(label->width());
    if (needHeight > label->height() + 1)
        out << QStringLiteral("wrapped text clipped (%1 px high for %2): ").arg(label->height()).arg(needHeight)
                + describe(label);
    QString text = label->text();
    if (Qt::mightBeRichText(text)) {
        QTextDocument d;
        d.setHtml(text);
        text = d.toPlainText();
    }
    // Laid out as the label wraps (at word boundaries; Chinese between characters): a line
    // wider than the label is a piece that cannot be broken, and is cut.
    text.replace(QLatin1Char('\n'), QChar::LineSeparator);
    QTextLayout layout(text, label->font());
    QTextOption option;
    option.setWrapMode(QTextOption::WordWrap);
    layout.setTextOption(option);
    layout.beginLayout();
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(room);
        if (line.naturalTextWidth() > room + 1) {
            out << QStringLiteral("unbreakable \"%1\" wider (%2) than the wrapped label (%3): ")
                        .arg(text.mid(line.textStart(), line.textLength()).trimmed().left(40))
                        .arg(int(line.naturalTextWidth()))
                        .arg(room)
                    + describe(label);
            break;
        }
    }
    layout.endLayout();
    return out;
}

// What a user would see cut in `top` as laid out now (empty: nothing).
inline QStringList problems(QWidget *top)
{
    QStringList out;
    QList<QWidget *> widgets = top->findChildren<QWidget *>();
    for (QWidget *w : std::as_const(widgets)) {
        if (!w->isVisibleTo(top) || w->isWindow())
            continue;
        if (auto *bar = qobject_cast<QScrollBar *>(w)) {
            if (bar->orientation() == Qt::Horizontal && bar->maximum() > bar->minimum())
                out << QStringLiteral("horizontal scroll bar: ") + describe(w->parentWidget());
            continue;
        }
        if (auto *tabs = qobject_cast<QTabBar *>(w)) {
            // Scroll arrows shown: some tab titles are out of view.
            for (QAbstractButton *b : tabs->findChildren<QAbstractButton *>(Qt::FindDirectChildrenOnly))
                if (b->isVisibleTo(top) && b->inherits("QToolButton")) {
                    QStringList titles;
                    for (int i = 0; i < tabs->count(); ++i)
                        titles << tabs->tabText(i);
                    out << QStringLiteral("tab bar scrolls: ") + describe(w) + QLatin1Char(' ') + titles.join(u'|');
                    break;
                }
        }
        if (w->inherits("QToolBarExtension")) {
            out << QStringLiteral("tool bar folds buttons away: ") + describe(w->parentWidget());
            continue;
        }
        if (scrolled(w, top) || w->parentWidget()->inherits("QTabBar"))
            continue;
        const QWidget *parent = w->parentWidget();
        const QRect inParent = w->geometry();
        if (inParent.right() > parent->width() + 1 || inParent.bottom() > parent->height() + 1 || inParent.left() < -1
            || inParent.top() < -1)
            out << QStringLiteral("outside its parent (%1,%2 %3×%4 in %5×%6): ")
                        .arg(inParent.x())
                        .arg(inParent.y())
                        .arg(inParent.width())
                        .arg(inParent.height())
                        .arg(parent->width())
                        .arg(parent->height())
                    + describe(w);
        // Texts squeezed below what they need (a button or label cut).
        const bool showsText = (qobject_cast<QAbstractButton *>(w)
                                && !static_cast<QAbstractButton *>(w)->text().isEmpty())
            || qobject_cast<QComboBox *>(w)
            || (qobject_cast<QLabel *>(w) && !static_cast<QLabel *>(w)->wordWrap()
                && !static_cast<QLabel *>(w)->text().isEmpty());
        if (showsText && w->sizePolicy().horizontalPolicy() != QSizePolicy::Ignored) {
            const QSize need = w->minimumSizeHint();
            if (need.isValid() && w->width() < need.width() - 1)
                out << QStringLiteral("narrower (%1) than it needs (%2): ").arg(w->width()).arg(need.width())
                        + describe(w);
        } else if (showsText && qobject_cast<QAbstractButton *>(w)) {
            // A button that lets its layout squeeze it (Ignored) still must show its text.
            const QSize need = w->sizeHint();
            if (need.isValid() && w->width() < need.width() - 1)
                out << QStringLiteral("button text cut (%1 px for %2): ").arg(w->width()).arg(need.width())
                        + describe(w);
        }
        if (auto *label = qobject_cast<QLabel *>(w); label && label->wordWrap() && !label->text().isEmpty())
            out << wrappedLabelProblems(label);
    }
    out.removeDuplicates();
    return out;
}

} // namespace overflowcheck
