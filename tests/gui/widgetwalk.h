#pragma once

// For the GUI tests that look at everything a user can see: every widget of a window that
// is shown (or would be, on another page of a tab / stacked widget), with each text it
// displays (labels, buttons, group titles, tab texts, combo items, headers, tree items,
// placeholders, tool tips, menus).

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QComboBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTextDocument>
#include <QTreeWidget>
#include <QWidget>
#include <functional>

namespace widgetwalk {

struct Text
{
    QWidget *widget = nullptr;
    QString what; // "label", "tooltip", "tab", ...
    QString text;
};

// Shown, or on a page of a stacked widget / tab widget the user can switch to.
inline bool reachable(const QWidget *w, const QWidget *top)
{
    for (const QWidget *p = w; p && p != top; p = p->parentWidget()) {
        if (!p->isHidden())
            continue;
        if (!qobject_cast<const QStackedWidget *>(p->parentWidget()))
            return false;
    }
    return true;
}

inline QString plain(const QString &text)
{
    if (!Qt::mightBeRichText(text))
        return text;
    QTextDocument d;
    d.setHtml(text);
    return d.toPlainText();
}

inline void addActions(QList<Text> *out, QWidget *owner, const QList<QAction *> &actions)
{
    for (QAction *a : actions) {
        if (!a->isVisible() || a->isSeparator())
            continue;
        out->append({owner, QStringLiteral("action"), a->text()});
        if (a->menu())
            addActions(out, a->menu(), a->menu()->actions());
    }
}

// Every text of `top` and its reachable children; `skip` leaves out a widget and its children.
inline QList<Text> texts(QWidget *top, const std::function<bool(QWidget *)> &skip = {})
{
    QList<Text> out;
    QList<QWidget *> widgets = top->findChildren<QWidget *>();
    widgets.prepend(top);
    for (QWidget *w : std::as_const(widgets)) {
        if (!reachable(w, top) || qobject_cast<QMenu *>(w))
            continue;
        bool skipped = false;
        for (QWidget *p = w; p && skip && !skipped; p = p->parentWidget())
            skipped = skip(p);
        if (skipped)
            continue;
        if (w == top)
            out.append({w, QStringLiteral("title"), w->windowTitle()});
        if (!w->toolTip().isEmpty())
            out.append({w, QStringLiteral("tooltip"), plain(w->toolTip())});
        if (auto *l = qobject_cast<QLabel *>(w))
            out.append({w, QStringLiteral("label"), plain(l->text())});
        else if (auto *b = qobject_cast<QAbstractButton *>(w))
            out.append({w, QStringLiteral("button"), b->text()});
        else if (auto *g = qobject_cast<QGroupBox *>(w))
            out.append({w, QStringLiteral("group"), g->title()});
        else if (auto *e = qobject_cast<QLineEdit *>(w))
            out.append({w, QStringLiteral("placeholder"), e->placeholderText()});
        else if (auto *c = qobject_cast<QComboBox *>(w)) {
            for (int i = 0; i < c->count(); ++i)
                out.append({w, QStringLiteral("combo item"), c->itemText(i)});
        } else if (auto *t = qobject_cast<QTabBar *>(w)) {
            for (int i = 0; i < t->count(); ++i)
                out.append({w, QStringLiteral("tab"), t->tabText(i)});
        } else if (auto *sb = qobject_cast<QStatusBar *>(w)) {
            out.append({w, QStringLiteral("status message"), sb->currentMessage()});
        } else if (auto *m = qobject_cast<QMenuBar *>(w)) {
            addActions(&out, m, m->actions());
        }
        if (auto *v = qobject_cast<QAbstractItemView *>(w); v && v->model() && !qobject_cast<QHeaderView *>(w)) {
            QAbstractItemModel *model = v->model();
            for (int c = 0; c < model->columnCount(); ++c)
                out.append({w, QStringLiteral("header"), model->headerData(c, Qt::Horizontal).toString()});
            // The first rows (a table of parameters repeats the same kinds of text).
            for (int r = 0; r < qMin(model->rowCount(), 60); ++r)
                for (int c = 0; c < model->columnCount(); ++c) {
                    const QModelIndex i = model->index(r, c);
                    out.append({w, QStringLiteral("cell"), i.data().toString()});
                    out.append({w, QStringLiteral("cell tooltip"), plain(i.data(Qt::ToolTipRole).toString())});
                }
            if (auto *tree = qobject_cast<QTreeWidget *>(w))
                for (QTreeWidgetItemIterator it(tree); *it; ++it)
                    for (int k = 0; k < tree->columnCount(); ++k) {
                        out.append({w, QStringLiteral("tree item"), (*it)->text(k)});
                        out.append({w, QStringLiteral("tree tooltip"), (*it)->toolTip(k)});
                    }
        }
    }
    return out;
}

} // namespace widgetwalk
