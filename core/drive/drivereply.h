#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"

#include <QMap>
#include <QObject>

namespace dd {

// The answer to one Drive operation, in the manner of QModbusReply: finished() is emitted
// exactly once, always from the event loop (never inside the call that created it), so a
// caller may connect after the call returns. The drive parents it; call deleteLater() in
// the finished handler (or let the drive's destruction take it).
class DriveReply : public QObject
{
    Q_OBJECT
public:
    explicit DriveReply(QObject *parent = nullptr);

    bool isFinished() const { return m_finished; }
    const Error &error() const { return m_error; }
    bool ok() const { return m_finished && !m_error.isError(); }

    // Results, by operation.
    const QMap<int, qint64> &parameters() const { return m_parameters; }         // readParameters
    const QList<ParameterWriteResult> &writeResults() const { return m_writes; } // writeParameters
    const QMap<QString, double> &samples() const { return m_samples; }           // readChannels
    qint64 sampleTimeUs() const { return m_sampleTimeUs; }
    const DriveStatus &status() const { return m_status; } // readStatus/readAlarm
    const QVariantMap &info() const { return m_info; }     // anything else

    // For drive implementations.
    void setParameter(int index, qint64 value) { m_parameters.insert(index, value); }
    void addWriteResult(const ParameterWriteResult &r) { m_writes.append(r); }
    void setSample(const QString &channel, double value) { m_samples.insert(channel, value); }
    void setSampleTimeUs(qint64 us) { m_sampleTimeUs = us; }
    void setStatus(const DriveStatus &s) { m_status = s; }
    void setInfo(const QString &key, const QVariant &value) { m_info.insert(key, value); }
    void reportProgress(int done, int total) { emit progress(done, total); }
    void finish(const Error &error = Error::none());

signals:
    void progress(int done, int total);
    void finished();

private:
    bool m_finished = false;
    Error m_error;
    QMap<int, qint64> m_parameters;
    QList<ParameterWriteResult> m_writes;
    QMap<QString, double> m_samples;
    qint64 m_sampleTimeUs = 0;
    DriveStatus m_status;
    QVariantMap m_info;
};

} // namespace dd
