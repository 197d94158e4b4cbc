#include "ui/workspace/driveparameters.h"

namespace dd {

DriveParameters::DriveParameters(bool writesNeedSave, QObject *parent)
    : QObject(parent)
    , m_writesNeedSave(writesNeedSave)
{
}

void DriveParameters::reportRead(const QMap<int, qint64> &values, ValueSource source)
{
    for (auto it = values.begin(); it != values.end(); ++it)
        m_values.insert(it.key(), {it.value(), source});
    if (source == ValueSource::ReadFromDrive)
        m_stale = false;
    emit valuesRead(values, source);
}

void DriveParameters::reportWrites(const QList<ParameterWriteResult> &results, QObject *origin)
{
    bool unsavedChanged = false;
    for (const ParameterWriteResult &r : results) {
        switch (r.outcome) {
        case WriteOutcome::Verified:
        case WriteOutcome::Mismatch: m_values.insert(r.index, {r.readBack, ValueSource::ReadFromDrive}); break;
        case WriteOutcome::WriteOnly: m_values.insert(r.index, {r.requested, ValueSource::LastWritten}); break;
        case WriteOutcome::ReadBackFailed:
        case WriteOutcome::Unknown: m_values.remove(r.index); break; // what the drive holds is unknown
        case WriteOutcome::NotWritten: break;
        }
        if (m_writesNeedSave && r.written && !m_unsaved.contains(r.index)) {
            m_unsaved.insert(r.index);
            unsavedChanged = true;
        }
    }
    emit writesReported(results, origin);
    if (unsavedChanged)
        emit this->unsavedChanged();
}

void DriveParameters::reportValuesReplaced(bool savedToEeprom)
{
    m_stale = true;
    if (savedToEeprom && !m_unsaved.isEmpty()) {
        m_unsaved.clear();
        emit unsavedChanged();
    }
    emit valuesReplaced();
}

void DriveParameters::reportSaved()
{
    if (m_unsaved.isEmpty())
        return;
    m_unsaved.clear();
    emit unsavedChanged();
}

} // namespace dd
