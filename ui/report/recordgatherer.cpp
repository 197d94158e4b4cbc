#include "ui/report/recordgatherer.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/parametertransfer.h"
#include "core/params/alarmdictionary.h"
#include "core/params/parameterdictionary.h"
#include "core/protocol/familytraits.h"
#include "core/report/recordcollector.h"
#include "core/report/verificationjournal.h"
#include "ui/bus/drivedirectory.h"
#include "ui/report/guijournal.h"
#include "ui/report/recordsession.h"

namespace dd {

RecordGatherer::RecordGatherer(DriveDirectory *directory, RecordSession *session, QObject *parent)
    : QObject(parent)
    , m_directory(directory)
    , m_session(session)
{
}

void RecordGatherer::gather(const QList<QPair<int, int>> &drives)
{
    m_pending = drives;
    m_records.clear();
    m_problems.clear();
    m_total = int(drives.size());
    m_busy = true;
    next();
}

void RecordGatherer::next()
{
    emit progress(m_total - int(m_pending.size()), m_total);
    if (m_pending.isEmpty()) {
        m_busy = false;
        emit finished(m_records, m_problems);
        return;
    }
    const QPair<int, int> drive = m_pending.takeFirst();
    const DriveInfo info = m_directory->info(drive.first, drive.second);
    DriveRecord record;
    record.family = info.identity.family;
    record.address = drive.second;
    record.firmware = info.identity.firmware;
    record.model = info.identity.model;
    record.link = info.identity.link;
    record.linkSettings = RecordCollector::linkSettingsJson(m_directory->connectionSettings(drive.first));
    if (record.link.isEmpty())
        record.link = m_directory->connectionSettings(drive.first).linkName();

    m_directory->hub()->run(
        drive.first, drive.second,
        [](Drive &d) {
            return d.readParameters(ParameterTransfer::readableIndices(d.parameterDictionary(), d.identity().model));
        },
        [this, drive, record](const DriveResult &result) mutable {
            if (!result.ok() && result.parameters.isEmpty()) {
                m_session->countError(drive.first, drive.second);
                m_problems << tr("%1 at address %2: %3")
                                  .arg(familyTraits(record.family).displayName())
                                  .arg(drive.second)
                                  .arg(result.error.message);
                return next();
            }
            record.setParameters(ParameterDictionary::bundled(record.family), result.parameters, QLocale());
            if (!result.ok()) {
                m_session->countError(drive.first, drive.second);
                record.readError = result.error.message;
            }
            readAlarm(drive, record);
        });
}

void RecordGatherer::readAlarm(const QPair<int, int> &drive, DriveRecord record)
{
    record.alarms = m_session->alarms(drive.first, drive.second);
    record.linkHealth = m_session->linkHealth(drive.first, drive.second);
    if (!m_directory->info(drive.first, drive.second).capabilities.testFlag(Capability::ReadAlarm))
        return done(drive, record);
    m_directory->hub()->run(
        drive.first, drive.second, [](Drive &d) { return d.readAlarm(); },
        [this, drive, record](const DriveResult &result) mutable {
            if (!result.ok())
                m_session->countError(drive.first, drive.second);
            else if (const int code = result.status.alarmCode) {
                const bool known = !record.alarms.isEmpty() && record.alarms.last().code == code
                    && !record.alarms.last().cleared;
                if (!known) {
                    RecordAlarm a;
                    a.when = QDateTime::currentDateTimeUtc();
                    a.code = code;
                    a.text = AlarmDictionary::bundled(record.family).text(code);
                    a.source = QStringLiteral("drive");
                    record.alarms.append(a);
                }
            }
            done(drive, record);
        });
}

void RecordGatherer::done(const QPair<int, int> &drive, const DriveRecord &record)
{
    DriveRecord r = record;
    const DriveInfo info = m_directory->info(drive.first, drive.second);
    VerificationJournal().attach(GuiJournal::key(m_directory->hub(), drive.first, drive.second, info.identity), &r);
    m_records.append(r);
    next();
}

} // namespace dd
