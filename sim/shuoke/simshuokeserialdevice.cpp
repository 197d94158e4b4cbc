#include "sim/shuoke/simshuokeserialdevice.h"

#include <QCoreApplication>

#include "core/link/wiretime.h"
#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokeasciistreamparser.h"
#include "core/protocol/shuoke/shuokeplc.h"
#include "core/protocol/shuoke/shuokertu.h"

#include <algorithm>

namespace dd {

using namespace shuoke;

namespace {
constexpr int kMaxShuokeData = 16;
constexpr qint64 kMinSilenceUs = 10000; // a frame left incomplete this long is stale

bool isHexDigit(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
}
} // namespace

SimShuokeSerialDevice::SimShuokeSerialDevice(const SimShuokeDrive::Config &config, Framing framing, AsciiCheck check)
    : m_drive(config)
    , m_framing(framing)
    , m_check(check)
{
}

qint64 SimShuokeSerialDevice::clockUs() const
{
    return m_clock ? std::max(m_nowUs, m_clock()) : m_nowUs;
}

SimShuokeDrive &SimShuokeSerialDevice::drive()
{
    if (m_clock)
        advanceTo(m_clock());
    return m_drive;
}

int SimShuokeSerialDevice::baud() const
{
    return m_drive.serialBaud(clockUs());
}

QString SimShuokeSerialDevice::describe() const
{
    static const char *const names[] = {"RTU", "ASCII", "PLC"};
    return QStringLiteral("shuoke %1 addr %2 %3 @ %4")
        .arg(modelName(m_drive.model()))
        .arg(m_drive.address())
        .arg(QLatin1String(names[static_cast<int>(m_framing)]))
        .arg(baud());
}

void SimShuokeSerialDevice::advanceTo(qint64 nowUs)
{
    if (nowUs > m_nowUs)
        m_nowUs = nowUs;
    m_drive.advanceTo(nowUs);
}

void SimShuokeSerialDevice::powerCycle()
{
    m_rx.clear();
    m_drive.powerCycle(clockUs());
}

void SimShuokeSerialDevice::drop(qsizetype n)
{
    n = std::min(n, m_rx.size());
    m_discarded += static_cast<quint64>(n);
    m_rx.remove(0, n);
}

QList<QByteArray> SimShuokeSerialDevice::onBusBytes(const QByteArray &bytes, qint64 nowUs)
{
    advanceTo(nowUs);
    const qint64 silence = std::max<qint64>(kMinSilenceUs, static_cast<qint64>(WireTime::modbusSilenceUs(baud())));
    if (!m_rx.isEmpty() && nowUs - m_lastRxUs > silence)
        drop(m_rx.size());
    m_lastRxUs = nowUs;
    m_rx += bytes;
    if (m_rx.size() > 1024)
        drop(m_rx.size() - 1024);
    return m_framing == Framing::Ascii ? frameAscii(nowUs) : frameBinary(nowUs);
}

QByteArray SimShuokeSerialDevice::encodeRtuReply(const Frame &reply) const
{
    RtuOptions o;
    o.padToFixedLength = m_drive.fixedLengthReplies();
    return encodeRtu(reply, o).value.value_or(QByteArray());
}

QByteArray SimShuokeSerialDevice::encodeAsciiReply(const Frame &reply) const
{
    AsciiOptions o;
    o.check = m_check;
    return encodeAscii(reply, o).value.value_or(QByteArray());
}

bool SimShuokeSerialDevice::takeModbus(qint64 nowUs, QList<QByteArray> *out, bool *wait)
{
    const quint8 function = static_cast<quint8>(m_rx.at(1));
    qsizetype need = 8;
    if (function == PlcWriteRegisters) {
        if (m_rx.size() < 7) {
            *wait = true;
            return true;
        }
        need = 9 + static_cast<quint8>(m_rx.at(6));
    }
    if (m_rx.size() < need) {
        *wait = true;
        return true;
    }
    const QByteArray adu = m_rx.left(need);
    if (!hasValidCrc16(adu))
        return false; // not a Modbus frame here: try Shuoke RTU
    m_rx.remove(0, need);
    const quint8 address = static_cast<quint8>(adu.at(0));
    if (!m_drive.isAddressed(address))
        return true;
    PlcOptions options;
    options.base = m_drive.plcBase();
    const Decoded<Frame> request = decodePlcRequest(adu, options);
    if (!request.ok()) {
        if (!m_drive.isBroadcast(address)) {
            QByteArray exception;
            exception.append(static_cast<char>(m_drive.address()));
            exception.append(static_cast<char>(function | 0x80));
            exception.append('\x02'); // illegal data address: the register maps to no command
            out->append(withCrc16(exception));
        }
        return true;
    }
    const std::optional<Frame> reply = m_drive.handle(*request.value, SimShuokeDrive::Medium::Plc, nowUs);
    if (reply) {
        const Decoded<QByteArray> bytes = encodePlcReply(*reply, *request.value, options);
        if (bytes.ok())
            out->append(*bytes.value);
    }
    return true;
}

QList<QByteArray> SimShuokeSerialDevice::frameBinary(qint64 nowUs)
{
    QList<QByteArray> out;
    while (m_rx.size() >= 2) {
        const quint8 address = static_cast<quint8>(m_rx.at(0));
        const quint8 command = static_cast<quint8>(m_rx.at(1));
        if (m_framing == Framing::Plc && (command == PlcReadRegisters || command == PlcWriteRegisters)) {
            bool wait = false;
            if (takeModbus(nowUs, &out, &wait)) {
                if (wait)
                    break;
                continue;
            }
        }
        if (m_rx.size() < 3)
            break;
        const int len = static_cast<quint8>(m_rx.at(2));
        if (len > kMaxShuokeData || (command & 0x80)) {
            drop(1);
            continue;
        }
        const qsizetype size = kRtuOverhead + len;
        if (m_rx.size() < size)
            break;
        QByteArray bytes = m_rx.left(size);
        bool crcOk = hasValidCrc16(bytes) || command == CmdHandshake || m_drive.skipsCrcCheck();
        // 驱动器接受命令同时支持这两种格式 (0x49): a request may also come in the fixed 8 + CRC
        // layout, its data zero-padded to 5 bytes (when it arrives whole).
        if (!crcOk && len <= kFixedDataSize && m_rx.size() >= kFixedFrameSize
            && hasValidCrc16(m_rx.left(kFixedFrameSize))) {
            bytes = m_rx.left(kFixedFrameSize);
            crcOk = true;
        }
        if (!crcOk) {
            if (address == m_drive.address()) {
                ++m_checksumErrors;
                m_rx.remove(0, size);
                out.append(encodeRtuReply(m_drive.failure(command, FailureChecksum)));
            } else {
                drop(1);
            }
            continue;
        }
        m_rx.remove(0, bytes.size());
        const Frame request = Frame::make(address, command, bytes.mid(3, len));
        if (const std::optional<Frame> reply = m_drive.handle(request, SimShuokeDrive::Medium::Serial, nowUs))
            out.append(encodeRtuReply(*reply));
    }
    return out;
}

QList<QByteArray> SimShuokeSerialDevice::frameAscii(qint64 nowUs)
{
    QList<QByteArray> out;
    for (;;) {
        const qsizetype start = m_rx.indexOf(kAsciiStart);
        if (start < 0) {
            drop(m_rx.size());
            break;
        }
        drop(start);
        const qsizetype lf = m_rx.indexOf('\n');
        const qsizetype next = m_rx.indexOf(kAsciiStart, 1);
        if (next > 0 && (lf < 0 || next < lf)) {
            drop(next);
            continue;
        }
        if (lf < 0) {
            if (m_rx.size() > AsciiStreamParser::kMaxFrameChars)
                drop(1);
            else
                break;
            continue;
        }
        const QByteArray line = m_rx.left(lf + 1);
        m_rx.remove(0, lf + 1);
        QByteArray hex = line.mid(1, line.size() - 2);
        if (hex.endsWith('\r'))
            hex.chop(1);
        if (hex.size() < 8 || hex.size() % 2 || !std::all_of(hex.cbegin(), hex.cend(), isHexDigit))
            continue;
        const QByteArray bytes = QByteArray::fromHex(hex);
        const quint8 address = static_cast<quint8>(bytes.at(0));
        const quint8 command = static_cast<quint8>(bytes.at(1));
        if (!m_drive.isAddressed(address))
            continue;
        const bool checkOk = asciiCheckByte(bytes.left(bytes.size() - 1), m_check) == static_cast<quint8>(bytes.back());
        if (!checkOk && !m_drive.skipsCrcCheck() && command != CmdHandshake) {
            ++m_checksumErrors;
            if (address == m_drive.address())
                out.append(encodeAsciiReply(m_drive.failure(command, FailureChecksum)));
            continue;
        }
        const int len = static_cast<quint8>(bytes.at(2));
        const int dataBytes = static_cast<int>(bytes.size()) - 4;
        if ((len != dataBytes && len != dataBytes + 1) || (command & 0x80)) {
            if (address == m_drive.address())
                out.append(encodeAsciiReply(m_drive.failure(command, FailureTimeoutOrLength)));
            continue;
        }
        const Frame request = Frame::make(address, command, bytes.mid(3, dataBytes));
        if (const std::optional<Frame> reply = m_drive.handle(request, SimShuokeDrive::Medium::Serial, nowUs))
            out.append(encodeAsciiReply(*reply));
    }
    return out;
}

std::unique_ptr<SimSerialDevice> SimShuokeSerialDevice::create(const SimDeviceSpec &spec, Error *error)
{
    Framing framing = Framing::Rtu;
    const QString f = spec.framing.toLower();
    if (f == QLatin1String("ascii")) {
        framing = Framing::Ascii;
    } else if (f == QLatin1String("plc")) {
        framing = Framing::Plc;
    } else if (!f.isEmpty() && f != QLatin1String("rtu")) {
        *error = {ErrorCode::InvalidArgument,
                  f == QLatin1String("can")
                      ? QCoreApplication::translate(
                          "dd::SimBench", "The shuoke CAN framing needs a CAN bus: give --can PLUGIN:INTERFACE.")
                      : QCoreApplication::translate("dd::SimBench",
                                                    "Unknown shuoke framing \"%1\": use rtu, ascii, can or plc.")
                            .arg(f)};
        return nullptr;
    }
    const int code = shuoke::baudCodeForRate(spec.baud);
    if (!shuoke::isUsableBaudCode(code)) {
        *error = {ErrorCode::InvalidArgument,
                  QCoreApplication::translate(
                      "dd::SimBench",
                      "A shuoke drive talks at 300, 600, 1200, 2400, 4800, 9600, 19200 or 38400 baud, not %1.")
                      .arg(spec.baud)};
        return nullptr;
    }
    if (!shuoke::isUnicastAddress(spec.address)) {
        *error = {ErrorCode::InvalidArgument,
                  QCoreApplication::translate("dd::SimBench", "A shuoke address is 1..247, not %1.").arg(spec.address)};
        return nullptr;
    }
    SimShuokeDrive::Config c;
    c.address = static_cast<quint8>(spec.address);
    c.baudCode = code;
    auto device = std::make_unique<SimShuokeSerialDevice>(c, framing);
    device->setClock(spec.clock);
    return device;
}

} // namespace dd
