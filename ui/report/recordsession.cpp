#include "ui/report/recordsession.h"

#include "core/drive/drivehub.h"
#include "core/params/alarmdictionary.h"
#include "core/report/linkhealthcounter.h"
#include "ui/bus/drivedirectory.h"

namespace dd {

RecordSession::RecordSession(DriveHub *hub, DriveDirectory *directory, QObject *parent)
    : QObject(parent)
    , m_directory(directory)
{
    connect(directory, &DriveDirectory::alarmChanged, this, &RecordSession::onAlarm);
    connect(hub, &DriveHub::trafficRecorded, this, &RecordSession::onTraffic);
    connect(directory, &DriveDirectory::connectionRemoved, this, [this](int id) {
        delete m_links.take(id);
        for (auto it = m_alarms.begin(); it != m_alarms.end();)
            it = it.key().first == id ? m_alarms.erase(it) : std::next(it);
    });
}

LinkHealthCounter *RecordSession::counter(int connectionId)
{
    LinkHealthCounter *&c = m_links[connectionId];
    if (!c) {
        const ConnectionSettings settings = m_directory->connectionSettings(connectionId);
        c = new LinkHealthCounter(nullptr, settings.isCan() ? 0 : settings.baud, this);
    }
    return c;
}

void RecordSession::onTraffic(int connectionId, const TrafficRecord &record)
{
    counter(connectionId)->count(record);
}

void RecordSession::countError(int connectionId, int address)
{
    counter(connectionId)->countError(address);
}

void RecordSession::onAlarm(int connectionId, int address, int code)
{
    QList<RecordAlarm> &list = m_alarms[{connectionId, address}];
    if (code == 0) {
        for (RecordAlarm &a : list)
            a.cleared = true;
        return;
    }
    if (!list.isEmpty() && list.last().code == code && !list.last().cleared)
        return; // the same alarm, seen again
    RecordAlarm a;
    a.when = QDateTime::currentDateTimeUtc();
    a.code = code;
    a.source = QStringLiteral("session");
    const Family family = m_directory->info(connectionId, address).identity.family;
    a.text = AlarmDictionary::bundled(family).text(code);
    list.append(a);
}

QList<RecordAlarm> RecordSession::alarms(int connectionId, int address) const
{
    return m_alarms.value({connectionId, address});
}

RecordLinkHealth RecordSession::linkHealth(int connectionId, int address) const
{
    const LinkHealthCounter *c = m_links.value(connectionId);
    if (!c)
        return {};
    return c->health(address, tr("since the connection was opened"));
}

} // namespace dd
