// ShuokeDrive: parameter reads and verified writes (see shuokedrive.h).
#include "core/drive/shuoke/shuokedrive.h"
#include "core/drive/shuoke/shuokeparameter.h"

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
            done({ErrorCode::Malformed, tr("The drive answered %1 data bytes for parameter %2 (%3 expected).")
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
        return {ErrorCode::OutOfRange, tr("%1 must be %2..%3; %4 was not sent.")
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
    writeNext(reply, writes, 0, Error::none());
    return reply;
}

void ShuokeDrive::writeNext(DriveReply *reply, QList<ParameterWrite> writes, int at, Error first)
{
    if (at >= writes.size()) {
        reply->finish(first);
        return;
    }
    const ParameterWrite w = writes.at(at);
    const ShuokeParameter p = *ShuokeParameter::byIndex(w.index);
    auto next = [this, reply, writes, at](const ParameterWriteResult &result, const Error &first) {
        reply->addWriteResult(result);
        reply->reportProgress(at + 1, static_cast<int>(writes.size()));
        writeNext(reply, writes, at + 1, first);
    };
    exchange(reply, p.setCommand, p.encode(w.value, byteOrder()),
             [this, reply, w, p, first, next](const Error &e, const Frame &) {
        ParameterWriteResult res;
        res.index = w.index;
        res.requested = w.value;
        res.readable = p.isReadable();
        if (e && e.code != ErrorCode::DriveException && p.isReadable() && e.code != ErrorCode::LinkClosed) {
            // The answer was lost or damaged; the write may have been carried out: the
            // read-back tells.
            readOneParameter(reply, p, [res, e, first, next, w](const Error &e2, qint64 value) mutable {
                if (!e2 && value == w.value) {
                    res.written = true;
                    res.verified = true;
                    res.readBack = value;
                    next(res, first);
                    return;
                }
                res.error = e.message;
                res.readBackFailed = bool(e2);
                if (!e2)
                    res.readBack = value;
                else
                    res.error += QLatin1Char(' ') + tr("Whether the drive took the value is unknown: read it again.");
                next(res, first ? first : e);
            });
            return;
        }
        if (e) {
            res.error = e.message;
            next(res, first ? first : e);
            return;
        }
        res.written = true;
        m_lastWritten.insert(w.index, w.value);
        if (!p.isReadable()) {
            res.error = tr("Not readable: the drive cannot report this setting; %1 is kept as the "
                           "last value written.")
                            .arg(w.value);
            next(res, first);
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
        readOneParameter(reply, p, [this, res, first, next, w](const Error &e2, qint64 value) mutable {
            Error f = first;
            if (e2) {
                res.readBackFailed = true;
                res.error = tr("Written, but reading it back failed: %1").arg(e2.message);
                if (!f)
                    f = e2;
            } else {
                res.readBack = value;
                res.verified = value == w.value;
                if (!res.verified) {
                    res.error = tr("The drive reports %1 after %2 was written.").arg(value).arg(w.value);
                    if (!f)
                        f = {ErrorCode::VerifyMismatch, tr("Parameter %1: %2").arg(w.index).arg(res.error)};
                }
            }
            next(res, f);
        });
    });
}

} // namespace dd
