#pragma once

#include "core/common/error.h"
#include "core/protocol/canframedata.h"

#include <QByteArray>
#include <QList>
#include <QObject>

namespace dd {

// The answer to one request on a link (serial or CAN), in the manner of QModbusReply:
// finished() is emitted exactly once, always from the event loop (never inside send()).
// The link parents it; the receiver calls deleteLater() when done with it.
class LinkReply : public QObject
{
    Q_OBJECT
public:
    explicit LinkReply(QObject *parent = nullptr);

    bool isFinished() const { return m_finished; }
    const Error &error() const { return m_error; }
    QByteArray frame() const { return m_frame; }             // serial: the matched reply frame
    CanFrameData canFrame() const { return m_canFrame; }     // CAN: the matched reply frame
    QList<quint16> registers() const { return m_registers; } // Modbus: register values
    int attempts() const { return m_attempts; }              // 1 = first try answered
    qint64 roundTripUs() const { return m_roundTripUs; }

    // For links only.
    void setAttempts(int attempts) { m_attempts = attempts; }
    void setRoundTripUs(qint64 us) { m_roundTripUs = us; }
    void finishWithFrame(const QByteArray &frame);
    void finishWithCanFrame(const CanFrameData &frame);
    void finishWithRegisters(const QList<quint16> &registers);
    void finishWithError(const Error &error);
    void finishEmpty(); // for requests that expect no reply

signals:
    void finished();

private:
    void finishLater();

    bool m_finished = false;
    Error m_error;
    QByteArray m_frame;
    CanFrameData m_canFrame;
    QList<quint16> m_registers;
    int m_attempts = 0;
    qint64 m_roundTripUs = 0;
};

} // namespace dd
