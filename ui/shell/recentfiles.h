#pragma once

#include <QObject>
#include <QPointer>
#include <QStringList>

class QMenu;

namespace dd {

// File → Recent files: the last files used (backups, parameter sets, dictionaries), most
// recent first, persisted in the "recentFiles" setting. Panels that open or save a file
// report it with add() (via DrivePanel::fileUsed); choosing an entry emits
// fileTriggered(), which the main window hands to the selected drive's panels.
class RecentFiles : public QObject
{
    Q_OBJECT
public:
    static constexpr int MaxFiles = 8;

    explicit RecentFiles(QObject *parent = nullptr);

    void setMenu(QMenu *menu);
    QStringList files() const { return m_files; }
    void add(const QString &path);
    void remove(const QString &path);
    void clear();

    void load();
    void save() const;
    void rebuildMenu(); // also after a language change

signals:
    void fileTriggered(const QString &path);
    void changed();

private:
    QPointer<QMenu> m_menu;
    QStringList m_files;
};

} // namespace dd
