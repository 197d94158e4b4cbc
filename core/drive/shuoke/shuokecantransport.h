#pragma once

#include "core/drive/shuoke/shuoketransport.h"
#include "core/link/canlink.h"

namespace dd {

// Shuoke over CAN on a CanLink: identifier = address (0 = broadcast), data = the RTU frame
// without CRC, zero-padded to 8 bytes. Default bitrate 100 kbit/s (code 12). Frames with
// more than 5 data bytes cannot go over CAN (NotSupported, nothing sent). A reply is the
// first frame that decodes and answers the request (isReplyTo); requests to different
// drives are pipelined by the link.
class ShuokeCanTransport : public ShuokeTransport
{
    Q_OBJECT
public:
    static constexpr int kDefaultResponseMs = 100;

    ShuokeCanTransport(const ShuokeOptions &options, QObject *parent = nullptr);
    ~ShuokeCanTransport() override;

    bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) override;
    void close() override;
    bool isOpen() const override;
    QString description() const override;
    void cancelAll(const Error &why) override;
    QString cannotCarry(const shuoke::Frame &frame) const override;

    CanLink *link() const { return m_link; }
    int bitrate() const { return m_bitrate; }
    static CanMatcher matcher(const shuoke::Frame &request);

protected:
    LinkReply *start(const ShuokeRequest &request, Error *error) override;
    Decoded<shuoke::Frame> decode(const LinkReply &reply, const ShuokeRequest &request) const override;

private:
    void onLinkClosed(const Error &why);

    CanLink *m_link;
    int m_bitrate = 0;
};

} // namespace dd
