#include "core/drive/servomodbus/servomodbusdrive.h"

#include "core/drive/servomodbus/servomodbuschannels.h"
#include "core/drive/writeverification.h"
#include "core/link/wiretime.h"

#include "core/link/modbusbatch.h"
#include "core/link/modbuslink.h"
#include "core/params/parameterdictionary.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QHash>
#include <QSet>
#include <QTimer>

namespace dd {

namespace {

constexpr quint16 AlarmRegister = 0x13;
constexpr quint16 OutputsRegister = 0x10; // DP-oUt: bit 0 servo ready, bit 1 alarm

qint64 nowUsSinceEpoch()
{
    return QDateTime::currentMSecsSinceEpoch() * 1000;
}

ModbusRequest request(int address, quint8 function, quint16 start, quint16 count, const QString &note)
{
    ModbusRequest q;
    q.pdu.address = static_cast<quint8>(address);
    q.pdu.function = function;
    q.pdu.start = start;
    q.pdu.count = count;
    q.note = note;
    return q;
}

QList<ModbusRequest> readRequests(int address, const QList<servomodbus::RegisterRange> &ranges, const QString &note)
{
    QList<ModbusRequest> out;
    for (const auto &r : ranges)
        out.append(request(address, modbusrtu::ReadHoldingRegisters, r.start, r.count, note));
    return out;
}

// Register -> value from the results of readRequests().
QHash<quint16, quint16> collect(const QList<ModbusRequest> &requests, const QList<ModbusBatch::Result> &results)
{
    QHash<quint16, quint16> regs;
    for (int i = 0; i < requests.size() && i < results.size(); ++i) {
        const auto &values = results.at(i).registers;
        for (int k = 0; k < values.size(); ++k)
            regs.insert(static_cast<quint16>(requests.at(i).pdu.start + k), values.at(k));
    }
    return regs;
}

// The 0x10 requests for the runs of consecutive parameters servomodbus::planWrites made.
QList<ModbusRequest> writeRequests(int address, const QList<servomodbus::RegisterWrite> &plan)
{
    QList<ModbusRequest> out;
    for (const auto &run : plan) {
        ModbusRequest q = request(address, modbusrtu::WriteMultipleRegisters, run.start,
                                  static_cast<quint16>(run.values.size()), QStringLiteral("write parameters"));
        q.pdu.values = run.values;
        out.append(q);
    }
    return out;
}

// Parameter -> the error of the failed request (read or write) that carried it.
QHash<int, Error> errorsByParameter(const QList<ModbusRequest> &requests, const QList<ModbusBatch::Result> &results)
{
    QHash<int, Error> errors;
    for (int i = 0; i < requests.size() && i < results.size(); ++i) {
        if (!results.at(i).error)
            continue;
        for (int k = 0; k < requests.at(i).pdu.count; ++k)
            errors.insert(servomodbus::parameterIndex(quint16(requests.at(i).pdu.start + k)), results.at(i).error);
    }
    return errors;
}

// Everything the drive did not refuse is read back: a write whose answer was lost or
// damaged may have been carried out, and only the read-back can tell.
QList<int> parametersToReadBack(const QList<ParameterWrite> &writes, const QHash<int, Error> &writeErrors)
{
    QList<int> out;
    for (const ParameterWrite &w : writes)
        if (writeErrors.value(w.index).code != ErrorCode::DriveException)
            out.append(w.index);
    return out;
}

} // namespace

ServoModbusOptions ServoModbusOptions::fromMap(const QVariantMap &options, Error *error)
{
    ServoModbusOptions o;
    auto bad = [error](const QString &key, const QString &value, const QString &allowed) {
        if (error && !error->isError())
            *error = {ErrorCode::InvalidArgument,
                      QCoreApplication::translate("dd::ServoModbusDrive", "Invalid value \"%1\" for %2 (allowed: %3).")
                          .arg(value, key, allowed)};
    };
    const QString rule = options.value(QStringLiteral("servo-modbus.positionRule")).toString().trimmed().toLower();
    if (!rule.isEmpty()) {
        if (rule == QLatin1String("binary"))
            o.positionRule = servomodbus::PositionPairRule::BinaryWords;
        else if (rule == QLatin1String("decimal10000"))
            o.positionRule = servomodbus::PositionPairRule::Decimal10000;
        else if (rule == QLatin1String("decimal100000"))
            o.positionRule = servomodbus::PositionPairRule::Decimal100000;
        else if (auto r = servomodbus::positionPairRuleFromId(rule))
            o.positionRule = *r;
        else
            bad(QStringLiteral("servo-modbus.positionRule"), rule,
                QStringLiteral("binary, decimal10000, decimal100000"));
    }
    const QString ee = options.value(QStringLiteral("servo-modbus.eeFormat")).toString().trimmed().toLower();
    if (!ee.isEmpty()) {
        if (auto c = servomodbus::eeFormatChoiceFromId(ee))
            o.eeFormat = *c;
        else
            bad(QStringLiteral("servo-modbus.eeFormat"), ee, QStringLiteral("auto, legacy, new"));
    }
    auto intOption = [&](const char *key, int *target, int min, int max) {
        const QVariant v = options.value(QLatin1String(key));
        if (!v.isValid())
            return;
        bool ok = false;
        const int x = v.toString().toInt(&ok);
        if (!ok || x < min || x > max)
            bad(QLatin1String(key), v.toString(), QStringLiteral("%1..%2").arg(min).arg(max));
        else
            *target = x;
    };
    intOption("servo-modbus.eeTimeoutMs", &o.eeTimeoutMs, 100, 600000);
    intOption("servo-modbus.eePollMs", &o.eePollMs, 0, 10000);
    return o;
}

ServoModbusDrive::ServoModbusDrive(ModbusLink *link, int address, const ServoModbusOptions &options, QObject *parent)
    : Drive(parent)
    , m_link(link)
    , m_options(options)
{
    DriveIdentity id;
    id.family = Family::ServoModbus;
    id.address = address;
    if (link)
        id.link = QStringLiteral("%1 @ %2").arg(link->name()).arg(link->settings().baud);
    setIdentity(id);
}

Capabilities ServoModbusDrive::capabilities() const
{
    return Capability::ReadParameters | Capability::WriteParameters | Capability::Monitor | Capability::ReadAlarm
        | Capability::EeOperations;
}

QString ServoModbusDrive::unsupportedReason(Capability c) const
{
    switch (c) {
    case Capability::ClearAlarm:
        return tr("The servo-modbus protocol has no command to clear an alarm. Remove the "
                  "cause, then reset the alarm at the drive (its panel, an alarm-reset input "
                  "or a power cycle) and read the alarm again.");
    case Capability::Jog:
    case Capability::MoveRelative:
    case Capability::MoveAbsolute:
    case Capability::Home:
    case Capability::Enable:
    case Capability::Stop:
    case Capability::EmergencyStop:
    case Capability::SetPosition:
        return tr("The servo-modbus protocol reads and writes parameters and monitor values "
                  "only; it has no motion, enable or stop commands. The axis runs from the "
                  "drive's own control inputs (pulses, analog command, I/O).");
    default: return Drive::unsupportedReason(c);
    }
}

QList<ChannelInfo> ServoModbusDrive::channels() const
{
    return ServoModbusChannels::channels();
}

Error ServoModbusDrive::checkLink() const
{
    if (!m_link || !m_link->isOpen())
        return {ErrorCode::LinkClosed, tr("The serial port is not open.")};
    if (address() < 1 || address() > 247)
        return {ErrorCode::InvalidArgument,
                tr("Address %1 cannot answer: servo drives use 1..247 (0 is broadcast).").arg(address())};
    return {};
}

DriveReply *ServoModbusDrive::refreshIdentity()
{
    if (Error e = checkLink())
        return finishedReply(e);
    DriveReply *reply = newReply();
    const auto ranges = servomodbus::planReads({servomodbus::FirmwareParameter, servomodbus::AddressParameter});
    const QList<ModbusRequest> requests = readRequests(address(), ranges, QStringLiteral("identity"));
    ModbusBatch::run(m_link, requests, reply, ModbusBatch::Mode::StopOnError,
                     [this, reply, requests](const Error &error, const QList<ModbusBatch::Result> &results) {
                         if (error) {
                             reply->finish(error);
                             return;
                         }
                         const auto regs = collect(requests, results);
                         const quint16 pa2 = regs.value(servomodbus::parameterRegister(servomodbus::FirmwareParameter));
                         const quint16 pa51 = regs.value(servomodbus::parameterRegister(servomodbus::AddressParameter));
                         m_firmware = pa2;
                         DriveIdentity &id = mutableIdentity();
                         id.firmware = QString::number(pa2);
                         id.link = QStringLiteral("%1 @ %2").arg(m_link->name()).arg(m_link->settings().baud);
                         const auto format = servomodbus::eeFormatForFirmware(pa2);
                         reply->setInfo(QStringLiteral("firmware"), int(pa2));
                         reply->setInfo(QStringLiteral("pa51"), int(pa51));
                         reply->setInfo(QStringLiteral("eeFormat"),
                                        format == servomodbus::EeFormat::Legacy ? QStringLiteral("legacy")
                                                                                : QStringLiteral("new"));
                         reply->finish();
                     });
    return reply;
}

DriveReply *ServoModbusDrive::readStatus()
{
    if (Error e = checkLink())
        return finishedReply(e);
    DriveReply *reply = newReply();
    // DP-SPd .. DP-Err is exactly 20 registers: one request.
    const QList<quint16> regsWanted = {0x00, 0x01, 0x02, OutputsRegister, AlarmRegister};
    const QList<ModbusRequest> requests = readRequests(address(), servomodbus::planRegisterReads(regsWanted),
                                                       QStringLiteral("status"));
    ModbusBatch::run(m_link, requests, reply, ModbusBatch::Mode::StopOnError,
                     [this, reply, requests](const Error &error, const QList<ModbusBatch::Result> &results) {
                         DriveStatus s = status();
                         if (error) {
                             if (error.code == ErrorCode::Timeout) {
                                 s.online = false;
                                 updateStatus(s);
                             }
                             reply->setStatus(s);
                             reply->finish(error);
                             return;
                         }
                         const auto regs = collect(requests, results);
                         s.online = true;
                         s.running = qint16(regs.value(0x00)) != 0;
                         // DP-oUt bit 0 "servo ready": the power stage is on (the drive
                         // follows its SON input; the protocol cannot switch it).
                         s.enabled = (regs.value(OutputsRegister) & 0x01) != 0;
                         s.positionValid = true;
                         s.position = servomodbus::combinePositionPair(regs.value(0x01), regs.value(0x02),
                                                                       m_options.positionRule);
                         s.alarmCode = regs.value(AlarmRegister);
                         updateStatus(s);
                         reply->setStatus(status());
                         reply->finish();
                     });
    return reply;
}

DriveReply *ServoModbusDrive::readAlarm()
{
    if (Error e = checkLink())
        return finishedReply(e);
    DriveReply *reply = newReply();
    LinkReply *r = m_link->readHoldingRegisters(address(), AlarmRegister, 1);
    connect(r, &LinkReply::finished, reply, [this, reply, r] {
        r->deleteLater();
        if (r->error()) {
            reply->finish(r->error());
            return;
        }
        DriveStatus s = status();
        s.online = true;
        s.alarmCode = r->registers().value(0);
        updateStatus(s);
        reply->setStatus(status());
        reply->setInfo(QStringLiteral("alarm"), s.alarmCode);
        reply->finish();
    });
    return reply;
}

DriveReply *ServoModbusDrive::readParameters(const QList<int> &indices)
{
    if (Error e = checkLink())
        return finishedReply(e);
    for (int n : indices) {
        if (!servomodbus::isParameterIndex(n))
            return finishedReply(
                {ErrorCode::InvalidArgument, tr("PA%1 does not exist: this drive has PA0..PA59.").arg(n)});
    }
    DriveReply *reply = newReply();
    const QList<ModbusRequest> requests = readRequests(address(), servomodbus::planReads(indices),
                                                       QStringLiteral("read parameters"));
    ModbusBatch::run(
        m_link, requests, reply, ModbusBatch::Mode::StopOnError,
        [this, reply, requests, indices](const Error &error, const QList<ModbusBatch::Result> &results) {
            if (error) {
                // Name the parameters the failed request was for.
                Error e = error;
                for (int i = 0; i < results.size() && i < requests.size(); ++i) {
                    if (!results.at(i).error)
                        continue;
                    const int first = servomodbus::parameterIndex(requests.at(i).pdu.start);
                    e.message =
                        tr("PA%1..PA%2: %3").arg(first).arg(first + requests.at(i).pdu.count - 1).arg(error.message);
                    break;
                }
                reply->finish(e);
                return;
            }
            const auto regs = collect(requests, results);
            for (int n : indices)
                reply->setParameter(n, parameterValue(n, regs.value(servomodbus::parameterRegister(n))));
            reply->finish();
        },
        [reply](int done, int total) { reply->reportProgress(done, total); });
    return reply;
}

double ServoModbusDrive::channelReadUs(const QStringList &channelIds) const
{
    if (!m_link)
        return 0.0;
    QList<quint16> regs;
    for (const QString &id : channelIds.isEmpty() ? ServoModbusChannels::ids() : channelIds)
        regs += ServoModbusChannels::registers(id);
    const qint32 baud = m_link->settings().baud;
    const int bits = m_link->settings().bitsPerChar;
    double us = 0.0;
    // Per 0x03 request: 8 request bytes, 5 + 2n reply bytes, the drive's latency and the
    // silence before the next request to the same drive.
    const double silenceUs = double(m_link->sameDriveGapUs());
    for (const servomodbus::RegisterRange &r : servomodbus::planRegisterReads(regs))
        us += WireTime::serialBytesUs(8 + 5 + 2 * r.count, baud, bits) + 1000.0 + silenceUs;
    return us;
}

DriveReply *ServoModbusDrive::readChannels(const QStringList &channelIds)
{
    if (Error e = checkLink())
        return finishedReply(e);
    QStringList ids = channelIds;
    if (ids.isEmpty())
        ids = ServoModbusChannels::ids();
    QList<quint16> regs;
    for (const QString &id : ids) {
        const QList<quint16> r = ServoModbusChannels::registers(id);
        if (r.isEmpty())
            return finishedReply({ErrorCode::InvalidArgument,
                                  tr("Unknown channel \"%1\". This drive offers: %2.")
                                      .arg(id, ServoModbusChannels::ids().join(QStringLiteral(", ")))});
        regs += r;
    }
    DriveReply *reply = newReply();
    const QList<ModbusRequest> requests = readRequests(address(), servomodbus::planRegisterReads(regs),
                                                       QStringLiteral("monitor"));
    ModbusBatch::run(m_link, requests, reply, ModbusBatch::Mode::StopOnError,
                     [this, reply, requests, ids](const Error &error, const QList<ModbusBatch::Result> &results) {
                         if (error) {
                             reply->finish(error);
                             return;
                         }
                         const auto values = collect(requests, results);
                         for (const QString &id : ids)
                             reply->setSample(id, ServoModbusChannels::value(id, values, m_options.positionRule));
                         reply->setSampleTimeUs(nowUsSinceEpoch());
                         if (values.contains(AlarmRegister)) {
                             DriveStatus s = status();
                             s.online = true;
                             s.alarmCode = values.value(AlarmRegister);
                             updateStatus(s);
                         }
                         reply->finish();
                     });
    return reply;
}

// ---- Parameter writes ----

qint64 ServoModbusDrive::parameterValue(int index, quint16 raw) const
{
    // Signed unless the dictionary says the register is unsigned.
    const ParameterInfo *p = parameterDictionary().byIndex(index);
    return (p && p->type == ValueType::UInt16) ? qint64(raw) : qint64(qint16(raw));
}

Error ServoModbusDrive::checkWrites(const QList<ParameterWrite> &writes) const
{
    QSet<int> seen;
    for (const ParameterWrite &w : writes) {
        if (!servomodbus::isParameterIndex(w.index))
            return {ErrorCode::InvalidArgument,
                    tr("PA%1 does not exist: this drive has PA0..PA59. Nothing was written.").arg(w.index)};
        if (seen.contains(w.index))
            return {ErrorCode::InvalidArgument, tr("PA%1 is given twice. Nothing was written.").arg(w.index)};
        seen.insert(w.index);
        if (w.index == servomodbus::FirmwareParameter)
            return {ErrorCode::NotSupported,
                    tr("PA2 is the firmware version and cannot be written. Nothing was written.")};
        if (w.value < -32768 || w.value > 65535)
            return {ErrorCode::OutOfRange,
                    tr("%1 does not fit the 16-bit register of PA%2 (-32768..32767, or 0..65535 "
                       "unsigned). Nothing was written.")
                        .arg(w.value)
                        .arg(w.index)};
    }
    // The dictionary (a user's file or the bundled one): ranges, read-only parameters.
    if (Error e = validateWrites(writes)) {
        e.message += QLatin1Char(' ') + tr("Nothing was written.");
        return e;
    }
    return {};
}

DriveReply *ServoModbusDrive::writeParameters(const QList<ParameterWrite> &writes)
{
    if (Error e = checkLink())
        return finishedReply(e);
    if (Error e = checkWrites(writes))
        return finishedReply(e);
    DriveReply *reply = newReply();
    writeThenVerify(reply, writes);
    return reply;
}

void ServoModbusDrive::writeThenVerify(DriveReply *reply, const QList<ParameterWrite> &writes)
{
    QMap<int, quint16> values;
    for (const ParameterWrite &w : writes)
        values.insert(w.index, static_cast<quint16>(w.value));
    const QList<ModbusRequest> requests = writeRequests(address(), servomodbus::planWrites(values));
    const int readCount = int(servomodbus::planReads(values.keys()).size());
    const int total = int(requests.size()) + readCount;
    ModbusBatch::run(
        m_link, requests, reply, ModbusBatch::Mode::ContinueOnError,
        [this, reply, requests, writes](const Error &, const QList<ModbusBatch::Result> &results) {
            verifyWrites(reply, writes, errorsByParameter(requests, results));
        },
        [reply, total](int done, int) { reply->reportProgress(done, total); });
}

void ServoModbusDrive::verifyWrites(DriveReply *reply, const QList<ParameterWrite> &writes,
                                    const QHash<int, Error> &writeErrors)
{
    const QList<int> toRead = parametersToReadBack(writes, writeErrors);
    const QList<ModbusRequest> requests = readRequests(address(), servomodbus::planReads(toRead),
                                                       QStringLiteral("verify"));
    QMap<int, quint16> all;
    for (const ParameterWrite &w : writes)
        all.insert(w.index, 0);
    const int writesDone = int(servomodbus::planWrites(all).size());
    const int total = writesDone + int(requests.size());
    ModbusBatch::run(
        m_link, requests, reply, ModbusBatch::Mode::ContinueOnError,
        [this, reply, requests, writes, writeErrors, toRead](const Error &, const QList<ModbusBatch::Result> &results) {
            const QHash<quint16, quint16> regs = collect(requests, results);
            const QHash<int, Error> readErrors = errorsByParameter(requests, results);
            WriteVerification verification;
            for (const ParameterWrite &w : writes) {
                // A read error counts only where a read-back was asked for: a refused write
                // may share a failed read request with its neighbours.
                const Error readError = toRead.contains(w.index) ? readErrors.value(w.index) : Error::none();
                reply->addWriteResult(
                    verification.add(verificationCheck(w, writeErrors.value(w.index), regs, readError)));
            }
            reply->finish(verification.summary());
        },
        [reply, writesDone, total](int done, int) { reply->reportProgress(writesDone + done, total); });
}

WriteVerification::Check ServoModbusDrive::verificationCheck(const ParameterWrite &w, const Error &writeError,
                                                             const QHash<quint16, quint16> &regs,
                                                             const Error &readError) const
{
    WriteVerification::Check c;
    c.index = w.index;
    c.requested = w.value;
    c.label = QStringLiteral("PA%1").arg(w.index);
    c.writeError = writeError;
    c.readError = readError;
    const quint16 reg = servomodbus::parameterRegister(w.index);
    if (regs.contains(reg)) {
        // The register holds 16 bits: equal bits are the value written; otherwise a value
        // above 32767 was meant unsigned, the rest reads as the dictionary types it.
        const quint16 raw = regs.value(reg);
        c.readBack = raw == static_cast<quint16>(w.value) ? w.value
            : w.value > 32767                             ? qint64(raw)
                                                          : parameterValue(w.index, raw);
    }
    return c;
}

// ---- EE operations ----

DriveReply *ServoModbusDrive::eeOperation(EeOperation op)
{
    if (Error e = checkLink())
        return finishedReply(e);
    const auto sop = servomodbus::eeOpFromCode(static_cast<quint16>(op));
    if (!sop)
        return finishedReply({ErrorCode::InvalidArgument, tr("Unknown EE operation.")});
    DriveReply *reply = newReply();
    reply->setInfo(QStringLiteral("operation"), eeMnemonic(op));
    if (const auto format = servomodbus::chooseEeFormat(m_options.eeFormat, m_firmware)) {
        runEe(reply, *sop, *format);
        return reply;
    }
    // Auto and PA2 not known yet: read it first.
    LinkReply *r = m_link->readHoldingRegisters(address(),
                                                servomodbus::parameterRegister(servomodbus::FirmwareParameter), 1);
    connect(r, &LinkReply::finished, reply, [this, reply, r, sop] {
        r->deleteLater();
        if (r->error()) {
            Error e = r->error();
            e.message = tr("The firmware version (PA2) could not be read, so the EE command "
                           "format is unknown: %1 Choose the format by hand (option "
                           "servo-modbus.eeFormat = legacy or new).")
                            .arg(e.message);
            reply->finish(e);
            return;
        }
        m_firmware = r->registers().value(0);
        mutableIdentity().firmware = QString::number(*m_firmware);
        runEe(reply, *sop, servomodbus::eeFormatForFirmware(*m_firmware));
    });
    return reply;
}

void ServoModbusDrive::runEe(DriveReply *reply, servomodbus::EeOp op, servomodbus::EeFormat format)
{
    const bool legacy = format == servomodbus::EeFormat::Legacy;
    reply->setInfo(QStringLiteral("eeFormat"), legacy ? QStringLiteral("legacy") : QStringLiteral("new"));
    if (legacy) {
        const qint64 deadline = QDateTime::currentMSecsSinceEpoch() + m_options.eeTimeoutMs;
        pollLegacyEe(reply, op, deadline, 1);
        return;
    }
    ModbusRequest q;
    q.pdu = servomodbus::eeRequest(static_cast<quint8>(address()), op, format);
    q.timeoutMs = m_options.eeReplyTimeoutMs;
    q.note = QString::fromLatin1(servomodbus::eeOpMnemonic(op));
    LinkReply *r = m_link->send(q);
    connect(r, &LinkReply::finished, reply, [reply, r] {
        r->deleteLater();
        reply->finish(r->error());
    });
}

void ServoModbusDrive::pollLegacyEe(DriveReply *reply, servomodbus::EeOp op, qint64 deadlineMs, int polls)
{
    ModbusRequest q;
    q.pdu = servomodbus::eeRequest(static_cast<quint8>(address()), op, servomodbus::EeFormat::Legacy);
    q.note = QStringLiteral("%1 (poll %2)").arg(QLatin1String(servomodbus::eeOpMnemonic(op))).arg(polls);
    LinkReply *r = m_link->send(q);
    connect(r, &LinkReply::finished, reply, [this, reply, r, op, deadlineMs, polls] {
        r->deleteLater();
        if (r->error()) {
            reply->finish(r->error());
            return;
        }
        reply->setInfo(QStringLiteral("polls"), polls);
        const quint16 value = r->registers().value(1);
        const QString name = QString::fromLatin1(servomodbus::eeOpMnemonic(op));
        switch (servomodbus::interpretLegacyEeReply(value, op)) {
        case servomodbus::EeProgress::Finished: reply->finish(); return;
        case servomodbus::EeProgress::Failed:
            reply->finish({ErrorCode::DriveException,
                           tr("The drive answered %1 with %2 instead of 0 (running) or %3 "
                              "(done): the operation failed or another one is running.")
                               .arg(name)
                               .arg(value)
                               .arg(static_cast<int>(op)),
                           value});
            return;
        case servomodbus::EeProgress::Running: break;
        }
        if (QDateTime::currentMSecsSinceEpoch() >= deadlineMs) {
            reply->finish({ErrorCode::Timeout,
                           tr("%1 did not finish within %2 s: the drive still reports it "
                              "running after %3 polls. Do not switch the drive off; read its "
                              "parameters again to see what was stored.")
                               .arg(name)
                               .arg(m_options.eeTimeoutMs / 1000.0, 0, 'f', 1)
                               .arg(polls)});
            return;
        }
        QTimer::singleShot(m_options.eePollMs, reply,
                           [this, reply, op, deadlineMs, polls] { pollLegacyEe(reply, op, deadlineMs, polls + 1); });
    });
}

} // namespace dd
