#include "ui/bus/drivedirectory.h"

#include "core/drive/drivehub.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QEvent>
#include <QPointer>

namespace dd {

DriveDirectory::DriveDirectory(DriveHub *hub, QObject *parent)
    : QObject(parent)
    , m_hub(hub)
{
    connect(hub, &DriveHub::statusChanged, this, &DriveDirectory::updateStatus);
    connect(hub, &DriveHub::alarmChanged, this, &DriveDirectory::onAlarm);
    connect(hub, &DriveHub::linkLost, this, &DriveDirectory::onLinkLost);
    if (QCoreApplication::instance())
        QCoreApplication::instance()->installEventFilter(this);
}

bool DriveDirectory::eventFilter(QObject *watched, QEvent *event)
{
    // The drive layer words its reasons and channel names in the language of the moment:
    // ask again after a switch (driveChanged follows with the new texts).
    if (watched == QCoreApplication::instance() && event->type() == QEvent::LanguageChange)
        for (auto c = m_connections.cbegin(); c != m_connections.cend(); ++c)
            if (c->state == LinkState::Open)
                for (int address : c->drives.keys())
                    refresh(c.key(), address);
    return QObject::eventFilter(watched, event);
}

void DriveDirectory::addConnection(int id, const ConnectionSettings &settings)
{
    Connection c;
    c.settings = settings;
    m_connections.insert(id, c);
    emit connectionAdded(id);
}

void DriveDirectory::removeConnection(int id)
{
    if (m_connections.remove(id))
        emit connectionRemoved(id);
}

void DriveDirectory::clear()
{
    const QList<int> ids = connections();
    for (int id : ids)
        removeConnection(id);
}

ConnectionSettings DriveDirectory::connectionSettings(int id) const
{
    return m_connections.value(id).settings;
}

DriveDirectory::LinkState DriveDirectory::linkState(int id) const
{
    return m_connections.value(id).state;
}

QString DriveDirectory::linkError(int id) const
{
    return m_connections.value(id).error;
}

void DriveDirectory::addDrive(int id, const DiscoveredDrive &drive)
{
    auto c = m_connections.find(id);
    if (c == m_connections.end())
        return;
    const bool isNew = !c->drives.contains(drive.address);
    Entry &e = c->drives[drive.address];
    e.discovered = drive;
    if (isNew) {
        e.info.connectionId = id;
        e.info.address = drive.address;
        e.info.identity.family = drive.family;
        e.info.identity.address = drive.address;
        e.info.identity.firmware = drive.firmware;
        e.info.identity.link = drive.link;
        emit driveAdded(id, drive.address);
        refresh(id, drive.address);
    } else {
        emit driveChanged(id, drive.address);
    }
}

QList<int> DriveDirectory::drives(int id) const
{
    return m_connections.value(id).drives.keys();
}

bool DriveDirectory::hasDrive(int id, int address) const
{
    auto c = m_connections.constFind(id);
    return c != m_connections.constEnd() && c->drives.contains(address);
}

DiscoveredDrive DriveDirectory::discovered(int id, int address) const
{
    return m_connections.value(id).drives.value(address).discovered;
}

DriveInfo DriveDirectory::info(int id, int address) const
{
    return m_connections.value(id).drives.value(address).info;
}

void DriveDirectory::refresh(int id, int address)
{
    QPointer<DriveDirectory> self(this);
    fetchDriveInfo(m_hub, id, address, [self, id, address](const DriveInfo &info, const Error &error) {
        if (!self || !self->hasDrive(id, address))
            return;
        Entry &e = self->m_connections[id].drives[address];
        if (info.valid) {
            DriveInfo merged = info;
            if (merged.identity.firmware.isEmpty())
                merged.identity.firmware = e.discovered.firmware;
            if (merged.identity.link.isEmpty())
                merged.identity.link = e.discovered.link;
            if (merged.status.updatedMs < e.info.status.updatedMs)
                merged.status = e.info.status;
            e.info = merged;
            emit self->driveChanged(id, address);
        }
        if (error.isError())
            emit self->errorOccurred(error);
    });
}

void DriveDirectory::markNoAnswer(int id, int address)
{
    auto c = m_connections.find(id);
    if (c == m_connections.end() || !c->drives.contains(address))
        return;
    DriveStatus &s = c->drives[address].info.status;
    if (!s.online && s.updatedMs)
        return;
    s.online = false;
    s.updatedMs = QDateTime::currentMSecsSinceEpoch();
    emit statusChanged(id, address, s);
    emit driveChanged(id, address);
}

void DriveDirectory::updateStatus(int id, int address, const DriveStatus &status)
{
    auto c = m_connections.find(id);
    if (c == m_connections.end() || !c->drives.contains(address))
        return;
    DriveStatus &current = c->drives[address].info.status;
    const bool same = current.online == status.online && current.running == status.running
        && current.enabled == status.enabled && current.positionValid == status.positionValid
        && current.position == status.position && current.alarmCode == status.alarmCode;
    current = status;
    if (same)
        return;
    emit statusChanged(id, address, status);
    emit driveChanged(id, address);
}

void DriveDirectory::onAlarm(int id, int address, int code)
{
    auto c = m_connections.find(id);
    if (c == m_connections.end() || !c->drives.contains(address))
        return;
    c->drives[address].info.status.alarmCode = code;
    emit alarmChanged(id, address, code);
    emit driveChanged(id, address);
}

void DriveDirectory::onLinkLost(int id, const Error &why)
{
    auto c = m_connections.find(id);
    if (c == m_connections.end())
        return;
    c->state = LinkState::Lost;
    c->error = why.message;
    for (Entry &e : c->drives)
        e.info.status.online = false;
    emit linkStateChanged(id);
    emit errorOccurred(why);
}

} // namespace dd
