#include "core/drive/servocan/servocanbackend.h"

#include "core/drive/servocan/servocandiscovery.h"
#include "core/drive/servocan/servocandrive.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/link/canlink.h"
#include "core/protocol/servocan/servocan.h"

#include <QSet>
#include <algorithm>

namespace dd {

namespace sc = servocan;

ServoCanBackend::ServoCanBackend(QObject *parent)
    : FamilyBackend(parent)
    , m_link(new CanLink(this))
    , m_tracker(new ServoCanStationTracker(m_link, this))
{
    connect(m_link, &CanLink::closed, this, &ServoCanBackend::onLinkClosed);
}

ServoCanBackend::~ServoCanBackend() = default;

Family ServoCanBackend::family() const
{
    return Family::ServoCan;
}

bool ServoCanBackend::open(const ConnectionSettings &settings, TrafficTap *tap, Error *error)
{
    auto fail = [error](const Error &e) {
        if (error)
            *error = e;
        return false;
    };
    CanSettings can;
    if (!CanSettings::parse(settings.can, &can))
        return fail({ErrorCode::InvalidArgument,
                     tr("\"%1\" is not a CAN interface: write plugin:interface, e.g. "
                        "socketcan:can0 or virtualcan:can0.")
                         .arg(settings.can)});
    can.bitrate = settings.bitrate > 0 ? settings.bitrate : sc::kBitrate;
    if (settings.timeoutMs >= 0)
        can.responseTimeoutMs = settings.timeoutMs;
    if (settings.retries >= 0)
        can.retries = settings.retries;
    const QVariantMap &o = settings.options;
    const QString stopMode = o.value(QStringLiteral("servo-can.emergencyStop"), QStringLiteral("disable")).toString();
    if (stopMode != QLatin1String("disable") && stopMode != QLatin1String("hold"))
        return fail({ErrorCode::InvalidArgument,
                     tr("servo-can.emergencyStop must be \"disable\" or \"hold\", not \"%1\".").arg(stopMode)});
    if (o.contains(QStringLiteral("servo-can.maxInFlight"))) {
        const int n = o.value(QStringLiteral("servo-can.maxInFlight")).toInt();
        if (n < 1)
            return fail({ErrorCode::InvalidArgument, tr("servo-can.maxInFlight must be at least 1.")});
        can.maxInFlight = n;
    }
    if (m_open)
        close();
    m_emergencyHolds = stopMode == QLatin1String("hold");
    m_confirmReads = o.value(QStringLiteral("servo-can.confirmReads"), false).toBool();
    m_bitrate = can.bitrate;
    m_link->setTap(tap);
    Error e;
    if (!m_link->open(can, &e))
        return fail(e);
    m_open = true;
    for (const QPointer<ServoCanDrive> &d : std::as_const(m_drives))
        if (d)
            configureDrive(d);
    return true;
}

void ServoCanBackend::close()
{
    if (!m_open)
        return;
    m_open = false;
    m_link->close(); // the tracker forgets the stations and stops the keep-alive
}

void ServoCanBackend::onLinkClosed(const Error &why)
{
    const bool wasOpen = m_open;
    m_open = false;
    if (wasOpen && why.isError())
        emit linkLost(why);
}

Drive *ServoCanBackend::drive(int address)
{
    return servoDrive(address);
}

ServoCanDrive *ServoCanBackend::servoDrive(int station)
{
    if (!sc::isValidStation(station))
        return nullptr;
    QPointer<ServoCanDrive> &d = m_drives[station];
    if (!d) {
        d = new ServoCanDrive(m_link, m_tracker, station, this);
        configureDrive(d);
    }
    return d;
}

void ServoCanBackend::configureDrive(ServoCanDrive *drive) const
{
    drive->setEmergencyStopHolds(m_emergencyHolds);
    drive->setConfirmReads(m_confirmReads);
}

Discovery *ServoCanBackend::createDiscovery(const ScanOptions &options)
{
    return new ServoCanDiscovery(m_tracker, options, m_bitrate, this);
}

void ServoCanBackend::stopAll()
{
    QSet<int> stations;
    for (int s : m_tracker->seenStations())
        stations.insert(s);
    for (auto it = m_drives.cbegin(); it != m_drives.cend(); ++it)
        if (it.value())
            stations.insert(it.key());
    QList<int> sorted = stations.values();
    std::sort(sorted.begin(), sorted.end());
    for (int s : std::as_const(sorted)) {
        if (ServoCanDrive *d = m_drives.value(s)) {
            DriveReply *r = d->stop(true);
            connect(r, &DriveReply::finished, r, &QObject::deleteLater);
        } else {
            const auto station = static_cast<quint8>(s);
            m_link->send(m_emergencyHolds ? sc::stop(station) : sc::stopAndDisable(station),
                         QStringLiteral("stop all"));
            m_tracker->releaseMotion(s);
        }
    }
}

QString ServoCanBackend::linkDescription() const
{
    return tr("%1, %2 kbit/s").arg(m_link->name()).arg(m_bitrate / 1000);
}

} // namespace dd
