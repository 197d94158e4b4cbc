#pragma once

#include "core/common/error.h"
#include "core/link/modbuslink.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <functional>

namespace dd {

// Several Modbus requests handed to a ModbusLink at once (so that the link sends them back
// to back, without a trip through the caller between them) and reported together.
//
// Each request gets its own result. With StopOnError the first failure withdraws the
// requests not yet sent and finishes the batch; with ContinueOnError every request runs.
// done() is called once, from the event loop; progress() after each finished request.
// The batch deletes itself after done() (it is parented to `context`, so it also goes
// away with it, silently).
class ModbusBatch : public QObject
{
    Q_OBJECT
public:
    enum class Mode { StopOnError, ContinueOnError };
    struct Result
    {
        Error error;
        QList<quint16> registers;
        bool ran = false; // false: withdrawn after an earlier failure
    };
    using Done = std::function<void(const Error &firstError, const QList<Result> &results)>;
    using Progress = std::function<void(int done, int total)>;

    static ModbusBatch *run(ModbusLink *link, const QList<ModbusRequest> &requests, QObject *context, Mode mode,
                            Done done, Progress progress = {});

private:
    ModbusBatch(QObject *context, Mode mode, Done done, Progress progress);
    void onFinished(int index);
    void complete();

    Mode m_mode;
    Done m_done;
    Progress m_progress;
    QList<QPointer<LinkReply>> m_replies;
    QList<Result> m_results;
    Error m_firstError;
    int m_finished = 0;
    bool m_completed = false;
};

} // namespace dd
