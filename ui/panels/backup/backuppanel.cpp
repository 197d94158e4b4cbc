#include "ui/panels/backup/backuppanel.h"

#include "core/drive/drivehub.h"
#include "core/fleet/defaultvalues.h"
#include "core/params/parameterdictionary.h"
#include "core/report/verificationjournal.h"
#include "ui/panels/backup/backupdifftable.h"
#include "ui/panels/backup/restorereportdialog.h"
#include "ui/panels/backup/transferoperation.h"
#include "ui/report/guijournal.h"
#include "ui/workspace/driveparameters.h"

#include <QCheckBox>
#include <QDate>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>

namespace dd {

BackupPanel::BackupPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
{
    m_dictionary = std::shared_ptr<const ParameterDictionary>(&ParameterDictionary::bundled(context.family),
                                                              [](const ParameterDictionary *) {});

    // Made in this order, which is the Tab order.
    buildSaveBox();
    buildRestoreBox();
    m_progress = createProgressBar(this);
    m_message = createMessageLabel(this, QStringLiteral("backupMessage"));
    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_progress);
    bottom->addWidget(m_message, 1);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_saveBox);
    layout->addWidget(m_restoreBox, 1);
    layout->addLayout(bottom);

    retranslate();
}

void BackupPanel::buildSaveBox()
{
    m_saveBox = new QGroupBox(this);
    m_saveHint = new QLabel(m_saveBox);
    m_saveHint->setWordWrap(true);
    m_save = new QPushButton(m_saveBox);
    m_save->setObjectName(QStringLiteral("saveBackupButton"));
    connect(m_save, &QPushButton::clicked, this, &BackupPanel::chooseSaveFile);
    m_saveChangedOnly = new QCheckBox(m_saveBox);
    m_saveChangedOnly->setObjectName(QStringLiteral("saveChangedOnlyCheck"));
    auto *saveLayout = new QHBoxLayout(m_saveBox);
    auto *saveText = new QVBoxLayout;
    saveText->addWidget(m_saveHint);
    saveText->addWidget(m_saveChangedOnly);
    saveLayout->addLayout(saveText, 1);
    saveLayout->addWidget(m_save);
}

void BackupPanel::buildRestoreBox()
{
    m_restoreBox = new QGroupBox(this);
    m_open = new QPushButton(m_restoreBox);
    m_open->setObjectName(QStringLiteral("openBackupButton"));
    connect(m_open, &QPushButton::clicked, this, &BackupPanel::chooseOpenFile);
    m_fileInfo = new QLabel(m_restoreBox);
    m_fileInfo->setObjectName(QStringLiteral("backupFileInfo"));
    m_fileInfo->setWordWrap(true);
    m_fileInfo->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_diffTable = new BackupDiffTable(m_restoreBox);
    m_showIdentical = new QCheckBox(m_restoreBox);
    connect(m_showIdentical, &QCheckBox::toggled, m_diffTable, &BackupDiffTable::setShowIdentical);
    m_selectAll = new QPushButton(m_restoreBox);
    m_selectNone = new QPushButton(m_restoreBox);
    connect(m_selectAll, &QPushButton::clicked, m_diffTable, [this] { m_diffTable->setAllChecked(true); });
    connect(m_selectNone, &QPushButton::clicked, m_diffTable, [this] { m_diffTable->setAllChecked(false); });
    m_apply = new QPushButton(m_restoreBox);
    m_apply->setObjectName(QStringLiteral("applyBackupButton"));
    connect(m_apply, &QPushButton::clicked, this, &BackupPanel::applySelected);
    m_selection = new QLabel(m_restoreBox);
    connect(m_diffTable, &BackupDiffTable::checkedChanged, this, &BackupPanel::updateActions);

    auto *fileRow = new QHBoxLayout;
    fileRow->addWidget(m_open);
    fileRow->addWidget(m_fileInfo, 1);
    auto *applyRow = new QHBoxLayout;
    applyRow->addWidget(m_showIdentical);
    applyRow->addStretch(1);
    applyRow->addWidget(m_selection);
    applyRow->addWidget(m_selectAll);
    applyRow->addWidget(m_selectNone);
    applyRow->addWidget(m_apply);
    auto *restoreLayout = new QVBoxLayout(m_restoreBox);
    restoreLayout->addLayout(fileRow);
    restoreLayout->addWidget(m_diffTable, 1);
    restoreLayout->addLayout(applyRow);
}

BackupPanel::~BackupPanel() = default;

QString BackupPanel::title() const
{
    return tr("Backup");
}

QString BackupPanel::message() const
{
    return m_message->text();
}

RestoreReportDialog *BackupPanel::reportDialog() const
{
    return m_reportDialog;
}

bool BackupPanel::looksLikeBackup(const QString &path)
{
    QFile f(path);
    const bool jsonName = path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive);
    if (f.size() > BackupFile::MaxFileSize || !f.open(QIODevice::ReadOnly))
        return jsonName; // let the loader say why it cannot be read
    const QJsonDocument doc = QJsonDocument::fromJson(f.readAll());
    if (!doc.isObject())
        return jsonName;
    const QJsonValue format = doc.object().value(QLatin1String("format"));
    return format.toString() == BackupFile::formatName() || (jsonName && format.isUndefined());
}

// ---- Save ----

QString BackupPanel::defaultFileName() const
{
    const QString dir = m_path.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                                         : QFileInfo(m_path).absolutePath();
    const QString name = QStringLiteral("%1-%2-%3.json")
                             .arg(familyId(context().family))
                             .arg(context().address)
                             .arg(QDate::currentDate().toString(QStringLiteral("yyyyMMdd")));
    return QDir(dir).filePath(name);
}

void BackupPanel::chooseSaveFile()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save backup"), defaultFileName(),
                                                      tr("DriveDesk backups (*.json)"));
    if (!path.isEmpty())
        saveBackup(path);
}

void BackupPanel::saveBackup(const QString &path)
{
    if (m_busy || !context().isValid())
        return;
    auto out = std::make_shared<TransferOutcome>();
    setBusy(true, [] { return tr("Reading the drive's parameters…"); });
    QPointer<BackupPanel> self(this);
    run(TransferOperation::backup(out), [self, out, path](const DriveResult &r) {
        if (self)
            self->onBackedUp(r, *out, path);
    });
}

void BackupPanel::onBackedUp(const DriveResult &result, const TransferOutcome &outcome, const QString &path)
{
    setBusy(false);
    if (!result.ok())
        return fail(result.error, [] { return tr("No backup was saved:"); });
    BackupFile backup = outcome.backup;
    if (m_saveChangedOnly->isChecked()) { // as backup --changed-only (docs/backup-format.md)
        backup.setValues(DefaultValues::changedOnly(*outcome.dictionary, backup.values()));
        backup.setChangedOnly(true);
    }
    if (Error e = backup.save(path, *outcome.dictionary))
        return fail(e, [] { return tr("No backup was saved:"); });
    // For the commissioning record (ui/report/guijournal.h).
    const Error journal = GuiJournal::backup(context(), result.identity, QStringLiteral("backup"), path,
                                             BackupFile::checksum(backup.values()));
    setMessage(
        [n = int(backup.values().size()), path, journal = journal.message] {
            return (tr("Saved %n parameter(s) to %1.", nullptr, n).arg(QDir::toNativeSeparators(path))
                    + QLatin1Char(' ') + journal)
                .trimmed();
        },
        journal ? MessageKind::Problem : MessageKind::Success);
    emit fileUsed(path);
    emit backupSaved(path);
}

// ---- Open and compare ----

void BackupPanel::chooseOpenFile()
{
    const QString dir = m_path.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                                         : QFileInfo(m_path).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open backup"), dir,
                                                      tr("DriveDesk backups (*.json);;All files (*)"));
    if (!path.isEmpty())
        loadFile(path);
}

bool BackupPanel::openFile(const QString &path)
{
    if (!looksLikeBackup(path))
        return false;
    loadFile(path);
    return true;
}

void BackupPanel::loadFile(const QString &path)
{
    if (m_busy) {
        setMessage(
            [path] {
                return tr("Wait until the drive has answered, then open %1 again.").arg(QDir::toNativeSeparators(path));
            },
            MessageKind::Info);
        return;
    }
    BackupFile file;
    Error e = file.load(path);
    if (!e)
        e = file.checkCompatible(context().family, QString(), true); // the family only
    m_path = path;
    m_report = RestoreReport();
    if (e) {
        // Nothing is sent: the table is emptied and Apply stays disabled.
        m_file = BackupFile();
        m_loadError = e.message;
        m_diffTable->clearDiff();
        showFileInfo();
        fail(e, [] { return tr("This file cannot be used, nothing was sent to the drive:"); });
        return;
    }
    m_file = file;
    m_loadError.clear();
    showFileInfo();
    emit fileUsed(path);
    compare();
}

void BackupPanel::compare()
{
    if (m_busy || !context().isValid() || m_file.values().isEmpty())
        return;
    auto out = std::make_shared<TransferOutcome>();
    setBusy(true, [] { return tr("Reading the drive to compare it with the file…"); });
    QPointer<BackupPanel> self(this);
    run(TransferOperation::compare(m_file, out), [self, out](const DriveResult &r) {
        if (self)
            self->onCompared(r, *out);
    });
}

void BackupPanel::onCompared(const DriveResult &result, const TransferOutcome &outcome)
{
    setBusy(false);
    if (!result.ok()) {
        m_diffTable->clearDiff();
        return fail(result.error, [] { return tr("The drive could not be compared with the file:"); });
    }
    m_dictionary = outcome.dictionary;
    m_diffTable->setDiff(outcome.diff, *m_dictionary);
    const ParameterDiff &d = outcome.diff;
    setMessage(
        [different = d.count(DiffStatus::Different), writeOnly = d.count(DiffStatus::NotReadable),
         notRead = d.count(DiffStatus::OnlyInFile), same = d.count(DiffStatus::Same)] {
            QStringList parts;
            parts << tr("%n different", nullptr, different);
            if (writeOnly)
                parts << tr("%n write-only (cannot be compared)", nullptr, writeOnly);
            if (notRead)
                parts << tr("%n not read from the drive", nullptr, notRead);
            parts << tr("%n the same", nullptr, same);
            return tr("Compared with the drive: %1.").arg(parts.join(QLatin1String(", ")));
        },
        MessageKind::Info);
    emit compared();
}

// ---- Restore ----

void BackupPanel::applySelected()
{
    if (m_busy || !context().isValid())
        return;
    const QList<int> indices = m_diffTable->checkedIndices();
    if (indices.isEmpty()) {
        setMessage([] { return tr("Tick the parameters to restore first."); }, MessageKind::Info);
        return;
    }
    RestoreOptions options;
    options.only = indices;
    if (!confirmRestore(indices, &options.force)) {
        setMessage([] { return tr("Restore cancelled: nothing was sent to the drive."); }, MessageKind::Info);
        return;
    }
    auto out = std::make_shared<TransferOutcome>();
    setBusy(true, [n = int(indices.size())] { return tr("Restoring %n parameter(s)…", nullptr, n); });
    QPointer<BackupPanel> self(this);
    run(TransferOperation::restore(m_file, options, out), [self, out](const DriveResult &r) {
        if (self)
            self->onRestored(r, *out);
    });
}

bool BackupPanel::confirmRestore(const QList<int> &indices, bool *force)
{
    *force = false;
    const QString driveFirmware = driveInfo().identity.firmware;
    if (Error e = m_file.checkCompatible(context().family, driveFirmware, false)) {
        QMessageBox box(QMessageBox::Warning, tr("Another firmware"),
                        e.message + QLatin1String("\n\n") + tr("Restore the ticked parameters anyway?"),
                        QMessageBox::Yes | QMessageBox::Cancel, this);
        box.setObjectName(QStringLiteral("firmwareConfirmation"));
        box.setDefaultButton(QMessageBox::Cancel);
        if (box.exec() != QMessageBox::Yes)
            return false;
        *force = true;
    }
    // An energised axis: the same question as Apply to several drives (FleetApplyDialog).
    const DriveStatus state = driveInfo().status;
    if (state.enabled || state.running) {
        QMessageBox box(QMessageBox::Warning, tr("Write to an energised drive?"),
                        tr("Drive %1 is %2: a parameter changed while the axis is energised takes effect at once "
                           "and can make it jerk or move.\n\nRestore the ticked parameters anyway?")
                            .arg(context().address)
                            .arg(state.running ? tr("moving") : tr("enabled")),
                        QMessageBox::Yes | QMessageBox::Cancel, this);
        box.setObjectName(QStringLiteral("energisedRestoreConfirmation"));
        box.setDefaultButton(QMessageBox::Cancel);
        if (box.exec() != QMessageBox::Yes)
            return false;
    }
    QStringList communication;
    for (int p : indices)
        if (const DiffEntry *e = m_diffTable->diff().entry(p); e && e->communication)
            communication << m_dictionary->label(p);
    if (communication.isEmpty())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Change communication settings?"),
                    tr("%1 changes how the drive communicates (address, baud rate or framing). After "
                       "the restore DriveDesk may no longer reach the drive with the current connection "
                       "settings: connect again with the new ones.\n\nRestore anyway?")
                        .arg(communication.join(QLatin1String(", "))),
                    QMessageBox::Yes | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("communicationRestoreConfirmation"));
    box.setDefaultButton(QMessageBox::Cancel);
    return box.exec() == QMessageBox::Yes;
}

void BackupPanel::onRestored(const DriveResult &result, const TransferOutcome &outcome)
{
    setBusy(false);
    m_report = outcome.report;
    // For the commissioning record (ui/report/guijournal.h).
    const Error journal = VerificationJournal().recordRestore(GuiJournal::key(context(), result.identity), m_report,
                                                              *m_dictionary, m_path,
                                                              BackupFile::checksum(m_file.values()));
    if (m_report.selected.isEmpty() || m_report.results.isEmpty()) {
        if (!result.ok())
            return fail(result.error, [] { return tr("Nothing was restored:"); });
    }
    if (m_reportDialog)
        m_reportDialog->close();
    m_reportDialog = new RestoreReportDialog(m_report, *m_dictionary, QFileInfo(m_path).fileName(), this);
    m_reportDialog->setAttribute(Qt::WA_DeleteOnClose);
    m_reportDialog->open();
    const bool complete = m_report.isComplete();
    // Every view of the drive's parameters shows what the restore wrote.
    parameters()->reportWrites(m_report.results, this);
    setMessage(
        [report = m_report, journal = journal.message] {
            return (RestoreReportDialog::summaryOf(report) + QLatin1Char(' ') + journal).trimmed();
        },
        complete && !journal ? MessageKind::Success : MessageKind::Problem);
    if (!result.ok())
        reportError(result.error);
    emit restored(complete);
    compare(); // show what is left to restore
}

// ---- Common ----

void BackupPanel::run(std::function<DriveReply *(Drive &)> op, std::function<void(const DriveResult &)> done)
{
    context().hub->run(context().connectionId, context().address, std::move(op), std::move(done),
                       progressOn(m_progress));
}

void BackupPanel::fail(const Error &error, const Text &context)
{
    setMessage([context, message = error.message] { return context() + QLatin1Char(' ') + message; },
               MessageKind::Problem);
    reportError(error);
    emit operationFailed(error);
}

void BackupPanel::setBusy(bool busy, const Text &what)
{
    m_busy = busy;
    m_progress->setVisible(busy);
    m_progress->setRange(0, 0);
    if (busy)
        setMessage(what, MessageKind::Info);
    updateActions();
}

void BackupPanel::setMessage(const Text &text, MessageKind kind)
{
    showMessage(m_message, text, kind);
}

void BackupPanel::updateActions()
{
    const bool canRead = context().can(Capability::ReadParameters);
    const bool canWrite = context().can(Capability::WriteParameters);
    const int checked = int(m_diffTable->checkedIndices().size());
    m_save->setEnabled(!m_busy && canRead);
    m_save->setToolTip(canRead ? QString() : driveInfo().reason(Capability::ReadParameters));
    m_open->setEnabled(!m_busy && canRead);
    m_apply->setEnabled(!m_busy && canWrite && checked > 0);
    m_apply->setToolTip(canWrite ? tr("Write the ticked values from the file; the drive reads each back")
                                 : driveInfo().reason(Capability::WriteParameters));
    m_selectAll->setEnabled(!m_busy && !m_diffTable->checkableIndices().isEmpty());
    m_selectNone->setEnabled(m_selectAll->isEnabled());
    m_selection->setText(tr("%1 of %2 ticked").arg(checked).arg(m_diffTable->checkableIndices().size()));
}

void BackupPanel::showFileInfo()
{
    if (m_path.isEmpty()) {
        m_fileInfo->setText(tr("No file open."));
        return;
    }
    const QString name = QDir::toNativeSeparators(m_path);
    if (!m_loadError.isEmpty()) {
        m_fileInfo->setText(tr("%1 — cannot be used: %2").arg(name, m_loadError));
        m_fileInfo->setStyleSheet(QStringLiteral("color: #c62828;"));
        return;
    }
    m_fileInfo->setStyleSheet(QString());
    const QString family = m_file.family() ? familyId(*m_file.family()) : QString();
    const QString firmware = m_file.firmware().isEmpty() ? tr("unknown") : m_file.firmware();
    QString text = tr("%1 — %2 drive at address %3, firmware %4, %n value(s), saved %5", nullptr,
                      m_file.values().size())
                       .arg(name, family)
                       .arg(m_file.address())
                       .arg(firmware, QLocale().toString(m_file.created().toLocalTime(), QLocale::ShortFormat));
    const QString driveFirmware = driveInfo().identity.firmware;
    if (!driveFirmware.isEmpty() && m_file.checkCompatible(context().family, driveFirmware, false))
        text += QLatin1Char('\n')
            + tr("The drive has firmware %1: a restore asks for confirmation.").arg(driveFirmware);
    m_fileInfo->setText(text);
}

void BackupPanel::driveInfoChanged(const DriveInfo &)
{
    showFileInfo();
    updateActions();
}

void BackupPanel::retranslate()
{
    m_saveBox->setTitle(tr("Back up"));
    m_saveHint->setText(tr("Read every parameter of the drive and save them to a file, to compare "
                           "or restore them later — to this drive or to its replacement."));
    m_save->setText(tr("Save backup…"));
    m_saveChangedOnly->setText(tr("Only the settings changed from the defaults"));
    m_saveChangedOnly->setToolTip(
        tr("Leaves out the settings equal to the dictionary's default and the read-only values; settings the "
           "dictionary gives no default for are kept. The file says it holds changes only, and restoring it "
           "touches only what it lists."));
    m_restoreBox->setTitle(tr("Compare and restore"));
    m_open->setText(tr("Open backup…"));
    m_showIdentical->setText(tr("Show identical parameters"));
    m_selectAll->setText(tr("Tick all"));
    m_selectNone->setText(tr("Tick none"));
    m_apply->setText(tr("Apply selected"));
    m_diffTable->retranslate();
    showFileInfo();
    updateActions();
}

} // namespace dd
