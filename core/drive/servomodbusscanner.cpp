#include "drive/servomodbusscanner.h"

#include "link/modbuslink.h"
#include "protocol/servomodbus.h"

#include <QLoggingCategory>
#include <QMetaObject>

Q_LOGGING_CATEGORY(lcServoModbusScan, "drivedesk.drive.servo-modbus.scan")

namespace dd {

namespace {
constexpr int Window = 2;        // probes handed to the link at a time
constexpr int ProbeRequestBytes = 8;
constexpr int ProbeReplyBytes = 7; // 0x03 reply with one register
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

int ServoModbusScanner::allowanceMs() const
{
    const qint64 us = std::max(m_baseAllowanceUs, 2 * m_maxTurnaroundUs + 1000);
    return int((us + 999) / 1000);
}

int ServoModbusScanner::probeTimeoutMs() const
{
    if (m_options.timeoutMs >= 0)
        return m_options.timeoutMs;
    if (!m_link)
        return 0;
    const qint64 wire = m_link->wireTimeUs(ProbeRequestBytes) + m_link->wireTimeUs(ProbeReplyBytes);
    const qint64 allowance = std::max(m_baseAllowanceUs, 2 * m_maxTurnaroundUs + 1000);
    return int((wire + allowance + 999) / 1000);
}

void ServoModbusScanner::start()
{
    if (m_running)
        return;
    if (!m_link || !m_link->isOpen()) {
        QMetaObject::invokeMethod(this, [this] {
            emit finished({ErrorCode::LinkClosed, tr("The serial port is not open.")});
        }, Qt::QueuedConnection);
        return;
    }
    m_running = true;
    m_originalBaud = m_link->settings().baud;
    m_bauds = m_options.bauds.isEmpty() ? QList<int>{m_originalBaud} : m_options.bauds;
    const int from = std::clamp(m_options.from, 1, 247);
    const int to = std::clamp(m_options.to, from, 247);
    m_total = int(m_bauds.size()) * (to - from + 1);
    m_done = 0;
    m_baudIndex = -1;
    m_found.clear();
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
    m_todo.clear();
    m_repeat.clear();
    for (int a = from; a <= to; ++a) {
        if (m_found.contains(a))
            ++m_done;   // found at an earlier baud
        else
            m_todo.append(a);
    }
    emit progress(m_done, m_total);
    qCDebug(lcServoModbusScan) << "sweeping" << m_todo.size() << "addresses at" << baud
                               << "timeout" << probeTimeoutMs() << "ms";
    fillWindow();
}

void ServoModbusScanner::fillWindow()
{
    while (m_running && m_inFlight.size() < Window && (!m_repeat.isEmpty() || !m_todo.isEmpty())) {
        const bool repeated = !m_repeat.isEmpty();
        const int address = repeated ? m_repeat.takeFirst() : m_todo.takeFirst();
        ModbusRequest q;
        q.pdu.address = static_cast<quint8>(address);
        q.pdu.function = modbusrtu::ReadHoldingRegisters;
        q.pdu.start = servomodbus::parameterRegister(servomodbus::FirmwareParameter);
        q.pdu.count = 1;
        q.timeoutMs = probeTimeoutMs();
        q.retries = 0;
        q.note = QStringLiteral("scan");
        LinkReply *r = m_link->send(q);
        ++m_probesSent;
        m_inFlight.append(r);
        connect(r, &LinkReply::finished, this, [this, r, address, repeated] {
            onProbeFinished(r, address, repeated);
        });
    }
    if (m_running && m_inFlight.isEmpty() && m_todo.isEmpty() && m_repeat.isEmpty())
        startBaud();
}

void ServoModbusScanner::onProbeFinished(LinkReply *reply, int address, bool repeated)
{
    m_inFlight.removeAll(reply);
    reply->deleteLater();
    if (!m_running)
        return;
    const Error &e = reply->error();
    const int baud = m_bauds.value(m_baudIndex);
    auto found = [&](const QString &firmware, const QString &state) {
        m_found.insert(address);
        DiscoveredDrive d;
        d.family = Family::ServoModbus;
        d.address = address;
        d.baud = baud;
        d.firmware = firmware;
        d.state = state;
        d.link = m_link ? m_link->name() : QString();
        report(d);
    };
    switch (e.code) {
    case ErrorCode::None: {
        const qint64 wire = m_link->wireTimeUs(ProbeRequestBytes) + m_link->wireTimeUs(ProbeReplyBytes);
        m_maxTurnaroundUs = std::max(m_maxTurnaroundUs, reply->roundTripUs() - wire);
        found(QString::number(reply->registers().value(0)), QString());
        break;
    }
    case ErrorCode::DriveException:
        found(QString(), QStringLiteral("exception %1").arg(e.driveCode));
        break;
    case ErrorCode::ChecksumError:
    case ErrorCode::Malformed:
        if (!repeated) {
            m_repeat.append(address);   // something answered garbled: once more
            fillWindow();
            return;
        }
        break;
    case ErrorCode::LinkClosed:
        endScan(e);
        return;
    case ErrorCode::Cancelled:
        return;
    default:
        break;
    }
    ++m_done;
    emit progress(m_done, m_total);
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
    QMetaObject::invokeMethod(this, [this, error] { emit finished(error); }, Qt::QueuedConnection);
}

} // namespace dd
