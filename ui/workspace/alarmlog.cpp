#include "ui/workspace/alarmlog.h"

namespace dd {

AlarmLog::AlarmLog(QObject *parent)
    : QObject(parent)
{
}

void AlarmLog::record(int code)
{
    if (code == m_code || code < 0)
        return;
    if (m_code >= 0 || code != 0)
        m_entries.append({QDateTime::currentDateTime(), code});
    m_code = code;
    emit changed();
}

void AlarmLog::clearHistory()
{
    if (m_entries.isEmpty())
        return;
    m_entries.clear();
    emit changed();
}

} // namespace dd
