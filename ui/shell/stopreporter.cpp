#include "ui/shell/stopreporter.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"
#include "ui/bus/drivedirectory.h"
#include "ui/common/displaytext.h"

#include <QPointer>
#include <QTimer>

namespace dd {

StopReporter::StopReporter(DriveDirectory *directory, QObject *parent)
    : QObject(parent)
    , m_directory(directory)
{
}

void StopReporter::start()
{
    ++m_generation; // a STOP while the last one is still being confirmed starts afresh
    m_started = true;
    m_lines.clear();
    for (int id : m_directory->connections()) {
        if (m_directory->linkState(id) != DriveDirectory::LinkState::Open)
            continue;
        for (int address : m_directory->drives(id)) {
            const DriveInfo info = m_directory->info(id, address);
            Line l;
            l.connectionId = id;
            l.address = address;
            l.family = m_directory->discovered(id, address).family;
            l.wasEnabled = info.status.enabled;
            // Before the description arrives, assume a stop command (and confirm it).
            l.hasStop = !info.valid || info.capabilities.testFlag(Capability::Stop)
                || info.capabilities.testFlag(Capability::EmergencyStop);
            m_lines << l;
        }
    }
    m_pending = int(m_lines.size());
    const int generation = m_generation;
    for (int i = 0; i < m_lines.size(); ++i)
        poll(generation, i);
    if (m_pending == 0)
        emit finished();
}

void StopReporter::poll(int generation, int index)
{
    if (generation != m_generation || index >= m_lines.size())
        return;
    Line &l = m_lines[index];
    ++l.reads;
    QPointer<StopReporter> self(this);
    m_directory->hub()->run(
        l.connectionId, l.address, [](Drive &d) { return d.readStatus(); },
        [self, generation, index](const DriveResult &r) {
            if (!self || generation != self->m_generation)
                return;
            Line &line = self->m_lines[index];
            if (r.ok())
                line.status = r.status;
            if (!r.ok()) {
                self->settle(index, Outcome::Failed, r.error.message);
                return;
            }
            if (!r.status.running) {
                self->settle(index, line.hasStop ? Outcome::Stopped : Outcome::AtRest);
                return;
            }
            // No stop command: nothing DriveDesk sent will stop it; one read tells.
            if (!line.hasStop) {
                self->settle(index, Outcome::NotSupported);
                return;
            }
            if (line.reads * PollIntervalMs >= ConfirmTimeoutMs) {
                self->settle(index, Outcome::Failed);
                return;
            }
            QTimer::singleShot(PollIntervalMs, self, [self, generation, index] {
                if (self)
                    self->poll(generation, index);
            });
        });
}

void StopReporter::settle(int index, Outcome outcome, const QString &error)
{
    Line &l = m_lines[index];
    if (l.outcome != Outcome::Pending)
        return;
    l.outcome = outcome;
    l.error = error;
    --m_pending;
    emit updated();
    if (m_pending == 0)
        emit finished();
}

QString StopReporter::lineText(const Line &l)
{
    const QString name = DisplayText::driveName(l.family, l.address);
    switch (l.outcome) {
    case Outcome::Pending: return tr("%1: stop sent, waiting for its state…").arg(name);
    case Outcome::Stopped:
        // servo-can's STOP is "stop and disable": say so, the next motion needs an Enable.
        if (l.wasEnabled && !l.status.enabled)
            return tr("%1: stopped (the drive reports the axis at rest); STOP switched its power stage off.").arg(name);
        return tr("%1: stopped (the drive reports the axis at rest).").arg(name);
    case Outcome::AtRest: return tr("%1: has no stop command; it is at rest.").arg(name);
    case Outcome::NotSupported:
        return tr("%1: has no stop command and is still moving; DriveDesk cannot stop it. Use the "
                  "machine's emergency stop or switch off the drive's servo-on input.")
            .arg(name);
    case Outcome::Failed:
        return l.error.isEmpty() ? tr("%1: STOP failed: the drive still reports motion.").arg(name)
                                 : tr("%1: STOP failed: %2").arg(name, l.error);
    }
    return QString();
}

QString StopReporter::summary() const
{
    if (!m_started)
        return QString();
    if (m_lines.isEmpty())
        return tr("STOP sent; no drive is connected.");
    QStringList parts;
    for (const Line &l : m_lines)
        parts << lineText(l);
    return tr("STOP: %1").arg(parts.join(QLatin1Char(' ')));
}

QString StopReporter::details() const
{
    if (!m_started)
        return QString();
    if (m_lines.isEmpty())
        return tr("STOP sent; no drive is connected.");
    QStringList parts{tr("What STOP did, drive by drive:")};
    for (const Line &l : m_lines)
        parts << lineText(l);
    return parts.join(QLatin1Char('\n'));
}

} // namespace dd
