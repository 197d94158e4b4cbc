#pragma once

#include "common/error.h"
#include "link/linkreply.h"
#include "link/serialsettings.h"

#include <QObject>

namespace dd {

class TrafficTap;

// Modbus RTU client transport on QModbusRtuSerialClient (servo-modbus, shuoke PLC mode),
// with the Qt 6.4 pitfalls of DESIGN.md handled:
//  - requests go one at a time through our own queue; the client's own retries are off;
//  - after a timeout the line is kept quiet (and the client reconnected) so that a late
//    reply can never be handed to the next request with the same address and function;
//  - setInterFrameDelay(-1) before every connectDevice() (baud changes reconnect);
//  - the response timeout covers the request's and the reply's byte time at the baud;
//  - a serial error (adapter unplugged) closes the link and fails everything pending.
// Exceptions finish the reply with ErrorCode::DriveException and Error::driveCode set.
// The tap receives the request and reply ADUs (rebuilt from the PDUs; CRC included).
class ModbusLink : public QObject
{
    Q_OBJECT
public:
    explicit ModbusLink(QObject *parent = nullptr);
    ~ModbusLink() override;

    void setTap(TrafficTap *tap);
    bool open(const SerialSettings &settings, Error *error = nullptr);
    void close();
    bool isOpen() const;
    const SerialSettings &settings() const;
    QString name() const;
    bool setBaudRate(qint32 baud);   // between transactions only

    // Replies carry registers(): the values read, or for writes the echoed start/count.
    LinkReply *readHoldingRegisters(int serverAddress, int start, int count, int timeoutMs = -1);
    LinkReply *writeRegisters(int serverAddress, int start, const QList<quint16> &values, int timeoutMs = -1);
    LinkReply *writeSingleRegister(int serverAddress, int reg, quint16 value, int timeoutMs = -1);
    void cancelAll(const Error &why);

    quint64 timeoutCount() const;
    quint64 retryCount() const;

signals:
    void opened();
    void closed(const dd::Error &reason);

private:
    class Private;
    Private *d;
};

} // namespace dd
