#include "core/link/modbusbatch.h"

#include <QMetaObject>

namespace dd {

ModbusBatch::ModbusBatch(QObject *context, Mode mode, Done done, Progress progress)
    : QObject(context)
    , m_mode(mode)
    , m_done(std::move(done))
    , m_progress(std::move(progress))
{
}

ModbusBatch *ModbusBatch::run(ModbusLink *link, const QList<ModbusRequest> &requests, QObject *context, Mode mode,
                              Done done, Progress progress)
{
    auto *batch = new ModbusBatch(context, mode, std::move(done), std::move(progress));
    batch->m_results.resize(requests.size());
    if (requests.isEmpty()) {
        QMetaObject::invokeMethod(batch, &ModbusBatch::complete, Qt::QueuedConnection);
        return batch;
    }
    for (int i = 0; i < requests.size(); ++i) {
        LinkReply *reply = link->send(requests.at(i));
        batch->m_replies.append(reply);
        connect(reply, &LinkReply::finished, batch, [batch, i] { batch->onFinished(i); });
    }
    return batch;
}

void ModbusBatch::onFinished(int index)
{
    LinkReply *reply = m_replies.value(index);
    if (!reply || m_completed)
        return;
    Result &r = m_results[index];
    r.ran = true;
    r.error = reply->error();
    r.registers = reply->registers();
    reply->deleteLater();
    m_replies[index] = nullptr;
    ++m_finished;
    if (m_progress)
        m_progress(m_finished, int(m_results.size()));
    if (r.error.isError() && !m_firstError.isError()) {
        m_firstError = r.error;
        if (m_mode == Mode::StopOnError) {
            // Withdraw the rest: the link skips requests whose reply is gone.
            for (QPointer<LinkReply> &p : m_replies) {
                delete p.data();
                p = nullptr;
            }
            complete();
            return;
        }
    }
    if (m_finished == m_results.size())
        complete();
}

void ModbusBatch::complete()
{
    if (m_completed)
        return;
    m_completed = true;
    Done done = std::move(m_done);
    const Error error = m_firstError;
    const QList<Result> results = m_results;
    deleteLater();
    if (done)
        done(error, results);
}

} // namespace dd
