#pragma once

#include "core/common/error.h"
#include "core/drive/shuoke/shuokeoptions.h"
#include "core/link/serialsettings.h"
#include "core/protocol/codecresult.h"
#include "core/protocol/shuoke/shuokeframe.h"

#include <QObject>
#include <functional>

namespace dd {

struct ConnectionSettings;
class LinkReply;
class TrafficTap;

// One Shuoke command on the wire, whatever the framing.
struct ShuokeRequest
{
    shuoke::Frame frame;
    bool expectReply = true; // false: sent without waiting (broadcast stops)
    int timeoutMs = -1;      // -1: the link's default (wire time + allowance)
    int retries = -1;        // -1: the link's default
    QString note;            // shown in the trace
    bool urgent = false;     // stops: ahead of every waiting ordinary request on the link
};

// The framing-specific half of a Shuoke session: turns a Frame into wire bytes on its link
// (SerialLink for RTU / ASCII, CanLink for CAN, ModbusLink for PLC mode), recognises the
// reply and decodes it back into a Frame. Everything above it (ShuokeDrive,
// ShuokeDiscovery) is written once for all four framings.
//
// request() never answers synchronously: the handler runs from the event loop, once, with
// either an error or the reply frame. A failure reply of the drive ([addr][cmd|0x80][1]
// [code], or a Modbus exception in PLC mode) is an ErrorCode::DriveException error whose
// driveCode is the failure code. Requests the framing cannot carry (a 7-byte frame over
// CAN, a command without a PLC register, 0x40 over CAN ...) fail with NotSupported and
// nothing is sent.
class ShuokeTransport : public QObject
{
    Q_OBJECT
public:
    using Handler = std::function<void(const Error &error, const shuoke::Frame &reply)>;

    ShuokeTransport(const ShuokeOptions &options, QObject *parent = nullptr);
    ~ShuokeTransport() override;

    virtual bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual QString description() const = 0;
    virtual void cancelAll(const Error &why) = 0;
    // Serial framings: the link's baud rate, and switching it between transactions (after
    // the drive accepted a new baud code; discovery sweeps). 0 / false elsewhere.
    virtual int baud() const { return 0; }
    virtual bool setBaud(int baud);
    // Why this framing cannot carry `frame`; empty when it can.
    virtual QString cannotCarry(const shuoke::Frame &frame) const;

    ShuokeFraming framing() const { return m_options.framing; }
    const ShuokeOptions &options() const { return m_options; }
    void setOptions(const ShuokeOptions &options) { m_options = options; }

    // Sends `request`; `handler` runs once from the event loop unless `context` is
    // destroyed first.
    void request(const ShuokeRequest &request, QObject *context, Handler handler);

    // The DriveException error of a failure reply, with the failure text.
    static Error failureError(const shuoke::Frame &reply);

signals:
    void linkLost(const dd::Error &why);

protected:
    // Starts the request on the link; nullptr with `error` set when it cannot.
    virtual LinkReply *start(const ShuokeRequest &request, Error *error) = 0;
    // The reply frame a successful LinkReply carries.
    virtual Decoded<shuoke::Frame> decode(const LinkReply &reply, const ShuokeRequest &request) const = 0;
    // Link errors may be reworded by the framing (PLC: Modbus exceptions).
    virtual Error translateLinkError(const Error &error, const ShuokeRequest &request) const;

    // The serial framings (RTU, ASCII, PLC): port settings from the connection (9600 baud
    // and a 100 ms allowance unless given), paced as the options say (the 50 ms rule).
    static constexpr int kDefaultSerialResponseMs = 100;
    SerialSettings serialSettings(const ConnectionSettings &settings) const;
    // Changes a serial link's baud rate between transactions and re-paces it for the rate.
    template <typename SerialLinkType>
    bool setSerialBaud(SerialLinkType *link, int baud) const
    {
        if (!link->setBaudRate(baud))
            return false;
        int gapMs = 0;
        int spacingMs = 0;
        options().applyGap(baud, link->settings().bitsPerChar, &gapMs, &spacingMs);
        link->setMinGapMs(gapMs);
        link->setMinCommandSpacingMs(spacingMs);
        return true;
    }

private:
    ShuokeOptions m_options;
};

} // namespace dd
