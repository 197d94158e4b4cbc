#pragma once

#include "core/drive/shuoke/shuoketransport.h"
#include "core/link/framematch.h"
#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokertu.h"

namespace dd {

class SerialLink;

// Shuoke RTU and ASCII framings on a SerialLink (half duplex, one command at a time, at
// least options().minGapMs (50 ms) of quiet between commands, the V1.5 rule).
// Replies are recognised by matchers built on the codecs: the reply must come from the
// request's address (any address for a broadcast; old or new for 0x22), carry one of the
// command codes the table accepts for it (or that code | 0x80 with a failure code) and a
// data length the table allows. A frame-shaped reply with a bad CRC / check byte is
// "corrupt" (the link retries at once); anything else before it is skipped.
class ShuokeSerialTransport : public ShuokeTransport
{
    Q_OBJECT
public:
    ShuokeSerialTransport(const ShuokeOptions &options, QObject *parent = nullptr);
    ~ShuokeSerialTransport() override;

    bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) override;
    void close() override;
    bool isOpen() const override;
    QString description() const override;
    void cancelAll(const Error &why) override;
    int baud() const override;
    bool setBaud(int baud) override;

    SerialLink *link() const { return m_link; }

    // The wire bytes of `frame` in this transport's framing.
    Decoded<QByteArray> encode(const shuoke::Frame &frame) const;
    // Wire size of a reply with `dataBytes` data bytes.
    int wireSize(int dataBytes) const;

    // Reply matchers for SerialLink (public for tests and tools that send raw bytes).
    static ReplyMatcher rtuMatcher(const shuoke::Frame &request, const shuoke::RtuOptions &options = {});
    static ReplyMatcher asciiMatcher(const shuoke::Frame &request, const shuoke::AsciiOptions &options = {});
    ReplyMatcher matcher(const shuoke::Frame &request) const;

protected:
    LinkReply *start(const ShuokeRequest &request, Error *error) override;
    Decoded<shuoke::Frame> decode(const LinkReply &reply, const ShuokeRequest &request) const override;

private:
    shuoke::AsciiOptions asciiOptions() const;
    void onLinkClosed(const Error &why);

    SerialLink *m_link;
};

} // namespace dd
