#pragma once

#include "core/report/commissioningrecord.h"
#include "core/report/recordruns.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QPushButton;
class QVBoxLayout;

namespace dd {

class DriveDirectory;
class RecordGatherer;
class RecordSession;

// File → Commissioning record…: choose the drives and the tuning runs (run files, .ddrun;
// each shown with the drive it was taken on), fill in the header (remembered between sessions), preview the pages, save the PDF
// with its JSON twin next to it (docs/gui.md, docs/record.md).
class RecordDialog : public QDialog
{
    Q_OBJECT
public:
    RecordDialog(DriveDirectory *directory, RecordSession *session, QWidget *parent = nullptr);

    // Reads the chosen drives and shows the first pages.
    void preview();
    // Reads the chosen drives and writes RECORD.pdf and RECORD.json (no file dialog).
    void saveTo(const QString &pdfPath);

    // Adds run files to the record (loaded and checked now: a bad one is not added, the
    // message says why). False when any was refused.
    bool addRunFiles(const QStringList &paths);

    QListWidget *driveList() const { return m_drives; }
    QListWidget *runList() const { return m_runs; }
    QString message() const;
    QString lastSha256() const { return m_sha256; }
    int previewPages() const;

signals:
    void previewShown(int pages);
    void recordSaved(const QString &pdfPath, const QString &jsonPath, const QString &sha256);
    void failed(const QString &message);

protected:
    void changeEvent(QEvent *event) override;
    void done(int result) override;

private:
    enum class Pending { None, Preview, Save };
    void buildUi();
    void retranslate();
    void fillDrives();
    void fitDriveList();
    void loadSettings();
    void saveSettings() const;
    void start(Pending what);
    void onGathered(const QList<DriveRecord> &records, const QStringList &problems);
    void showPreview(const CommissioningRecord &record);
    void write(const CommissioningRecord &record);
    void chooseFileAndSave();
    void chooseRunFiles();
    void removeSelectedRuns();
    void setBusy(bool busy);
    CommissioningRecord recordOf(const QList<DriveRecord> &drives) const;

    DriveDirectory *m_directory;
    RecordSession *m_session;
    RecordGatherer *m_gatherer;
    Pending m_pending = Pending::None;
    QString m_savePath;
    QString m_sha256;

    QLabel *m_drivesLabel = nullptr;
    QListWidget *m_drives = nullptr;
    QLabel *m_runsLabel = nullptr;
    QListWidget *m_runs = nullptr;
    QPushButton *m_addRunsButton = nullptr;
    QPushButton *m_removeRunsButton = nullptr;
    QList<RecordRunFile> m_runFiles; // in the order of m_runs
    QLabel *m_machineLabel = nullptr;
    QLabel *m_customerLabel = nullptr;
    QLabel *m_siteLabel = nullptr;
    QLabel *m_engineerLabel = nullptr;
    QLabel *m_notesLabel = nullptr;
    QLabel *m_pageSizeLabel = nullptr;
    QLineEdit *m_machine = nullptr;
    QLineEdit *m_customer = nullptr;
    QLineEdit *m_site = nullptr;
    QLineEdit *m_engineer = nullptr;
    QPlainTextEdit *m_notes = nullptr;
    QComboBox *m_pageSize = nullptr;
    QLabel *m_message = nullptr;
    QVBoxLayout *m_pagesLayout = nullptr;
    QList<QLabel *> m_pages;
    QPushButton *m_previewButton = nullptr;
    QPushButton *m_saveButton = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace dd
