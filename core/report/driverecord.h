#pragma once

#include "core/common/family.h"
#include "core/report/backupreference.h"
#include "core/report/recordalarm.h"
#include "core/report/recordeeoperation.h"
#include "core/report/recordlinkhealth.h"
#include "core/report/recordparameter.h"
#include "core/report/recordverification.h"
#include "core/report/runrecord.h"

#include <QJsonObject>
#include <QList>
#include <QString>

namespace dd {

class ParameterDictionary;

// Everything a commissioning record says about one drive.
struct DriveRecord
{
    Family family = Family::ServoModbus;
    int address = 0;
    QString firmware;
    QString model;
    QString link;             // "/dev/ttyUSB0 @ 115200"
    QJsonObject linkSettings; // scalar values: port, baud, framing, can, bitrate
    // How the verification journal told this drive from others and what it cannot tell
    // apart (JournalKey::identifiedBy, cannotTellApart); "" when no journal was read.
    QString identification;
    QString journalError;              // the journal could not be read (damaged, ...); "" when it could
    QString readError;                 // why the parameters could not (all) be read; "" when they were
    QList<RecordParameter> parameters; // every parameter of the dictionary, ascending index
    RecordVerification verification;   // the last restore or write; empty when none is known
    RecordEeOperation eeOperation;     // the last EEPROM operation; empty when none is known
    QList<RecordAlarm> alarms;
    RecordLinkHealth linkHealth;
    QList<RunRecord> runs;
    QList<BackupReference> backups;

    QList<RecordParameter> nonDefault() const;
    // Parameters read from the drive for which the dictionary gives no default: they cannot be
    // compared (the bundled dictionaries give few defaults; a user's dictionary may add them).
    int withoutDefault() const;
    // The parameters of `dictionary` with `values` (index -> value) read from the drive, in
    // the language of `locale`.
    void setParameters(const ParameterDictionary &dictionary, const QMap<int, qint64> &values, const QLocale &locale);
};

} // namespace dd
