#include "core/report/recordcollector.h"

#include "core/drive/drive.h"
#include "core/drive/parametertransfer.h"
#include "core/link/connectionsettings.h"
#include "core/params/alarmdictionary.h"
#include "core/params/parameterdictionary.h"
#include "core/report/verificationjournal.h"

namespace dd {

RecordCollector::RecordCollector(const QLocale &locale, QObject *parent)
    : QObject(parent)
    , m_locale(locale)
{
}

QJsonObject RecordCollector::linkSettingsJson(const ConnectionSettings &c)
{
    QJsonObject link;
    if (c.isCan()) {
        link.insert(QStringLiteral("can"), c.can);
        if (c.bitrate)
            link.insert(QStringLiteral("bitrate"), c.bitrate);
    } else if (!c.port.isEmpty()) {
        link.insert(QStringLiteral("port"), c.port);
        if (c.baud)
            link.insert(QStringLiteral("baud"), c.baud);
    }
    if (!c.framing.isEmpty())
        link.insert(QStringLiteral("framing"), c.framing);
    return link;
}

void RecordCollector::collect(Drive *drive, const QJsonObject &linkSettings)
{
    m_drive = drive;
    m_record = DriveRecord();
    m_record.family = drive->family();
    m_record.address = drive->address();
    m_record.linkSettings = linkSettings;
    DriveReply *reply = drive->refreshIdentity();
    connect(reply, &DriveReply::finished, this, [this, reply] {
        reply->deleteLater();
        onIdentity(reply);
    });
}

void RecordCollector::onIdentity(DriveReply *reply)
{
    if (!reply->ok()) {
        emit operationFailed(reply->error());
        return done(reply->error());
    }
    const DriveIdentity id = m_drive->identity();
    m_record.firmware = id.firmware;
    m_record.model = id.model;
    m_record.link = id.link;
    const ParameterDictionary &dictionary = m_drive->parameterDictionary();
    DriveReply *next = m_drive->readParameters(ParameterTransfer::readableIndices(dictionary, id.model));
    connect(next, &DriveReply::finished, this, [this, next] {
        next->deleteLater();
        onParameters(next);
    });
}

void RecordCollector::onParameters(DriveReply *reply)
{
    m_record.setParameters(m_drive->parameterDictionary(), reply->parameters(), m_locale);
    if (!reply->ok()) {
        m_record.readError = reply->error().message;
        emit operationFailed(reply->error());
    }
    if (!m_drive->hasCapability(Capability::ReadAlarm))
        return done({});
    DriveReply *next = m_drive->readAlarm();
    connect(next, &DriveReply::finished, this, [this, next] {
        next->deleteLater();
        onAlarm(next);
    });
}

void RecordCollector::onAlarm(DriveReply *reply)
{
    if (!reply->ok()) {
        emit operationFailed(reply->error());
    } else if (const int code = reply->status().alarmCode) {
        RecordAlarm a;
        a.when = QDateTime::currentDateTimeUtc();
        a.code = code;
        a.text = AlarmDictionary::bundled(m_record.family).text(code, m_locale);
        a.source = QStringLiteral("drive");
        m_record.alarms.append(a);
    }
    done({});
}

void RecordCollector::done(const Error &error)
{
    if (!error && m_journal)
        m_journal->attach(JournalKey::of(m_drive->identity(), m_journalLink, m_machine), &m_record);
    emit finished(error);
}

} // namespace dd
