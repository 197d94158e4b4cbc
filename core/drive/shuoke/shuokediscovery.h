#pragma once

#include "core/drive/discovery.h"

#include <QPointer>
#include <QSet>
#include <QTimer>

namespace dd {

class ShuokeTransport;
class ShuokeSerialTransport;
class ShuokeCanTransport;
struct CanFrameData;

// Finds Shuoke drives (docs/protocols/shuoke.md, "Discovery").
//
// CAN: the query-address command 0x21 is sent to identifier 0; every drive answers with
// its address (CAN arbitration orders the replies). Replies are collected for
// ScanOptions::listenMs.
//
// Serial (RTU / ASCII): for each baud rate of ScanOptions::bauds (the link's rate when
// empty) the handshake 0x20 is sent to every address from..to, one at a time with the 50 ms
// gap; a drive at the wrong baud cannot understand it and stays silent. With option
// "shuoke.scanSkipSilent" (default on) a broadcast 0x21 goes first at each rate: when not
// a single byte comes back, no drive listens at that rate and its address scan is skipped
// (several drives answering at once garble each other, which counts as "heard").
// A drive that answered the broadcast cleanly is reported at once.
//
// PLC mode: the baud code (0x23, two registers) is read at every address.
//
// The link is left at the baud rate it had.
class ShuokeDiscovery : public Discovery
{
    Q_OBJECT
public:
    ShuokeDiscovery(ShuokeTransport *transport, const ScanOptions &options, QObject *parent = nullptr);
    ~ShuokeDiscovery() override;

    void start() override;
    void cancel() override;

    // Per-probe timeout used at `baud` (ScanOptions::timeoutMs, or adaptive).
    int probeTimeoutMs(int baud) const;
    int skippedBauds() const { return m_skippedBauds; }

private:
    void startCan();
    void onCanFrame(const CanFrameData &frame);
    void onListenDone();
    void startBaud();
    void probeBroadcast();
    void probeNextAddress();
    void probeAddress(int address);
    void addressDone();
    void report(int address);
    void finish(const Error &error);
    int baudCount() const;

    QPointer<ShuokeTransport> m_transport;
    ScanOptions m_options;
    QList<int> m_bauds;
    int m_baudIndex = 0;
    int m_address = 0;
    int m_originalBaud = 0;
    int m_done = 0;
    int m_total = 0;
    int m_skippedBauds = 0;
    bool m_running = false;
    bool m_cancelled = false;
    QSet<int> m_foundAtBaud; // addresses found at the current baud (CAN: all)
    QTimer m_listen;
    QMetaObject::Connection m_canConnection;
};

} // namespace dd
