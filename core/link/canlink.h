#pragma once

#include "core/common/error.h"
#include "core/link/cansettings.h"
#include "core/link/linkreply.h"
#include "core/protocol/canframedata.h"

#include <QCanBusDevice>
#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QQueue>
#include <QTimer>
#include <functional>
#include <vector>

namespace dd {

class TrafficTap;

using CanMatcher = std::function<bool(const CanFrameData &frame)>;

// One request on a CAN bus: a frame and, if it is answered, how to recognise the answer.
struct CanRequest
{
    CanFrameData frame;
    CanMatcher matcher; // empty: no reply expected
    int timeoutMs = -1; // -1: settings.responseTimeoutMs
    int retries = -1;   // -1: settings.retries
    // The identifier the answer comes with, when known (servo-can: the request's own ID).
    // The timeout then forgives only the bus time of frames that win arbitration over it;
    // -1: unknown, every frame on the bus is taken to hold the answer back.
    qint64 answerId = -1;
    bool answerExtended = false;
    QString note;
    bool urgent = false; // stop / disable: ahead of every waiting ordinary request
};

// Transport on QCanBusDevice (socketcan, virtualcan, ...). Frames sent before the device
// is connected wait in a queue. Requests are pipelined: up to maxInFlight are outstanding
// at once and each received frame completes the oldest request whose matcher accepts it.
// Every received frame is also emitted by frameReceived() (heartbeats, alarms, ...).
// An urgent request (stop, disable) goes ahead of every request waiting for the window,
// behind the urgent ones queued before it; one that expects no reply takes no place in the
// window, so it is written at once (nothing in flight is aborted).
//
// Fair window (docs/reliability.md, "Several stations on one CAN bus"): ordinary requests
// wait in one lane per destination (the request frame's identifier), each lane in the order
// its requests came; a free place in the window goes to the lane with the fewest requests
// in flight (round robin between equals). So one station's 220 pipelined reads do not hold
// the window while the other stations' requests wait behind them.
//
// Timeouts count only the time the answer could have been on the bus. A CAN node cannot
// send while another frame is on the bus, and loses arbitration to every frame with a lower
// identifier: a station whose answer is ready may wait behind our own queued requests and
// the other stations' answers for as long as they keep the bus busy (a saturated bus, as
// several stations' pipelined reads make it). So the bus time of every frame received after
// the request was written that outranks the answer or has its identifier (CanRequest::
// answerId; all of them when unknown), of our own later frames that outrank it strictly,
// and of our own frames still queued ahead of it, is not counted as the station's silence
// (worst-case stuffed frame times at settings.bitrate). A request gives up regardless after
// StarvedTimeoutFactor times its timeout in wall-clock time (a bus held by a babbling node).
// The QCanBusDevice is created in open(), so the link may be moved to a worker thread first.
class CanLink : public QObject
{
    Q_OBJECT
public:
    static constexpr int StarvedTimeoutFactor = 40;

    explicit CanLink(QObject *parent = nullptr);
    ~CanLink() override;

    void setTap(TrafficTap *tap) { m_tap = tap; }
    TrafficTap *tap() const { return m_tap; }

    bool open(const CanSettings &settings, Error *error = nullptr);
    void close();
    bool isConnected() const;
    const CanSettings &settings() const { return m_settings; }
    QString name() const { return m_settings.toString(); }

    // Send a frame that expects no reply. Returns false when the link is closed.
    bool send(const CanFrameData &frame, const QString &note = {});
    // Send a request; the reply is parented to the link; delete it when done.
    LinkReply *request(const CanRequest &request);
    void cancelAll(const Error &why);
    int inFlightCount() const { return m_inFlight.size(); }
    quint64 timeoutCount() const { return m_timeouts; }
    quint64 retryCount() const { return m_retryCount; }

signals:
    void connected();
    void frameReceived(const dd::CanFrameData &frame);
    void closed(const dd::Error &reason);

private:
    struct Pending
    {
        CanRequest request;
        QPointer<LinkReply> reply;
        int attempts = 0;
        qint64 sentUs = 0;
        qint64 excusedUs = 0; // bus time since sentUs in which the answer could not be sent
    };
    // Ordinary requests to one destination, in the order they came.
    struct Lane
    {
        quint64 key = 0;
        QQueue<Pending> queue;
        int inFlight = 0;
    };

    void onStateChanged(QCanBusDevice::CanBusDeviceState state);
    void onErrorOccurred(QCanBusDevice::CanBusError error);
    void onFramesReceived();
    void onTick();
    void pump();
    Lane *pickLane();
    Lane &laneFor(quint64 key);
    void dispatch(Pending p);
    void release(const Pending &p);
    bool writeNow(const CanFrameData &frame, const QString &note);
    void excuse(const CanFrameData &frame, bool own = false);
    qint64 frameBusUs(const CanFrameData &frame) const;
    qint64 dueUs(const Pending &p) const;
    void failAll(const Error &why);
    void armTimer();
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }

    CanSettings m_settings;
    QCanBusDevice *m_device = nullptr;
    TrafficTap *m_tap = nullptr;
    QQueue<QPair<CanFrameData, QString>> m_unsent; // written once connected
    QQueue<Pending> m_urgent;                      // urgent requests not yet sent
    std::vector<Lane> m_lanes;                     // ordinary requests not yet sent, per destination
    size_t m_nextLane = 0;                         // round robin between lanes of equal load
    QList<Pending> m_inFlight;
    qint64 m_ownBusEndUs = 0; // when the frames we wrote so far have left (estimate)
    QTimer m_timer;
    QElapsedTimer m_clock;
    bool m_closing = false;
    quint64 m_timeouts = 0;
    quint64 m_retryCount = 0;
};

} // namespace dd
