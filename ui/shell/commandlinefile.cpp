#include "ui/shell/commandlinefile.h"

#include "ui/shell/mainwindow.h"
#include "ui/shell/recentfiles.h"
#include "ui/shell/statusbarwidget.h"
#include "ui/workspace/driveworkspace.h"

#include <QDir>
#include <QFileInfo>

namespace dd {

CommandLineFile::CommandLineFile(MainWindow *window, const QString &path)
    : QObject(window)
    , m_window(window)
    , m_path(QFileInfo(path).absoluteFilePath())
{
    m_window->recentFiles()->add(m_path);
    m_window->statusBarWidget()->showMessage(
        tr("%1 opens in the drive's tabs when a drive is selected: connect (File → Connect) or start the "
           "demo bench.")
            .arg(QDir::toNativeSeparators(m_path)));
    connect(m_window->workspace(), &DriveWorkspace::currentDriveChanged, this, &CommandLineFile::onDriveChanged);
}

QString CommandLineFile::checkReadable(const QString &path)
{
    const QFileInfo info(path);
    if (!info.exists())
        return tr("%1 does not exist.").arg(QDir::toNativeSeparators(path));
    if (!info.isFile() || !info.isReadable())
        return tr("%1 is not a file that can be read.").arg(QDir::toNativeSeparators(path));
    return {};
}

void CommandLineFile::onDriveChanged(int id, int address)
{
    if (id == 0)
        return;
    Q_UNUSED(address);
    if (m_window->workspace()->openFile(m_path))
        m_window->statusBarWidget()->clearMessage();
    else
        m_window->statusBarWidget()->showMessage(
            tr("No tab of this drive opens %1; it stays under File → Recent files.")
                .arg(QDir::toNativeSeparators(m_path)),
            15000);
    deleteLater(); // the first drive only
}

} // namespace dd
