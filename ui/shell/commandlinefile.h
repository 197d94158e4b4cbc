#pragma once

#include <QObject>
#include <QString>

namespace dd {

class MainWindow;

// `drivedesk FILE` (what the desktop does when a DriveDesk backup or run file is opened):
// the file goes to File → Recent files at once, and is handed to the drive's tabs when a
// drive is first selected (the first drive found is selected by itself after a connect or
// the demo bench); a backup then opens in the Backup tab, compared with the drive. Until
// then, and when no tab takes the file, the status bar says so.
class CommandLineFile : public QObject
{
    Q_OBJECT
public:
    CommandLineFile(MainWindow *window, const QString &path);

    // A clear message when `path` cannot be opened (missing, unreadable), else empty.
    static QString checkReadable(const QString &path);

private:
    void onDriveChanged(int id, int address);

    MainWindow *m_window = nullptr;
    QString m_path;
};

} // namespace dd
