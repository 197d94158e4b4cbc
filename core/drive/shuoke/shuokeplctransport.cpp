#include "core/drive/shuoke/shuokeplctransport.h"

#include "core/link/connectionsettings.h"
#include "core/link/linkreply.h"
#include "core/link/modbuslink.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokeplc.h"

#include <QCoreApplication>

namespace dd {

using shuoke::Frame;

ShuokePlcTransport::ShuokePlcTransport(const ShuokeOptions &options, QObject *parent)
    : ShuokeTransport(options, parent)
    , m_link(new ModbusLink(this))
{
    connect(m_link, &ModbusLink::closed, this, &ShuokePlcTransport::onLinkClosed);
}

ShuokePlcTransport::~ShuokePlcTransport() = default;

bool ShuokePlcTransport::open(const ConnectionSettings &settings, TrafficTap *tap, Error *error)
{
    m_link->setTap(tap);
    return m_link->open(serialSettings(settings), error);
}

void ShuokePlcTransport::close()
{
    m_link->close();
}

bool ShuokePlcTransport::isOpen() const
{
    return m_link->isOpen();
}

QString ShuokePlcTransport::description() const
{
    return tr("%1 @ %2 baud, Shuoke PLC mode (Modbus registers from 0x%3)")
        .arg(m_link->name())
        .arg(m_link->settings().baud)
        .arg(options().plcBase, 4, 16, QLatin1Char('0'));
}

void ShuokePlcTransport::cancelAll(const Error &why)
{
    m_link->cancelAll(why);
}

int ShuokePlcTransport::baud() const
{
    return m_link->settings().baud;
}

bool ShuokePlcTransport::setBaud(int baud)
{
    return setSerialBaud(m_link, baud);
}

QString ShuokePlcTransport::cannotCarry(const Frame &frame) const
{
    const QString base = ShuokeTransport::cannotCarry(frame);
    if (!base.isEmpty())
        return base;
    const shuoke::CommandInfo *info = shuoke::commandInfo(frame.command);
    const QString name = info ? QCoreApplication::translate("dd::shuoke", info->name)
                              : shuoke::commandName(frame.command);
    if (!info || info->plcAccess == shuoke::PlcAccess::None)
        return tr("\"%1\" has no register in PLC mode; use the RTU framing for it.").arg(name);
    if (info->plcAccess == shuoke::PlcAccess::Read && info->plcRegisters == 0)
        return tr("\"%1\" maps to a read of 0 registers in PLC mode, which Modbus cannot send; "
                  "use the RTU framing for it.")
            .arg(name);
    shuoke::PlcOptions o;
    o.base = options().plcBase;
    const Decoded<shuoke::PlcRequestLayout> layout = shuoke::plcRequestLayout(frame, o);
    if (!layout.ok())
        return tr("\"%1\" cannot be sent in PLC mode: %2").arg(name, layout.error);
    return QString();
}

LinkReply *ShuokePlcTransport::start(const ShuokeRequest &request, Error *error)
{
    shuoke::PlcOptions o;
    o.base = options().plcBase;
    const Decoded<shuoke::PlcRequestLayout> layout = shuoke::plcRequestLayout(request.frame, o);
    if (!layout.ok()) {
        *error = {ErrorCode::InvalidArgument, tr("The command cannot be encoded: %1").arg(layout.error)};
        return nullptr;
    }
    ModbusRequest r;
    r.pdu.address = request.frame.address;
    r.pdu.function = layout.value->function;
    r.pdu.start = layout.value->registerAddress;
    r.pdu.count = layout.value->registerCount;
    r.pdu.values = shuoke::plcBytesToRegisters(layout.value->values);
    r.timeoutMs = request.timeoutMs;
    r.retries = request.retries;
    r.urgent = request.urgent;
    r.note = request.note.isEmpty() ? shuoke::commandName(request.frame.command) : request.note;
    return m_link->send(r);
}

Decoded<Frame> ShuokePlcTransport::decode(const LinkReply &reply, const ShuokeRequest &request) const
{
    const shuoke::CommandInfo *info = shuoke::commandInfo(request.frame.command);
    if (info && info->plcAccess == shuoke::PlcAccess::Read) {
        const Decoded<QByteArray> data = shuoke::plcReplyData(request.frame.command,
                                                              shuoke::plcRegistersToBytes(reply.registers()));
        if (!data.ok())
            return Decoded<Frame>::failure(data.error);
        return Decoded<Frame>::success(Frame::make(request.frame.address, request.frame.command, *data.value));
    }
    return Decoded<Frame>::success(Frame::make(request.frame.address, request.frame.command));
}

Error ShuokePlcTransport::translateLinkError(const Error &error, const ShuokeRequest &request) const
{
    if (error.code != ErrorCode::DriveException)
        return error;
    const Frame failure = Frame::failureReply(request.frame.address, request.frame.command,
                                              static_cast<quint8>(error.driveCode));
    Error e = failureError(failure);
    e.message = tr("%1 (PLC mode: Modbus exception %2)").arg(e.message).arg(error.driveCode);
    return e;
}

void ShuokePlcTransport::onLinkClosed(const Error &why)
{
    if (why.isError())
        emit linkLost(why);
}

} // namespace dd
