#include "ui/bus/statuspoller.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "ui/bus/drivedirectory.h"

#include <QPointer>

namespace dd {

StatusPoller::StatusPoller(DriveDirectory *directory, QObject *parent)
    : QObject(parent)
    , m_directory(directory)
{
    m_timer.setInterval(DefaultIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &StatusPoller::poll);
    connect(directory, &DriveDirectory::connectionRemoved, this, [this](int id) { m_paused.remove(id); });
}

void StatusPoller::setEnabled(bool on)
{
    if (on)
        m_timer.start();
    else
        m_timer.stop();
}

void StatusPoller::pauseConnection(int id, bool paused)
{
    if (paused)
        m_paused.insert(id);
    else
        m_paused.remove(id);
}

void StatusPoller::poll()
{
    QPointer<StatusPoller> self(this);
    for (int id : m_directory->connections()) {
        if (m_paused.contains(id) || m_directory->linkState(id) != DriveDirectory::LinkState::Open)
            continue;
        for (int address : m_directory->drives(id)) {
            const quint64 key = (quint64(quint32(id)) << 32) | quint32(address);
            if (m_inFlight.contains(key))
                continue;
            m_inFlight.insert(key);
            m_directory->hub()->run(
                id, address, [](Drive &d) { return d.readStatus(); },
                [self, key, id, address](const DriveResult &r) {
                    if (!self)
                        return;
                    self->m_inFlight.remove(key);
                    if (r.ok() && (r.status.online || r.status.updatedMs))
                        self->m_directory->updateStatus(id, address, r.status);
                    if (!r.ok()) {
                        self->m_directory->markNoAnswer(id, address);
                        emit self->pollFailed(id, address, r.error);
                    }
                });
        }
    }
}

} // namespace dd
