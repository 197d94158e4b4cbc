#pragma once

#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"
#include "ui/workspace/drivepanel.h"

#include <QPointer>
#include <functional>
#include <memory>

class QCheckBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace dd {

class BackupDiffTable;
class Drive;
class DriveReply;
class ParameterDictionary;
class RestoreReportDialog;
struct TransferOutcome;

// The Backup tab: save the drive's parameters to a file, and restore a file to the drive.
// Both run the shared workflow (ParameterTransfer through TransferOperation):
//   - Save backup…: read every readable parameter, save the file atomically;
//   - Open backup…: load and validate the file (a bad file shows why; nothing is sent),
//     read the drive and list the differences (BackupDiffTable) with a checkbox each;
//   - Apply selected: write the ticked values, each read back by the drive, then show a
//     report (RestoreReportDialog) of what was written and verified, and compare again.
// A firmware other than the file's, and communication settings, are confirmed first.
class BackupPanel : public DrivePanel
{
    Q_OBJECT
public:
    explicit BackupPanel(const DriveContext &context, QWidget *parent = nullptr);
    ~BackupPanel() override;

    QString panelId() const override { return QStringLiteral("backup"); }
    QString title() const override;

    // A backup file (from File → Recent files): load it and compare it with the drive.
    bool openFile(const QString &path) override;
    // Reads the drive and saves its parameters to `path`.
    void saveBackup(const QString &path);
    // Restores the ticked parameters of the open file.
    void applySelected();
    // Compares the open file with the drive again.
    void compare();

    bool isBusy() const { return m_busy; }
    QString message() const;
    QString loadedPath() const { return m_path; }
    const BackupFile &loadedFile() const { return m_file; }
    BackupDiffTable *diffTable() const { return m_diffTable; }
    const RestoreReport &lastReport() const { return m_report; }
    RestoreReportDialog *reportDialog() const; // the last report, while it is open

    // Whether `path` is (or claims to be) a DriveDesk backup: a JSON object with the backup
    // format, or a .json file that cannot be read as another kind of JSON object.
    static bool looksLikeBackup(const QString &path);

signals:
    void backupSaved(const QString &path);
    void compared();
    void restored(bool complete);
    void operationFailed(const dd::Error &error);

protected:
    void retranslate() override;
    void driveInfoChanged(const DriveInfo &info) override;

private:
    void buildSaveBox();
    void buildRestoreBox();
    void chooseSaveFile();
    void chooseOpenFile();
    void loadFile(const QString &path);
    void onBackedUp(const DriveResult &result, const TransferOutcome &outcome, const QString &path);
    void onCompared(const DriveResult &result, const TransferOutcome &outcome);
    void onRestored(const DriveResult &result, const TransferOutcome &outcome);
    // The message lines are made again after a language switch (LiveText); a drive's or a
    // file's own error text stays as it came.
    using Text = std::function<QString()>;
    void fail(const Error &error, const Text &context);
    bool confirmRestore(const QList<int> &indices, bool *force);
    void setBusy(bool busy, const Text &what = {});
    void setMessage(const Text &text, MessageKind kind);
    void updateActions();
    void showFileInfo();
    void run(std::function<DriveReply *(Drive &)> op, std::function<void(const DriveResult &)> done);
    QString defaultFileName() const;

    QGroupBox *m_saveBox = nullptr;
    QGroupBox *m_restoreBox = nullptr;
    QLabel *m_saveHint = nullptr;
    QPushButton *m_save = nullptr;
    QCheckBox *m_saveChangedOnly = nullptr; // save only the settings changed from the defaults
    QPushButton *m_open = nullptr;
    QLabel *m_fileInfo = nullptr;
    BackupDiffTable *m_diffTable = nullptr;
    QCheckBox *m_showIdentical = nullptr;
    QPushButton *m_selectAll = nullptr;
    QPushButton *m_selectNone = nullptr;
    QPushButton *m_apply = nullptr;
    QLabel *m_selection = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_message = nullptr;
    QPointer<RestoreReportDialog> m_reportDialog;

    std::shared_ptr<const ParameterDictionary> m_dictionary;
    BackupFile m_file;
    QString m_path;
    QString m_loadError;
    RestoreReport m_report;
    bool m_busy = false;
};

} // namespace dd
