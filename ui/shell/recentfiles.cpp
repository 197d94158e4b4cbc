#include "ui/shell/recentfiles.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace dd {

namespace {
const QString RecentFilesSettingKey = QStringLiteral("recentFiles");
}

RecentFiles::RecentFiles(QObject *parent)
    : QObject(parent)
{
}

void RecentFiles::setMenu(QMenu *menu)
{
    m_menu = menu;
    rebuildMenu();
}

void RecentFiles::add(const QString &path)
{
    const QString abs = QFileInfo(path).absoluteFilePath();
    m_files.removeAll(abs);
    m_files.prepend(abs);
    while (m_files.size() > MaxFiles)
        m_files.removeLast();
    save();
    rebuildMenu();
    emit changed();
}

void RecentFiles::remove(const QString &path)
{
    if (m_files.removeAll(path) == 0)
        return;
    save();
    rebuildMenu();
    emit changed();
}

void RecentFiles::clear()
{
    m_files.clear();
    save();
    rebuildMenu();
    emit changed();
}

void RecentFiles::load()
{
    QSettings s;
    m_files = s.value(RecentFilesSettingKey).toStringList();
    while (m_files.size() > MaxFiles)
        m_files.removeLast();
    rebuildMenu();
    emit changed();
}

void RecentFiles::save() const
{
    QSettings s;
    s.setValue(RecentFilesSettingKey, m_files);
}

void RecentFiles::rebuildMenu()
{
    if (!m_menu)
        return;
    m_menu->clear();
    int n = 0;
    for (const QString &path : std::as_const(m_files)) {
        ++n;
        const QString label = n < 10 ? QStringLiteral("&%1 %2").arg(n).arg(QFileInfo(path).fileName())
                                     : QFileInfo(path).fileName();
        QAction *a = m_menu->addAction(label);
        a->setToolTip(QDir::toNativeSeparators(path));
        a->setStatusTip(QDir::toNativeSeparators(path));
        connect(a, &QAction::triggered, this, [this, path] { emit fileTriggered(path); });
    }
    if (m_files.isEmpty()) {
        m_menu->addAction(tr("(none)"))->setEnabled(false);
    } else {
        m_menu->addSeparator();
        m_menu->addAction(tr("&Clear list"), this, &RecentFiles::clear);
    }
}

} // namespace dd
