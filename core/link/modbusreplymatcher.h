#pragma once

#include "core/link/framematch.h"
#include "core/protocol/modbus/modbusrtu.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>
#include <memory>

namespace dd {

// What ModbusLink hands SerialLink to recognise the answer to one Modbus request, and the
// words of its errors. See ModbusLink for the rules; in the receive buffer (everything
// since the request went out):
//  - the first CRC-valid frame that answers the request (decodeReply) is the reply, an
//    exception for the request's function whatever its address byte included;
//  - a CRC-valid frame from another address or of another function is passed over
//    (Garbage; remembered for the timeout's words), as are bytes before a valid frame;
//  - a CRC-valid *request* frame at the front (another master asking a drive, an adapter's
//    echo) is passed over the same way: traffic of others, not a damaged reply;
//  - a CRC-valid frame from the request's address that does not fit it (byte count, echo,
//    register count) is Unfit: the request is asked again, or fails Malformed;
//  - at least the reply's length of bytes with no valid frame among them is Corrupt (a
//    damaged reply: ChecksumError, asked again); fewer wait for more, or for the timeout.
class ModbusReplyMatcher
{
    Q_DECLARE_TR_FUNCTIONS(dd::ModbusReplyMatcher)
public:
    ModbusReplyMatcher(const modbusrtu::Request &request, QString portName);

    ReplyMatcher matcher() const;
    // The timeout's words: what came instead of the reply, if anything.
    QString describeTimeout(int timeoutMs, const QByteArray &unmatched) const;
    QString describeCorrupt() const;

    // The addresses of the complete CRC-valid Modbus replies among `bytes`.
    static QList<int> peersIn(const QByteArray &bytes);

private:
    struct Seen
    {
        QList<QByteArray> foreign; // frames from other addresses / of other functions
    };
    static FrameMatch match(const modbusrtu::Request &request, const QString &port, Seen &seen,
                            const QByteArray &buffer);

    modbusrtu::Request m_request;
    QString m_port;
    std::shared_ptr<Seen> m_seen;
};

} // namespace dd
