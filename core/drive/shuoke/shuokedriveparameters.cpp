// ShuokeDrive: parameter reads and verified writes (see shuokedrive.h).
#include "core/drive/shuoke/shuokedrive.h"
#include "core/drive/shuoke/shuokeparameter.h"
#include "core/drive/writeverification.h"

#include <QVariantMap>
#include <memory>

namespace dd {

using namespace shuoke;

QList<int> ShuokeDrive::parameterIndices() const
{
    QList<int> out;
    for (const ShuokeParameter &p : ShuokeParameter::all())
        if (maySupport(p.setCommand, p.size))
            out.append(p.index());
    return out;
}

std::optional<qint64> ShuokeDrive::lastWritten(int index) const
{
    const auto it = m_lastWritten.constFind(index);
    if (it == m_lastWritten.cend())
        return std::nullopt;
    return *it;
}

void ShuokeDrive::readOneParameter(DriveReply *reply, const ShuokeParameter &p,
                                   std::function<void(const Error &, qint64)> done)
{
    const ShuokeParameter param = p;
    exchange(reply, p.readCommand, {}, [this, param, done](const Error &e, const Frame &f) {
        if (e) {
            done(e, 0);
            return;
        }
        const auto v = param.decode(f.data, byteOrder());
        if (!v) {
            done({ErrorCode::Malformed,
                  tr("The drive answered %1 data bytes for parameter %2 (%3 expected).")
                      .arg(f.data.size())
                      .arg(QString::fromLatin1(param.key))
                      .arg(param.size)},
                 0);
            return;
        }
        done(Error::none(), *v);
    });
}

DriveReply *ShuokeDrive::readParameters(const QList<int> &indices)
{
    QList<const ShuokeParameter *> asked;
    const QList<int> wanted = indices.isEmpty() ? parameterIndices() : indices;
    for (int index : wanted) {
        const ShuokeParameter *p = ShuokeParameter::byIndex(index);
        if (!p)
            return finishedReply({ErrorCode::InvalidArgument,
                                  tr("%1 is not a Shuoke parameter (the index is the SET command code).").arg(index)});
        if (!maySupport(p->setCommand, p->size))
            return finishedReply({ErrorCode::NotSupported, commandUnavailable(p->setCommand, p->size)});
        if (p->isReadable()) {
            const QString why = commandUnavailable(p->readCommand, 0);
            if (!why.isEmpty())
                return finishedReply({ErrorCode::NotSupported, why});
        }
        if (!asked.contains(p))
            asked.append(p);
    }

    DriveReply *reply = newReply();
    QVariantList notReadable;
    QVariantMap lastWrittenValues;
    QList<const ShuokeParameter *> readable;
    for (const ShuokeParameter *p : std::as_const(asked)) {
        if (p->isReadable()) {
            readable.append(p);
            continue;
        }
        notReadable.append(p->index());
        if (const auto v = lastWritten(p->index()))
            lastWrittenValues.insert(QString::number(p->index()), *v);
    }
    reply->setInfo(QStringLiteral("notReadable"), notReadable);
    reply->setInfo(QStringLiteral("lastWritten"), lastWrittenValues);
    if (readable.isEmpty()) {
        reply->finish();
        return reply;
    }

    struct State
    {
        int pending = 0;
        int done = 0;
        Error first;
    };
    auto state = std::make_shared<State>();
    state->pending = static_cast<int>(readable.size());
    const int total = state->pending;
    for (const ShuokeParameter *p : std::as_const(readable)) {
        const int index = p->index();
        const QString key = QString::fromLatin1(p->key);
        readOneParameter(reply, *p, [reply, state, index, total, key](const Error &e, qint64 value) {
            if (e && !state->first) {
                state->first = e;
                state->first.message = tr("%1: %2").arg(key, e.message);
            }
            if (!e)
                reply->setParameter(index, value);
            reply->reportProgress(++state->done, total);
            if (--state->pending == 0)
                reply->finish(state->first);
        });
    }
    return reply;
}

Error ShuokeDrive::checkParameterWrite(const ParameterWrite &w, const ShuokeParameter **param) const
{
    const ShuokeParameter *p = ShuokeParameter::byIndex(w.index);
    if (!p)
        return {ErrorCode::InvalidArgument,
                tr("%1 is not a Shuoke parameter (the index is the SET command code).").arg(w.index)};
    if (!p->inRange(w.value))
        return {ErrorCode::OutOfRange,
                tr("%1 must be %2..%3; %4 was not sent.")
                    .arg(QString::fromLatin1(p->key))
                    .arg(p->min)
                    .arg(p->max)
                    .arg(w.value)};
    if (const Error e = check(p->setCommand, p->encode(w.value, byteOrder())))
        return e;
    if (p->isReadable()) {
        const QString why = commandUnavailable(p->readCommand, 0);
        if (!why.isEmpty())
            return {ErrorCode::NotSupported, why};
    }
    *param = p;
    return Error::none();
}

DriveReply *ShuokeDrive::writeParameters(const QList<ParameterWrite> &writes)
{
    // The dictionary first (names, ranges of the user's file), then the drive's own limits.
    if (const Error e = validateWrites(writes))
        return finishedReply(e);
    for (const ParameterWrite &w : writes) {
        const ShuokeParameter *p = nullptr;
        if (const Error e = checkParameterWrite(w, &p))
            return finishedReply(e);
    }
    DriveReply *reply = newReply();
    writeNext(reply, writes, 0, std::make_shared<WriteVerification>());
    return reply;
}

void ShuokeDrive::writeNext(DriveReply *reply, QList<ParameterWrite> writes, int at,
                            std::shared_ptr<WriteVerification> verification)
{
    if (at >= writes.size()) {
        reply->finish(verification->summary());
        return;
    }
    const ParameterWrite w = writes.at(at);
    const ShuokeParameter p = *ShuokeParameter::byIndex(w.index);
    WriteVerification::Check check;
    check.index = w.index;
    check.requested = w.value;
    check.label = QString::fromLatin1(p.key);
    check.readable = p.isReadable();
    auto next = [this, reply, writes, at, verification](const WriteVerification::Check &check) {
        reply->addWriteResult(verification->add(check));
        reply->reportProgress(at + 1, static_cast<int>(writes.size()));
        writeNext(reply, writes, at + 1, verification);
    };
    // Reads the value back into `check`, then goes on with the next write.
    auto readBack = [this, reply, p, next](WriteVerification::Check check) {
        readOneParameter(reply, p, [check, next](const Error &e, qint64 value) mutable {
            if (e)
                check.readError = e;
            else
                check.readBack = value;
            next(check);
        });
    };
    exchange(reply, p.setCommand, p.encode(w.value, byteOrder()),
             [this, reply, w, p, check, next, readBack](const Error &e, const Frame &) mutable {
                 check.writeError = e;
                 if (e) {
                     // The answer was lost or damaged; the write may have been carried out: the
                     // read-back tells. A refusal or a closed link leaves nothing to read back.
                     if (e.code != ErrorCode::DriveException && p.isReadable() && e.code != ErrorCode::LinkClosed)
                         readBack(check);
                     else
                         next(check);
                     return;
                 }
                 m_lastWritten.insert(w.index, w.value);
                 if (!p.isReadable()) {
                     next(check);
                     return;
                 }
                 if (p.setCommand == CmdSetBaudCode && m_transport && m_transport->baud() > 0) {
                     // The drive answers at the old rate, then switches (seed: "change the current baud rate").
                     const int baud = baudRateForCode(static_cast<int>(w.value));
                     if (!m_transport->setBaud(baud))
                         reply->setInfo(QStringLiteral("baudSwitchFailed"), baud);
                     else
                         reply->setInfo(QStringLiteral("linkBaud"), baud);
                 }
                 readBack(check);
             });
}

} // namespace dd
