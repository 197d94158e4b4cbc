#pragma once

#include "core/common/error.h"
#include "core/report/driverecord.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QLocale>
#include <QObject>

namespace dd {

class Drive;
class DriveReply;
class VerificationJournal;
struct ConnectionSettings;

// Reads what a commissioning record says about one drive from the drive itself: its
// identity, every readable parameter (compared with the dictionary's defaults) and the
// alarm it reports; adds what the verification journal knows (the last restore or write,
// the backup files). collect() returns at once; finished() follows once. A drive that does
// not identify itself finishes with that error; a failed parameter or alarm read is noted
// in the record (DriveRecord::readError) and is not an error. Lives in the drive's thread.
class RecordCollector : public QObject
{
    Q_OBJECT
public:
    explicit RecordCollector(const QLocale &locale, QObject *parent = nullptr);

    // The journal to read, with what the journal key takes besides the drive's identity:
    // the link's name (JournalKey::link) and the engineer's machine name.
    void setJournal(const VerificationJournal *journal, const QString &link, const QString &machine)
    {
        m_journal = journal;
        m_journalLink = link;
        m_machine = machine;
    }
    void collect(Drive *drive, const QJsonObject &linkSettings);
    const DriveRecord &record() const { return m_record; }

    // A link's settings as the record (and a backup file) shows them: port and baud or CAN
    // interface and bitrate, and the framing.
    static QJsonObject linkSettingsJson(const ConnectionSettings &settings);

signals:
    void finished(const dd::Error &error);
    void operationFailed(const dd::Error &error); // a read the record had to do without

private:
    void onIdentity(DriveReply *reply);
    void onParameters(DriveReply *reply);
    void onAlarm(DriveReply *reply);
    void done(const Error &error);

    QLocale m_locale;
    const VerificationJournal *m_journal = nullptr;
    QString m_journalLink;
    QString m_machine;
    Drive *m_drive = nullptr;
    DriveRecord m_record;
};

} // namespace dd
