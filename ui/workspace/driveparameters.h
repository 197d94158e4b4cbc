#pragma once

#include "core/drive/drivetypes.h"
#include "core/params/parameterset.h"

#include <QMap>
#include <QObject>
#include <QSet>

namespace dd {

// What DriveDesk knows of one drive's parameter values, shared by every view of that drive
// (one object per drive, made by the workspace and handed to the panels in DriveContext):
// whoever reads or writes parameters (the Parameters tab, a restore, an EE operation)
// reports it here, and every view follows the signals — no view keeps values of its own
// that another panel's write could leave stale.
//
// It also keeps, for families whose writes go to working memory only (servo-modbus: until
// EE-Set), which parameters were written since the last save to EEPROM.
class DriveParameters : public QObject
{
    Q_OBJECT
public:
    explicit DriveParameters(bool writesNeedSave = false, QObject *parent = nullptr);

    // Values read from the drive (or, for write-only ones, the values it last took).
    void reportRead(const QMap<int, qint64> &values, ValueSource source = ValueSource::ReadFromDrive);
    // The outcome of writes by `origin` (the panel that wrote; nullptr: another workflow).
    void reportWrites(const QList<ParameterWriteResult> &results, QObject *origin);
    // The drive now works with other values nobody has read yet (EE-rd, EE-rS, EE-dEF);
    // `savedToEeprom`: its working values equal the EEPROM's afterwards.
    void reportValuesReplaced(bool savedToEeprom);
    // EE-Set: the working values are in the EEPROM now.
    void reportSaved();

    ParameterValue value(int index) const { return m_values.value(index); }
    QMap<int, ParameterValue> values() const { return m_values; }
    // Written since the last EE-Set (empty for families whose writes are permanent).
    bool writesNeedSave() const { return m_writesNeedSave; }
    bool isUnsaved(int index) const { return m_unsaved.contains(index); }
    QSet<int> unsaved() const { return m_unsaved; }
    bool isStale() const { return m_stale; }

signals:
    void valuesRead(const QMap<int, qint64> &values, dd::ValueSource source);
    void writesReported(const QList<dd::ParameterWriteResult> &results, QObject *origin);
    // Every value may have changed: read again.
    void valuesReplaced();
    void unsavedChanged();

private:
    QMap<int, ParameterValue> m_values;
    QSet<int> m_unsaved;
    bool m_writesNeedSave = false;
    bool m_stale = false;
};

} // namespace dd
