// ShuokeDrive: monitor channels (see shuokedrive.h).
#include "core/drive/shuoke/shuokedrive.h"

#include "core/link/seriallink.h"

#include "core/drive/shuoke/shuokecantransport.h"
#include "core/link/wiretime.h"
#include "core/protocol/shuoke/shuokevalues.h"

#include <QCoreApplication>
#include <QDateTime>
#include <algorithm>
#include <memory>

namespace dd {

using namespace shuoke;

namespace {

struct ShuokeChannelDef
{
    const char *id;
    const char *name; // translated in context dd::ShuokeDrive
    const char *unit;
    quint8 command;
    quint8 command2; // second command of a derived channel; 0 none
};

const ShuokeChannelDef kChannels[] = {
    {"speed", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Speed"), "pulse/s", CmdQuerySpeed, 0},
    {"position", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Absolute position"), "pulse", CmdQueryAbsolutePosition, 0},
    {"relative-position", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Relative position"), "pulse", CmdQueryRelativePosition,
     0},
    {"status", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Status bits (running, left limit, origin, right limit, enable)"),
     "", CmdQueryStatus, 0},
    {"inputs", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Inputs IO1..IO5"), "", CmdReadInputs, 0},
    {"control-inputs", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Inputs pulse, direction, enable, F1, F2"), "",
     CmdReadOtherInputs, 0},
    {"closed-loop-position", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Closed-loop absolute position"), "pulse",
     CmdClosedLoopGetAbsolute, 0},
    {"closed-loop-relative-position", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Closed-loop relative position"), "pulse",
     CmdClosedLoopGetRelative, 0},
    {"position-error", QT_TRANSLATE_NOOP("dd::ShuokeDrive", "Position error (commanded - feedback)"), "pulse",
     CmdQueryAbsolutePosition, CmdClosedLoopGetAbsolute},
};

const ShuokeChannelDef *shuokeChannelDef(const QString &id)
{
    for (const ShuokeChannelDef &c : kChannels)
        if (id == QLatin1String(c.id))
            return &c;
    return nullptr;
}

} // namespace

bool ShuokeDrive::channelAvailable(const QString &id) const
{
    const ShuokeChannelDef *c = shuokeChannelDef(id);
    if (!c)
        return false;
    if (!commandUnavailable(c->command, 0).isEmpty())
        return false;
    return c->command2 == 0 || commandUnavailable(c->command2, 0).isEmpty();
}

QList<ChannelInfo> ShuokeDrive::channels() const
{
    QList<ChannelInfo> out;
    for (const ShuokeChannelDef &c : kChannels) {
        const QString id = QLatin1String(c.id);
        if (!channelAvailable(id))
            continue;
        ChannelInfo info;
        info.id = id;
        info.name = QCoreApplication::translate("dd::ShuokeDrive", c.name);
        info.unit = QString::fromUtf8(c.unit);
        out.append(info);
    }
    return out;
}

QList<quint8> ShuokeDrive::channelCommands(const QStringList &ids) const
{
    QList<quint8> out;
    for (const QString &id : ids) {
        const ShuokeChannelDef *c = shuokeChannelDef(id);
        if (!c)
            continue;
        if (!out.contains(c->command))
            out.append(c->command);
        if (c->command2 && !out.contains(c->command2))
            out.append(c->command2);
    }
    return out;
}

void ShuokeDrive::fillSamples(DriveReply *reply, const QStringList &ids, const QHash<quint8, QByteArray> &data) const
{
    auto intOf = [this, &data](quint8 command) -> std::optional<qint32> {
        const auto it = data.constFind(command);
        return it == data.cend() ? std::nullopt : decodeInt(*it);
    };
    for (const QString &id : ids) {
        const ShuokeChannelDef *c = shuokeChannelDef(id);
        if (!c || !data.contains(c->command) || (c->command2 && !data.contains(c->command2)))
            continue;
        if (c->command == CmdQueryStatus) {
            if (const auto st = decodeMotionStatus(data.value(c->command)))
                reply->setSample(id,
                                 (st->running ? StatusChannelBits::Running : 0)
                                     | (st->leftLimit ? StatusChannelBits::LeftLimit : 0)
                                     | (st->origin ? StatusChannelBits::Origin : 0)
                                     | (st->rightLimit ? StatusChannelBits::RightLimit : 0)
                                     | (st->enableInput ? StatusChannelBits::EnableInput : 0));
        } else if (c->command == CmdReadInputs || c->command == CmdReadOtherInputs) {
            if (const auto bits = decodeInputBits(data.value(c->command)))
                reply->setSample(id, *bits);
        } else if (c->command2) {
            const auto a = intOf(c->command);
            const auto b = intOf(c->command2);
            if (a && b)
                reply->setSample(id, static_cast<double>(qint64(*a) - qint64(*b)));
        } else if (c->command == CmdQuerySpeed) {
            // The drive reports the magnitude; the direction is the one last commanded.
            if (const auto v = intOf(c->command))
                reply->setSample(id, *v > 0 && m_commandedDirection < 0 ? -double(*v) : double(*v));
        } else if (const auto v = intOf(c->command)) {
            reply->setSample(id, *v);
        }
    }
}

double ShuokeDrive::channelReadUs(const QStringList &channelIds) const
{
    if (!m_transport)
        return 0.0;
    QStringList ids = channelIds;
    if (ids.isEmpty())
        for (const ChannelInfo &c : channels())
            ids.append(c.id);
    const double commands = double(std::max<qsizetype>(1, channelCommands(ids).size()));
    if (const auto *can = qobject_cast<const ShuokeCanTransport *>(m_transport.data()))
        return commands * (2.0 * WireTime::canFrameUs(8, false, can->bitrate()) + 200.0);
    // Serial: a query is 5 bytes out and up to 9 back, and the seed's rule leaves
    // minGapMs (50 ms) between commands. The link counts those from the reply's first byte,
    // i.e. the drive's latency (1 ms) after the command, and adds its margin: what a
    // command really takes, so that the trend's default rate is one the link can keep.
    const int baud = m_transport->baud();
    if (baud <= 0)
        return 0.0;
    const double transaction = WireTime::serialBytesUs(14, baud) + 1000.0;
    const double spaced = 1000.0 * m_transport->options().minGapMs + double(SerialLink::CommandSpacingMarginUs)
        + 1000.0;
    return commands * std::max(transaction, spaced);
}

DriveReply *ShuokeDrive::readChannels(const QStringList &channelIds)
{
    QStringList ids = channelIds;
    if (ids.isEmpty())
        for (const ChannelInfo &c : channels())
            ids.append(c.id);
    for (const QString &id : std::as_const(ids)) {
        const ShuokeChannelDef *c = shuokeChannelDef(id);
        if (!c)
            return finishedReply({ErrorCode::InvalidArgument, tr("\"%1\" is not a Shuoke channel.").arg(id)});
        if (!channelAvailable(id)) {
            QString why = commandUnavailable(c->command, 0);
            if (why.isEmpty() && c->command2)
                why = commandUnavailable(c->command2, 0);
            return finishedReply({ErrorCode::NotSupported, why});
        }
    }
    const QList<quint8> commands = channelCommands(ids);
    DriveReply *reply = newReply();
    struct State
    {
        int pending = 0;
        Error first;
        QHash<quint8, QByteArray> data;
    };
    auto state = std::make_shared<State>();
    state->pending = static_cast<int>(commands.size());
    if (commands.isEmpty()) {
        reply->finish();
        return reply;
    }
    for (const quint8 command : commands) {
        exchange(reply, command, {}, [this, reply, state, ids, command](const Error &e, const Frame &f) {
            if (e && !state->first)
                state->first = e;
            if (!e)
                state->data.insert(command, f.data);
            if (--state->pending > 0)
                return;
            reply->setSampleTimeUs(QDateTime::currentMSecsSinceEpoch() * 1000);
            fillSamples(reply, ids, state->data);
            reply->finish(state->first);
        });
    }
    return reply;
}

} // namespace dd
