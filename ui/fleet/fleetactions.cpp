#include "ui/fleet/fleetactions.h"

#include "core/params/backupfile.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/drivedirectory.h"
#include "ui/compare/compareview.h"
#include "ui/fleet/fleetapplydialog.h"

#include <QAction>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>

namespace dd {

FleetActions::FleetActions(DriveDirectory *directory, BusTreeWidget *busTree, QMenu *menu, QWidget *window)
    : QObject(window)
    , m_directory(directory)
    , m_window(window)
{
    m_compare = new QAction(this);
    m_compare->setObjectName(QStringLiteral("compareAction"));
    menu->addAction(m_compare);
    connect(m_compare, &QAction::triggered, this, [this] { openCompare(0, {}); });
    connect(busTree, &BusTreeWidget::compareRequested, this, &FleetActions::openCompare);
    connect(busTree, &BusTreeWidget::applyBackupRequested, this, &FleetActions::applyBackup);
    connect(busTree, &BusTreeWidget::copyParametersRequested, this, &FleetActions::copyParameters);
    window->installEventFilter(this);
    retranslate();
}

bool FleetActions::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_window && event->type() == QEvent::LanguageChange)
        retranslate();
    return QObject::eventFilter(watched, event);
}

void FleetActions::retranslate()
{
    m_compare->setText(tr("Co&mpare parameters…"));
}

void FleetActions::openCompare(int connectionId, const QList<int> &addresses)
{
    auto *view = new CompareView(m_directory, m_window);
    view->setAttribute(Qt::WA_DeleteOnClose);
    for (int a : addresses)
        view->addDrive(connectionId, a);
    view->show();
}

void FleetActions::applyBackup(int connectionId, const QList<int> &addresses)
{
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Apply a backup to several drives"), QString(),
                                                      tr("DriveDesk backups (*.json *.ddbackup);;All files (*)"));
    if (path.isEmpty())
        return;
    BackupFile file;
    if (Error e = file.load(path)) {
        QMessageBox::warning(m_window, tr("Apply backup"), e.message);
        return;
    }
    const Family family = m_directory->connectionSettings(connectionId).family;
    if (file.family() && *file.family() != family) {
        QMessageBox::warning(m_window, tr("Apply backup"),
                             tr("%1 is a backup of a %2 drive; these are %3 drives. A backup is never applied to "
                                "another family.")
                                 .arg(QFileInfo(path).fileName(), familyId(*file.family()), familyId(family)));
        return;
    }
    auto *dialog = new FleetApplyDialog(m_directory, connectionId, addresses, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setSourceFile(file, QFileInfo(path).fileName(), path);
    dialog->show();
}

void FleetActions::copyParameters(int connectionId, int source, const QList<int> &targets)
{
    auto *dialog = new FleetApplyDialog(m_directory, connectionId, targets, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setSourceDrive(source);
    dialog->show();
}

} // namespace dd
