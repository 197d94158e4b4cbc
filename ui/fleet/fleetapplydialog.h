#pragma once

#include "core/common/error.h"
#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"

#include <QDialog>
#include <QMap>

class QCheckBox;
class QLabel;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace dd {

class DriveDirectory;

// Apply one set of parameters to several drives of a link: a backup file ("Apply
// backup…") or the values of one drive ("Copy parameters from drive N…"). First the plan:
// every target is read and compared (nothing written), and the dialog lists per drive the
// parameters that will change; communication settings (address, baud rate, station number)
// are left alone and said so. Apply then writes, per drive, only the differences, reads each
// back and reports per drive: verified, failed (with what was written and what not) or not
// attempted. "Stop at the first failed drive" runs the drives one after the other; without
// it they run together. A drive that is enabled or moving is written only after the user
// confirms, since its behaviour changes while it is energised.
class FleetApplyDialog : public QDialog
{
    Q_OBJECT
public:
    enum class DriveState { Planning, Planned, PlanFailed, Writing, Verified, Failed, NotAttempted };

    FleetApplyDialog(DriveDirectory *directory, int connectionId, const QList<int> &targets, QWidget *parent = nullptr);
    ~FleetApplyDialog() override;

    // The source; the plan starts at once.
    // `path`: the file's path, for the verification journal (ui/report/guijournal.h).
    void setSourceFile(const BackupFile &file, const QString &name, const QString &path = QString());
    void setSourceDrive(int address); // reads it, then plans

    bool isPlanned() const;
    DriveState state(int address) const { return m_states.value(address); }
    QList<int> planned(int address) const; // indices that will change
    RestoreReport report(int address) const { return m_reports.value(address); }
    // The drives that need the confirmation (enabled or moving), ascending.
    QList<int> energisedTargets() const;
    QCheckBox *confirmBox() const { return m_confirm; }
    QCheckBox *stopAtFirstFailureBox() const { return m_stopAtFirst; }
    QPushButton *applyButton() const { return m_apply; }
    QTreeWidget *tree() const { return m_tree; }
    QString message() const;

public slots:
    void apply();

signals:
    void planReady();
    void applied();

protected:
    void changeEvent(QEvent *event) override;

private:
    void plan();
    void onPlanned(int address, const Error &error, const RestoreReport &report);
    void startWrite(int address);
    void onWritten(int address, const Error &error, const RestoreReport &report);
    void startNext();
    void finishIfDone();
    void updateItem(int address);
    void updateButtons();
    void retranslate();

    DriveDirectory *m_directory = nullptr;
    int m_connectionId = 0;
    QList<int> m_targets;
    BackupFile m_file;
    QString m_sourceName;
    QString m_sourcePath;   // the source file's path; empty when the source is a drive
    QString m_journalError; // the last verification journal that could not be written
    bool m_hasSource = false;
    bool m_applying = false;
    bool m_done = false;
    bool m_stopping = false;
    QMap<int, DriveState> m_states;
    QMap<int, RestoreReport> m_plans;
    QMap<int, RestoreReport> m_reports;
    QMap<int, Error> m_errors;
    QList<int> m_queue; // sequential apply: the drives still to write
    QLabel *m_source = nullptr;
    QLabel *m_message = nullptr;
    QTreeWidget *m_tree = nullptr;
    QCheckBox *m_stopAtFirst = nullptr;
    QCheckBox *m_confirm = nullptr;
    QPushButton *m_apply = nullptr;
    QPushButton *m_close = nullptr;
};

} // namespace dd
