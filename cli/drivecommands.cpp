#include "cli/drivecommands.h"

#include "cli/clidescribe.h"
#include "cli/clivalues.h"

#include "core/drive/drive.h"
#include "core/params/alarmdictionary.h"

namespace dd {

namespace {

// "12 (Overcurrent: check the motor cable)" from the family's alarm table.
QString alarmText(Family family, int code)
{
    const AlarmDictionary &alarms = AlarmDictionary::bundled(family);
    const QString text = alarms.text(code);
    const QString remedy = alarms.remedy(code);
    QString out = QString::number(code);
    if (!text.isEmpty() && text != out)
        out += QStringLiteral(" (%1)").arg(remedy.isEmpty() ? text : text + QStringLiteral(": ") + remedy);
    return out;
}

} // namespace

// --- info -------------------------------------------------------------------------------

bool InfoCommand::prepare(const CliInvocation &inv, QString *error)
{
    return expectArguments(inv, 0, 0, QString(), error);
}

void InfoCommand::start()
{
    Drive *d = drive();
    onFinished(d->refreshIdentity(), [this, d](DriveReply *r) {
        if (!r->ok())
            return fail(r->error());
        m_warnings = r->info().value(QStringLiteral("warnings")).toStringList();
        onFinished(d->readStatus(), [this, d](DriveReply *r) {
            if (!r->ok())
                return fail(r->error());
            m_status = r->status();
            if (!d->hasCapability(Capability::ReadAlarm))
                return report();
            onFinished(d->readAlarm(), [this](DriveReply *r) {
                if (!r->ok())
                    return fail(r->error());
                m_status.alarmCode = r->status().alarmCode;
                report();
            });
        });
    });
}

void InfoCommand::report()
{
    Drive *d = drive();
    const DriveIdentity id = d->identity();
    const QStringList caps = capabilityIds(d->capabilities());
    QStringList channelIds;
    for (const ChannelInfo &c : d->channels())
        channelIds << c.id;

    QJsonObject status = CliDescribe::status(m_status);
    if (m_status.alarmCode)
        status.insert(QStringLiteral("alarmText"), AlarmDictionary::bundled(id.family).text(m_status.alarmCode));
    QJsonObject json{{QStringLiteral("identity"), CliDescribe::identity(id)},
                     {QStringLiteral("status"), status},
                     {QStringLiteral("capabilities"), QJsonArray::fromStringList(caps)},
                     {QStringLiteral("channels"), CliDescribe::channels(d->channels())},
                     {QStringLiteral("warnings"), QJsonArray::fromStringList(m_warnings)}};
    QList<QPair<QString, QString>> rows{
        {tr("Family"), familyId(id.family)},
        {tr("Address"), QString::number(id.address)},
        {tr("Link"), id.link},
        {tr("Model"), id.model.isEmpty() ? tr("unknown") : id.model},
        {tr("Firmware"), id.firmware.isEmpty() ? tr("not readable") : id.firmware},
        {tr("State"), CliDescribe::statusText(m_status)},
    };
    if (m_status.positionValid)
        rows.append({tr("Position"), QString::number(m_status.position)});
    rows.append({tr("Alarm"), m_status.alarmCode ? alarmText(id.family, m_status.alarmCode) : tr("none")});
    rows.append({tr("Capabilities"), caps.join(QLatin1String(", "))});
    rows.append({tr("Channels"), channelIds.join(QLatin1String(", "))});
    for (const QString &w : std::as_const(m_warnings))
        rows.append({tr("Warning"), w});
    succeed(json, CliDescribe::table(rows));
}

// --- channels ---------------------------------------------------------------------------

bool ChannelsCommand::prepare(const CliInvocation &inv, QString *error)
{
    return expectArguments(inv, 0, 0, QString(), error);
}

void ChannelsCommand::start()
{
    // The model may decide which channels exist (shuoke M6505 vs M4505): ask first, and
    // fall back to the family's list when the drive does not answer.
    onFinished(drive()->refreshIdentity(), [this](DriveReply *r) {
        if (!r->ok())
            out()->note(
                tr("Could not identify the drive (%1); listing the family's channels.").arg(r->error().message));
        const QList<ChannelInfo> channels = drive()->channels();
        QList<QPair<QString, QString>> rows;
        for (const ChannelInfo &c : channels)
            rows.append({c.id, c.unit.isEmpty() ? c.name : QStringLiteral("%1 [%2]").arg(c.name, c.unit)});
        succeed({{QStringLiteral("channels"), CliDescribe::channels(channels)}}, CliDescribe::table(rows));
    });
}

// --- stop -------------------------------------------------------------------------------

bool StopCommand::prepare(const CliInvocation &inv, QString *error)
{
    m_emergency = inv.has(QStringLiteral("emergency"));
    return expectArguments(inv, 0, 0, QString(), error);
}

void StopCommand::start()
{
    onFinished(drive()->stop(m_emergency), [this](DriveReply *r) {
        if (!r->ok())
            return fail(r->error());
        succeed({{QStringLiteral("emergency"), m_emergency}},
                m_emergency ? tr("Emergency stop sent.") : tr("Stopped."));
    });
}

// --- enable -----------------------------------------------------------------------------

bool EnableCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("on or off"), error))
        return false;
    const auto on = CliValues::onOff(inv.positionals.at(0), QStringLiteral("enable"), error);
    if (!on)
        return false;
    m_on = *on;
    return true;
}

void EnableCommand::start()
{
    onFinished(drive()->setEnabled(m_on), [this](DriveReply *r) {
        if (!r->ok())
            return fail(r->error());
        succeed({{QStringLiteral("enabled"), m_on}}, m_on ? tr("Servo enabled.") : tr("Servo disabled."));
    });
}

// --- clear-alarm ------------------------------------------------------------------------

bool ClearAlarmCommand::prepare(const CliInvocation &inv, QString *error)
{
    return expectArguments(inv, 0, 0, QString(), error);
}

void ClearAlarmCommand::start()
{
    Drive *d = drive();
    onFinished(d->clearAlarm(), [this, d](DriveReply *r) {
        if (!r->ok())
            return fail(r->error());
        if (!d->hasCapability(Capability::ReadAlarm))
            return succeed({{QStringLiteral("verified"), false}},
                           tr("Alarm clear sent (this family cannot read the alarm back)."));
        onFinished(d->readAlarm(), [this](DriveReply *r) {
            if (!r->ok())
                return fail(r->error());
            const int code = r->status().alarmCode;
            if (code != 0)
                return fail({ErrorCode::DriveException,
                             tr("Alarm %1 is still active: its cause persists. Remove the cause "
                                "(see the drive's manual), then clear again.")
                                 .arg(alarmText(drive()->family(), code)),
                             code},
                            {{QStringLiteral("alarm"), code}});
            succeed({{QStringLiteral("alarm"), 0}, {QStringLiteral("verified"), true}}, tr("Alarm cleared."));
        });
    });
}

} // namespace dd
