#pragma once

#include <QDateTime>
#include <QString>

namespace dd {

// One alarm in a commissioning record: the GUI's alarm history of the session, or the alarm
// the drive reported when the record was made.
struct RecordAlarm
{
    QDateTime when;
    int code = 0;
    QString text;   // the alarm dictionary's text in the record's language
    QString source; // "drive" (read when the record was made), "session" (seen while connected)
    bool cleared = false;
};

} // namespace dd
