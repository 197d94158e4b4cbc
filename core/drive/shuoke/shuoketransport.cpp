#include "core/drive/shuoke/shuoketransport.h"
#include "core/protocol/familytraits.h"

#include "core/link/connectionsettings.h"

#include "core/link/linkreply.h"
#include "core/protocol/shuoke/shuokecommands.h"

#include <QCoreApplication>
#include <QPointer>
#include <QTimer>

namespace dd {

ShuokeTransport::ShuokeTransport(const ShuokeOptions &options, QObject *parent)
    : QObject(parent)
    , m_options(options)
{
}

ShuokeTransport::~ShuokeTransport() = default;

bool ShuokeTransport::setBaud(int)
{
    return false;
}

QString ShuokeTransport::cannotCarry(const shuoke::Frame &frame) const
{
    const shuoke::CommandInfo *info = shuoke::commandInfo(frame.command);
    if (!info)
        return QString();
    const bool can = framing() == ShuokeFraming::Can;
    const QString name = QCoreApplication::translate("dd::shuoke", info->name);
    if (can && info->flags.testFlag(shuoke::SerialOnly))
        return tr("\"%1\" is accepted over RS232/RS485 only, not over CAN.").arg(name);
    if (!can && info->flags.testFlag(shuoke::CanOnly))
        return tr("\"%1\" is accepted over CAN only.").arg(name);
    return QString();
}

Error ShuokeTransport::translateLinkError(const Error &error, const ShuokeRequest &) const
{
    return error;
}

Error ShuokeTransport::failureError(const shuoke::Frame &reply)
{
    // tr() first: lupdate mistakes a tr() that follows a translate() with a variable text
    // in one expression for QCoreApplication::tr().
    QString why = tr("unknown failure code");
    if (const char *text = shuoke::failureCodeText(reply.failureCode))
        why = QCoreApplication::translate("dd::shuoke", text);
    const shuoke::CommandInfo *info = shuoke::commandInfo(reply.command);
    const QString command = info ? QCoreApplication::translate("dd::shuoke", info->name)
                                 : shuoke::commandName(reply.command);
    Error e{ErrorCode::DriveException,
            tr("The drive at address %1 refused \"%2\" (command 0x%3): %4 (failure code 0x%5).")
                .arg(reply.address)
                .arg(command)
                .arg(reply.command, 2, 16, QLatin1Char('0'))
                .arg(why)
                .arg(reply.failureCode, 2, 16, QLatin1Char('0'))};
    e.driveCode = reply.failureCode;
    return e;
}

void ShuokeTransport::request(const ShuokeRequest &request, QObject *context, Handler handler)
{
    QPointer<QObject> guard(context);
    auto later = [guard, handler](const Error &e) {
        QTimer::singleShot(0, guard.data(), [guard, handler, e] {
            if (guard)
                handler(e, shuoke::Frame());
        });
    };
    const QString refused = cannotCarry(request.frame);
    if (!refused.isEmpty()) {
        later({ErrorCode::NotSupported, refused});
        return;
    }
    Error startError;
    LinkReply *reply = start(request, &startError);
    if (!reply) {
        later(startError.isError() ? startError : Error{ErrorCode::LinkClosed, tr("The link is not open.")});
        return;
    }
    // The caller went away: the link skips or drops the request's reply.
    connect(context, &QObject::destroyed, reply, &QObject::deleteLater);
    connect(reply, &LinkReply::finished, context, [this, reply, request, handler] {
        reply->deleteLater();
        if (reply->error().isError()) {
            handler(translateLinkError(reply->error(), request), shuoke::Frame());
            return;
        }
        if (!request.expectReply) {
            handler(Error::none(), shuoke::Frame());
            return;
        }
        const Decoded<shuoke::Frame> frame = decode(*reply, request);
        if (!frame.ok()) {
            handler({ErrorCode::Malformed, tr("The drive's reply could not be read: %1").arg(frame.error)},
                    shuoke::Frame());
            return;
        }
        if (frame.value->failure) {
            handler(failureError(*frame.value), *frame.value);
            return;
        }
        handler(Error::none(), *frame.value);
    });
}

SerialSettings ShuokeTransport::serialSettings(const ConnectionSettings &settings) const
{
    SerialSettings s;
    s.portName = settings.port;
    s.baud = settings.baud > 0 ? settings.baud : familyTraits(Family::Shuoke).defaultBaud;
    options().applyGap(s.baud, s.bitsPerChar, &s.minGapMs, &s.minCommandSpacingMs);
    s.responseTimeoutMs = settings.timeoutMs >= 0 ? settings.timeoutMs : kDefaultSerialResponseMs;
    if (settings.retries >= 0)
        s.retries = settings.retries;
    return s;
}

} // namespace dd
