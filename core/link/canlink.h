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
// The QCanBusDevice is created in open(), so the link may be moved to a worker thread first.
class CanLink : public QObject
{
    Q_OBJECT
public:
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
        qint64 deadlineUs = 0;
        qint64 sentUs = 0;
    };

    void onStateChanged(QCanBusDevice::CanBusDeviceState state);
    void onErrorOccurred(QCanBusDevice::CanBusError error);
    void onFramesReceived();
    void onTick();
    void pump();
    bool writeNow(const CanFrameData &frame, const QString &note);
    void failAll(const Error &why);
    void armTimer();
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }

    CanSettings m_settings;
    QCanBusDevice *m_device = nullptr;
    TrafficTap *m_tap = nullptr;
    QQueue<QPair<CanFrameData, QString>> m_unsent; // written once connected
    QQueue<Pending> m_waiting;                     // requests not yet sent (window full)
    QList<Pending> m_inFlight;
    QTimer m_timer;
    QElapsedTimer m_clock;
    bool m_closing = false;
    quint64 m_timeouts = 0;
    quint64 m_retryCount = 0;
};

} // namespace dd
