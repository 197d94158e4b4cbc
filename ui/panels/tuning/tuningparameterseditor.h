#pragma once

#include "core/drive/drivetypes.h"
#include "core/params/tuningentry.h"
#include "core/tuning/tuningrun.h"
#include "ui/workspace/drivecontext.h"

#include <QMap>
#include <QWidget>
#include <memory>

class QLabel;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;

namespace dd {

class ParameterDictionary;

// The drive's tuning parameters (its dictionary's "tuning" group) beside the capture plot,
// editable: values come from and go to the drive's shared DriveParameters, so the
// Parameters tab shows what is written here and this table what is written there. "Write"
// validates every edited value against the drive's dictionary first (nothing is sent when
// one is wrong), writes them, reads them back and reports the outcome to DriveParameters.
//
// A dictionary without a tuning group (the bundled family dictionaries: the protocol
// documents name no gains) falls back to the DriveDesk simulator's gain parameters, with a
// visible note that they are the simulator's model.
class TuningParametersEditor : public QWidget
{
    Q_OBJECT
public:
    TuningParametersEditor(const DriveContext &context, QWidget *parent = nullptr);

    // The drive's dictionary (read on the I/O thread by the panel).
    void setDictionary(std::shared_ptr<const ParameterDictionary> dictionary);
    const QVector<TuningEntry> &entries() const { return m_entries; }
    QString keyOf(int index) const;
    // The value DriveParameters knows (read or verified), if any.
    std::optional<qint64> knownValue(int index) const;
    // An edited value waiting for Write.
    Error setEdited(int index, qint64 value);
    bool hasEdits() const { return !m_edited.isEmpty(); }

    // The entries a dictionary gives (its tuning group, else the simulator's gains that it
    // has; *simulator tells which).
    static QVector<TuningEntry> entriesFor(const ParameterDictionary &dictionary, Family family,
                                           bool *simulator = nullptr);

    void readValues();
    // "Apply this run's parameters": reads the drive's values, writes only those that
    // differ from the snapshot, reads them back and says what it did.
    void applySnapshot(const QList<TuningSnapshotEntry> &snapshot, const QString &runLabel);
    // applySnapshot() of a run that RunParameterApply::check() accepts against the drive's
    // dictionary and the tuning roles this tab shows (entries()): only tuning parameters;
    // anything else refuses the whole run, by name, with nothing sent.
    // Writes the run's tuning parameters to the drive, after the checks apply-run makes
    // (RunParameterApply::check and ::checkDrive: family, model, tuning roles only).
    void applyRun(const TuningRun &run, const DriveIdentity &drive);
    void writeEdited();
    bool isBusy() const { return m_busy; }
    QString message() const;
    bool usesSimulatorGains() const { return m_simulatorFallback; }
    QTableWidget *table() const { return m_table; }

signals:
    void busyChanged(bool busy);
    void errorOccurred(const dd::Error &error);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void rebuildRows();
    void refreshValues();
    void onItemChanged(QTableWidgetItem *item);
    void setBusy(bool busy);
    void setMessage(std::function<QString()> text, bool problem);
    void writeValues(const QList<ParameterWrite> &writes, const QString &runLabel, int alreadyEqual);

    DriveContext m_context;
    std::shared_ptr<const ParameterDictionary> m_dictionary; // validates writes
    const ParameterDictionary *m_names = nullptr;            // names the rows
    QVector<TuningEntry> m_entries;
    QMap<int, qint64> m_edited;
    bool m_simulatorFallback = false;
    bool m_busy = false;
    bool m_filling = false;
    QTableWidget *m_table = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_write = nullptr;
    QLabel *m_note = nullptr;
    QLabel *m_message = nullptr;
};

} // namespace dd
