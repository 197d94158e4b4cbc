#include "core/drive/servomodbus/servomodbusscanner.h"

#include "core/link/modbuslink.h"
#include "core/protocol/modbus/crc16.h"
#include "core/protocol/servomodbus/servomodbus.h"

#include <QLoggingCategory>
#include <QMetaObject>
#include <QTimer>

#include <algorithm>

Q_LOGGING_CATEGORY(lcServoModbusScan, "drivedesk.drive.servo-modbus.scan")

namespace dd {

namespace {
constexpr int Window = 2; // probes handed to the link at a time
constexpr int ProbeRequestBytes = 8;
constexpr int ProbeReplyBytes = 7; // 0x03 reply with one register
constexpr qsizetype MaxStrayBytes = 256;
} // namespace

ServoModbusScanner::ServoModbusScanner(ModbusLink *link, const ScanOptions &options, QObject *parent)
    : Discovery(parent)
    , m_link(link)
    , m_options(options)
{
    qRegisterMetaType<dd::DiscoveredDrive>();
}

ServoModbusScanner::~ServoModbusScanner()
{
    for (auto &r : m_inFlight)
        delete r.data();
}

qint64 ServoModbusScanner::allowanceUs() const
{
    // Until a drive answered: the base allowance; then what the drives' turnaround needs.
    if (!m_turnaroundSeen || m_allowanceSet)
        return m_baseAllowanceUs;
    // Twice the turnaround, at least the turnaround + 1 ms (the host's wake-ups, a reply
    // delivered whole rather than byte by byte).
    return m_turnaroundUs + std::max<qint64>(m_turnaroundUs, 1000);
}

int ServoModbusScanner::allowanceMs() const
{
    return int((allowanceUs() + 999) / 1000);
}

qint64 ServoModbusScanner::firstByteTimeoutUs() const
{
    if (m_options.timeoutMs >= 0 || !m_link)
        return 0; // an explicit timeout is the whole timeout
    return m_link->wireTimeUs(ProbeRequestBytes) + allowanceUs();
}

int ServoModbusScanner::probeTimeoutMs() const
{
    if (m_options.timeoutMs >= 0)
        return m_options.timeoutMs;
    if (!m_link)
        return 0;
    const qint64 wire = m_link->wireTimeUs(ProbeRequestBytes) + m_link->wireTimeUs(ProbeReplyBytes);
    return int((wire + allowanceUs() + 999) / 1000);
}

int ServoModbusScanner::finalWaitMs() const
{
    const qint64 learnedUs = std::min<qint64>(2 * m_latestReplyUs, qint64(MaxFinalWaitMs) * 1000);
    return std::max({2 * probeTimeoutMs(), MinFinalWaitMs, int((learnedUs + 999) / 1000)});
}

void ServoModbusScanner::start()
{
    if (m_running)
        return;
    if (!m_link || !m_link->isOpen()) {
        QMetaObject::invokeMethod(
            this,
            [this] {
                emit finished({ErrorCode::LinkClosed, tr("The serial port is not open.")});
            },
            Qt::QueuedConnection);
        return;
    }
    m_running = true;
    connect(m_link, &ModbusLink::strayBytes, this, &ServoModbusScanner::onStrayBytes, Qt::UniqueConnection);
    m_originalBaud = m_link->settings().baud;
    m_bauds = m_options.bauds.isEmpty() ? QList<int>{m_originalBaud} : m_options.bauds;
    const int from = std::clamp(m_options.from, 1, 247);
    const int to = std::clamp(m_options.to, from, 247);
    m_total = int(m_bauds.size()) * (to - from + 1);
    m_done = 0;
    m_baudIndex = -1;
    m_found.clear();
    m_latestReplyUs = 0;
    m_clock.start();
    emit progress(0, m_total);
    QMetaObject::invokeMethod(this, &ServoModbusScanner::startBaud, Qt::QueuedConnection);
}

void ServoModbusScanner::startBaud()
{
    if (!m_running)
        return;
    ++m_baudIndex;
    if (m_baudIndex >= m_bauds.size()) {
        endScan(Error::none());
        return;
    }
    const int baud = m_bauds.at(m_baudIndex);
    if (!m_link || !m_link->setBaudRate(baud)) {
        endScan({ErrorCode::Busy,
                 tr("Cannot switch the port to %1 baud: the link is busy or closed. Stop other "
                    "operations on this port before scanning.")
                     .arg(baud)});
        return;
    }
    const int from = std::clamp(m_options.from, 1, 247);
    const int to = std::clamp(m_options.to, from, 247);
    m_unprobed.clear();
    m_repeat.clear();
    m_rescue.clear();
    m_timedOut.clear();
    m_rescued.clear();
    m_probeSentUs.clear();
    m_stray.clear();
    m_lastTimedOut = false;
    m_finishingBaud = false;
    for (int a = from; a <= to; ++a) {
        if (m_found.contains(a))
            ++m_done; // found at an earlier baud
        else
            m_unprobed.append(a);
    }
    emit progress(m_done, m_total);
    qCDebug(lcServoModbusScan) << "sweeping" << m_unprobed.size() << "addresses at" << baud << "timeout"
                               << probeTimeoutMs() << "ms";
    fillWindow();
}

void ServoModbusScanner::fillWindow()
{
    while (m_running && !m_finishingBaud && m_inFlight.size() < Window
           && (!m_rescue.isEmpty() || !m_repeat.isEmpty() || !m_unprobed.isEmpty())) {
        if (!m_rescue.isEmpty())
            sendProbe(m_rescue.takeFirst(), Probe::Rescue);
        else if (!m_repeat.isEmpty())
            sendProbe(m_repeat.takeFirst(), Probe::Repeat);
        else
            sendProbe(m_unprobed.takeFirst(), Probe::First);
    }
    if (m_running && !m_finishingBaud && m_inFlight.isEmpty() && m_unprobed.isEmpty() && m_repeat.isEmpty()
        && m_rescue.isEmpty())
        finishBaud();
}

void ServoModbusScanner::sendProbe(int address, Probe kind)
{
    ModbusRequest q;
    q.pdu.address = static_cast<quint8>(address);
    q.pdu.function = modbusrtu::ReadHoldingRegisters;
    q.pdu.start = servomodbus::parameterRegister(servomodbus::FirmwareParameter);
    q.pdu.count = 1;
    // A drive that answered late gets the link's normal timeout the second time.
    q.timeoutMs = kind == Probe::Rescue ? -1 : probeTimeoutMs();
    q.retries = 0;
    if (kind != Probe::Rescue) {
        // Late replies are caught (strayBytes): after a silent address only t3.5, and an
        // absent drive costs its request + the allowance, not the reply's wire time too.
        q.quietAfterTimeoutUs = m_link->interFrameGapUs();
        q.firstByteTimeoutUs = firstByteTimeoutUs();
    }
    q.note = kind == Probe::Rescue ? QStringLiteral("scan (again: its reply came late)") : QStringLiteral("scan");
    LinkReply *r = m_link->send(q);
    if (kind == Probe::First)
        m_probeSentUs.insert(address, m_clock.nsecsElapsed() / 1000);
    ++m_probesSent;
    m_inFlight.append(r);
    connect(r, &LinkReply::finished, this, [this, r, address, kind] { onProbeFinished(r, address, kind); });
}

void ServoModbusScanner::noteTurnaround(qint64 us)
{
    us = std::max<qint64>(0, us);
    // Late replies are caught (a slower drive is asked again): the quickest turnaround, so
    // that one answer slowed by a busy host does not slow every later probe.
    m_turnaroundUs = m_turnaroundSeen ? std::min(m_turnaroundUs, us) : us;
    m_turnaroundSeen = true;
}

void ServoModbusScanner::finishBaud()
{
    if (!m_lastTimedOut) {
        startBaud();
        return;
    }
    // The reply to the last probe may still be on its way: see finalWaitMs(). onStrayBytes
    // ends the wait early if it comes.
    m_finishingBaud = true;
    const int waitMs = finalWaitMs();
    QTimer::singleShot(waitMs, this, [this, baudIndex = m_baudIndex] {
        if (!m_running || !m_finishingBaud || baudIndex != m_baudIndex)
            return;
        m_finishingBaud = false;
        m_lastTimedOut = false;
        fillWindow();
    });
}

void ServoModbusScanner::onStrayBytes(const QByteArray &bytes)
{
    if (!m_running)
        return;
    m_stray += bytes;
    if (m_stray.size() > MaxStrayBytes)
        m_stray.remove(0, m_stray.size() - MaxStrayBytes);
    if (findLateReplies()) {
        m_finishingBaud = false;
        fillWindow();
    }
}

bool ServoModbusScanner::findLateReplies()
{
    bool added = false;
    for (qsizetype i = 0; i + ProbeReplyBytes <= m_stray.size(); ++i) {
        const QByteArray f = m_stray.mid(i, ProbeReplyBytes);
        if (quint8(f.at(1)) != modbusrtu::ReadHoldingRegisters || quint8(f.at(2)) != 2 || !hasValidCrc16(f))
            continue;
        const int address = quint8(f.at(0));
        if (!m_timedOut.contains(address) || m_rescued.contains(address) || m_found.contains(address))
            continue;
        // How late a drive on this line can answer (from its probe being queued: an upper
        // bound): the wait after the last probe learns from it.
        if (m_probeSentUs.contains(address))
            m_latestReplyUs = std::max(m_latestReplyUs, m_clock.nsecsElapsed() / 1000 - m_probeSentUs.value(address));
        qCDebug(lcServoModbusScan) << "late reply from" << address << "- asking again";
        m_rescued.insert(address);
        m_rescue.append(address);
        added = true;
    }
    return added;
}

void ServoModbusScanner::onProbeFinished(LinkReply *reply, int address, Probe kind)
{
    m_inFlight.removeAll(reply);
    reply->deleteLater();
    if (!m_running)
        return;
    const Error &e = reply->error();
    const int baud = m_bauds.value(m_baudIndex);
    auto found = [&](const QString &firmware, const QString &state) {
        m_found.insert(address);
        m_timedOut.remove(address);
        DiscoveredDrive d;
        d.family = Family::ServoModbus;
        d.address = address;
        d.baud = baud;
        d.firmware = firmware;
        d.state = state;
        d.link = m_link ? m_link->name() : QString();
        report(d);
    };
    m_lastTimedOut = false;
    switch (e.code) {
    case ErrorCode::None: {
        const qint64 wire = m_link->wireTimeUs(ProbeRequestBytes) + m_link->wireTimeUs(ProbeReplyBytes);
        noteTurnaround(reply->roundTripUs() - wire);
        found(QString::number(reply->registers().value(0)), QString());
        break;
    }
    case ErrorCode::DriveException:
        // A drive is there. Exception 0x04 is also its answer to a probe that reached it
        // damaged (docs/protocols/servo-modbus.md, "Exceptions"): once more, for the firmware.
        if (kind == Probe::First && e.driveCode == modbusrtu::ServerDeviceFailure) {
            m_repeat.append(address);
            fillWindow();
            return;
        }
        found(QString(), tr("exception %1").arg(e.driveCode));
        break;
    case ErrorCode::ChecksumError:
    case ErrorCode::Malformed:
        if (kind == Probe::First) {
            m_repeat.append(address); // something answered garbled: once more
            fillWindow();
            return;
        }
        break;
    case ErrorCode::LinkClosed: endScan(e); return;
    case ErrorCode::Cancelled: return;
    case ErrorCode::Timeout:
        m_timedOut.insert(address);
        m_lastTimedOut = true;
        // The link reports the bytes of a reply that came too late for this probe before
        // it reports the timeout: they may be waiting already.
        findLateReplies();
        break;
    default: break;
    }
    if (kind != Probe::Rescue) { // a rescued address was counted when its first probe ended
        ++m_done;
        emit progress(m_done, m_total);
    }
    fillWindow();
}

void ServoModbusScanner::cancel()
{
    if (!m_running)
        return;
    endScan({ErrorCode::Cancelled, tr("The scan was cancelled.")});
}

void ServoModbusScanner::endScan(const Error &error)
{
    if (!m_running)
        return;
    m_running = false;
    m_finishingBaud = false;
    if (m_link)
        disconnect(m_link, &ModbusLink::strayBytes, this, &ServoModbusScanner::onStrayBytes);
    // Only a scan that stops with probes still under way aborts the link's queue; at the
    // normal end the queue holds other users' requests (a parameter read, a status poll)
    // that must go on.
    const bool probesUnderWay = !m_inFlight.isEmpty();
    for (auto &r : m_inFlight)
        delete r.data();
    m_inFlight.clear();
    if (m_link && m_link->isOpen()) {
        if (probesUnderWay && !m_link->isIdle())
            m_link->cancelAll({ErrorCode::Cancelled, tr("The scan was cancelled.")});
        if (m_link->settings().baud != m_originalBaud)
            m_link->setBaudRate(m_originalBaud);
    }
    QMetaObject::invokeMethod(
        this, [this, error] { emit finished(error); }, Qt::QueuedConnection);
}

} // namespace dd
