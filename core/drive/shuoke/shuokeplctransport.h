#pragma once

#include "core/drive/shuoke/shuoketransport.h"

namespace dd {

class ModbusLink;

// Shuoke "PLC mode" on a ModbusLink (RS485, standard Modbus RTU): a command becomes a read
// (0x03) or write (0x10) of the registers at "shuoke.plcBase" + command code (see
// protocol/shuokeplc.h). Only the commands the seed's PLC chapter maps are carried; the
// handshake and query-address map to reads of 0 registers, which no Modbus client sends,
// so they are refused too (NotSupported, nothing sent). A Modbus exception is a
// DriveException whose driveCode is the exception code; the message also gives the Shuoke
// failure meaning of that number, which is what the drives put there.
// The 50 ms gap between commands ("shuoke.minGapMs") applies as on the other serial framings.
class ShuokePlcTransport : public ShuokeTransport
{
    Q_OBJECT
public:
    ShuokePlcTransport(const ShuokeOptions &options, QObject *parent = nullptr);
    ~ShuokePlcTransport() override;

    bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) override;
    void close() override;
    bool isOpen() const override;
    QString description() const override;
    void cancelAll(const Error &why) override;
    int baud() const override;
    bool setBaud(int baud) override;
    QString cannotCarry(const shuoke::Frame &frame) const override;

    ModbusLink *link() const { return m_link; }

protected:
    LinkReply *start(const ShuokeRequest &request, Error *error) override;
    Decoded<shuoke::Frame> decode(const LinkReply &reply, const ShuokeRequest &request) const override;
    Error translateLinkError(const Error &error, const ShuokeRequest &request) const override;

private:
    void onLinkClosed(const Error &why);

    ModbusLink *m_link;
};

} // namespace dd
