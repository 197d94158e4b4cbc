#include "ui/report/recorddialog.h"

#include "core/protocol/familytraits.h"
#include "core/report/recordfont.h"
#include "core/report/recordjson.h"
#include "core/report/recordrenderer.h"
#include "ui/bus/drivedirectory.h"
#include "ui/report/recordgatherer.h"
#include "ui/report/recordsession.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPixmap>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QVBoxLayout>
#include <algorithm>

namespace dd {

namespace {

constexpr int PreviewDpi = 56;
constexpr int PreviewMaxPages = 6;
const char *SettingsGroup = "commissioningRecord";
constexpr int ConnectionRole = Qt::UserRole;
constexpr int AddressRole = Qt::UserRole + 1;

} // namespace

RecordDialog::RecordDialog(DriveDirectory *directory, RecordSession *session, QWidget *parent)
    : QDialog(parent)
    , m_directory(directory)
    , m_session(session)
    , m_gatherer(new RecordGatherer(directory, session, this))
{
    setObjectName(QStringLiteral("recordDialog"));
    buildUi();
    fillDrives();
    loadSettings();
    retranslate();
    connect(m_gatherer, &RecordGatherer::finished, this, &RecordDialog::onGathered);
    connect(m_gatherer, &RecordGatherer::progress, this, [this](int done, int total) {
        if (done < total)
            m_message->setText(tr("Reading drive %1 of %2 …").arg(done + 1).arg(total));
    });
}

void RecordDialog::buildUi()
{
    m_drivesLabel = new QLabel(this);
    m_drives = new QListWidget(this);
    m_drives->setObjectName(QStringLiteral("recordDrives"));
    m_drives->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_drives->setTextElideMode(Qt::ElideMiddle);
    m_runsLabel = new QLabel(this);
    m_runsLabel->setWordWrap(true);
    m_runs = new QListWidget(this);
    m_runs->setObjectName(QStringLiteral("recordRuns"));
    m_runs->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_runs->setMaximumHeight(80);
    m_addRunsButton = new QPushButton(this);
    m_addRunsButton->setObjectName(QStringLiteral("recordAddRuns"));
    m_removeRunsButton = new QPushButton(this);
    m_removeRunsButton->setObjectName(QStringLiteral("recordRemoveRuns"));
    connect(m_addRunsButton, &QPushButton::clicked, this, &RecordDialog::chooseRunFiles);
    connect(m_removeRunsButton, &QPushButton::clicked, this, &RecordDialog::removeSelectedRuns);
    auto *runButtons = new QHBoxLayout;
    runButtons->addWidget(m_addRunsButton);
    runButtons->addWidget(m_removeRunsButton);
    runButtons->addStretch(1);

    m_machine = new QLineEdit(this);
    m_machine->setObjectName(QStringLiteral("recordMachine"));
    m_customer = new QLineEdit(this);
    m_customer->setObjectName(QStringLiteral("recordCustomer"));
    m_site = new QLineEdit(this);
    m_site->setObjectName(QStringLiteral("recordSite"));
    m_engineer = new QLineEdit(this);
    m_engineer->setObjectName(QStringLiteral("recordEngineer"));
    for (QLineEdit *e : {m_machine, m_customer, m_site, m_engineer})
        e->setMaxLength(RecordHeader::MaxFieldLength);
    m_notes = new QPlainTextEdit(this);
    m_notes->setObjectName(QStringLiteral("recordNotes"));
    m_notes->setMaximumHeight(90);
    m_pageSize = new QComboBox(this);
    m_pageSize->setObjectName(QStringLiteral("recordPageSize"));
    m_pageSize->addItem(QStringLiteral("A4"), int(QPageSize::A4));
    m_pageSize->addItem(QString(), int(QPageSize::Letter));

    m_machineLabel = new QLabel(this);
    m_customerLabel = new QLabel(this);
    m_siteLabel = new QLabel(this);
    m_engineerLabel = new QLabel(this);
    m_notesLabel = new QLabel(this);
    m_pageSizeLabel = new QLabel(this);
    auto *form = new QFormLayout;
    form->addRow(m_machineLabel, m_machine);
    form->addRow(m_customerLabel, m_customer);
    form->addRow(m_siteLabel, m_site);
    form->addRow(m_engineerLabel, m_engineer);
    form->addRow(m_notesLabel, m_notes);
    form->addRow(m_pageSizeLabel, m_pageSize);

    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(m_drivesLabel);
    leftLayout->addWidget(m_drives, 1);
    leftLayout->addWidget(m_runsLabel);
    leftLayout->addWidget(m_runs);
    leftLayout->addLayout(runButtons);
    leftLayout->addLayout(form);

    auto *pages = new QWidget;
    m_pagesLayout = new QVBoxLayout(pages);
    m_pagesLayout->addStretch(1);
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("recordPreview"));
    scroll->setWidget(pages);
    scroll->setWidgetResizable(true);
    scroll->setMinimumWidth(500);

    auto *splitter = new QSplitter(this);
    splitter->addWidget(left);
    splitter->addWidget(scroll);
    splitter->setStretchFactor(1, 1);

    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("recordMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_previewButton = m_buttons->addButton(QString(), QDialogButtonBox::ActionRole);
    m_previewButton->setObjectName(QStringLiteral("recordPreviewButton"));
    m_saveButton = m_buttons->addButton(QString(), QDialogButtonBox::ActionRole);
    m_saveButton->setObjectName(QStringLiteral("recordSaveButton"));
    connect(m_previewButton, &QPushButton::clicked, this, &RecordDialog::preview);
    connect(m_saveButton, &QPushButton::clicked, this, &RecordDialog::chooseFileAndSave);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_message);
    layout->addWidget(m_buttons);
    resize(1100, 640);
}

void RecordDialog::retranslate()
{
    setWindowTitle(tr("Commissioning record"));
    m_drivesLabel->setText(tr("Drives in the record:"));
    m_runsLabel->setText(tr("Tuning runs (run files, each shown with the drive it was taken on):"));
    m_addRunsButton->setText(tr("Add run files…"));
    m_removeRunsButton->setText(tr("Remove"));
    for (int i = 0; i < m_runs->count() && i < m_runFiles.size(); ++i) {
        const TuningRun &run = m_runFiles.at(i).run;
        m_runs->item(i)->setText(
            tr("%1 — %2, %3 at address %4").arg(run.label, RecordRuns::testName(run.test), run.family).arg(run.address));
        m_runs->item(i)->setToolTip(QDir::toNativeSeparators(m_runFiles.at(i).path));
    }
    m_machineLabel->setText(tr("Machine / project:"));
    m_machine->setToolTip(tr("Also keeps this machine's drives apart in the verification journal: the writes, "
                             "restores and EEPROM operations made from now on are noted under this name, and a "
                             "record shows those noted under the name it is made with."));
    m_customerLabel->setText(tr("Customer:"));
    m_siteLabel->setText(tr("Site:"));
    m_engineerLabel->setText(tr("Engineer:"));
    m_notesLabel->setText(tr("Notes:"));
    m_pageSizeLabel->setText(tr("Paper:"));
    m_pageSize->setItemText(1, tr("Letter"));
    m_previewButton->setText(tr("&Preview"));
    m_saveButton->setText(tr("&Save PDF…"));
    for (int i = 0; i < m_drives->count(); ++i) {
        QListWidgetItem *item = m_drives->item(i);
        const int id = item->data(ConnectionRole).toInt();
        const int address = item->data(AddressRole).toInt();
        const DriveInfo info = m_directory->info(id, address);
        item->setText(tr("%1 at address %2 — %3")
                          .arg(familyTraits(info.identity.family).displayName())
                          .arg(address)
                          .arg(m_directory->connectionSettings(id).linkName()));
        item->setToolTip(item->text());
    }
    fitDriveList();
    if (m_drives->count() == 0)
        m_message->setText(tr("No drive is connected: connect to the drives first (File → Connect…)."));
}

void RecordDialog::fitDriveList()
{
    // As wide as its longest entry (no sideways scrolling), up to a third of a laptop's
    // screen; longer entries are elided in the middle (full text in the tool tip).
    const int need = m_drives->sizeHintForColumn(0) + 2 * m_drives->frameWidth()
        + m_drives->verticalScrollBar()->sizeHint().width() + 4;
    m_drives->setMinimumWidth(qBound(200, need, 440));
}

void RecordDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void RecordDialog::fillDrives()
{
    for (int id : m_directory->connections())
        for (int address : m_directory->drives(id)) {
            auto *item = new QListWidgetItem(m_drives);
            item->setData(ConnectionRole, id);
            item->setData(AddressRole, address);
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            item->setCheckState(Qt::Checked);
        }
}

bool RecordDialog::addRunFiles(const QStringList &paths)
{
    QStringList refused;
    for (const QString &path : paths) {
        RecordRunFile file;
        if (Error e = RecordRuns::load(path, &file)) {
            refused << e.message;
            continue;
        }
        const bool listed = std::any_of(m_runFiles.cbegin(), m_runFiles.cend(),
                                        [&file](const RecordRunFile &f) { return f.path == file.path; });
        if (listed)
            continue;
        m_runFiles.append(file);
        new QListWidgetItem(m_runs);
    }
    retranslate();
    if (!refused.isEmpty()) {
        const QString message = tr("Not added: %1").arg(refused.join(QLatin1String("; ")));
        m_message->setText(message);
        emit failed(message);
        return false;
    }
    return true;
}

void RecordDialog::chooseRunFiles()
{
    QSettings s;
    s.beginGroup(QLatin1String(SettingsGroup));
    const QString folder = s.value(QStringLiteral("runFolder"), QDir::homePath()).toString();
    const QStringList paths = QFileDialog::getOpenFileNames(this, tr("Choose tuning runs for the record"), folder,
                                                            tr("Run files (*.ddrun)"));
    if (paths.isEmpty())
        return;
    s.setValue(QStringLiteral("runFolder"), QFileInfo(paths.first()).absolutePath());
    addRunFiles(paths);
}

void RecordDialog::removeSelectedRuns()
{
    for (int i = m_runs->count() - 1; i >= 0; --i)
        if (m_runs->item(i)->isSelected()) {
            delete m_runs->takeItem(i);
            m_runFiles.removeAt(i);
        }
}

QString RecordDialog::message() const
{
    return m_message->text();
}

void RecordDialog::loadSettings()
{
    QSettings s;
    s.beginGroup(QLatin1String(SettingsGroup));
    m_machine->setText(s.value(QStringLiteral("machine")).toString());
    m_customer->setText(s.value(QStringLiteral("customer")).toString());
    m_site->setText(s.value(QStringLiteral("site")).toString());
    m_engineer->setText(s.value(QStringLiteral("engineer")).toString());
    m_notes->setPlainText(s.value(QStringLiteral("notes")).toString());
    const int size = s.value(QStringLiteral("pageSize"), int(RecordRenderer::defaultPageSize(QLocale::system())))
                         .toInt();
    m_pageSize->setCurrentIndex(qMax(0, m_pageSize->findData(size)));
}

void RecordDialog::saveSettings() const
{
    QSettings s;
    s.beginGroup(QLatin1String(SettingsGroup));
    s.setValue(QStringLiteral("machine"), m_machine->text());
    s.setValue(QStringLiteral("customer"), m_customer->text());
    s.setValue(QStringLiteral("site"), m_site->text());
    s.setValue(QStringLiteral("engineer"), m_engineer->text());
    s.setValue(QStringLiteral("notes"), m_notes->toPlainText());
    s.setValue(QStringLiteral("pageSize"), m_pageSize->currentData().toInt());
}

void RecordDialog::done(int result)
{
    saveSettings();
    QDialog::done(result);
}

int RecordDialog::previewPages() const
{
    return int(m_pages.size());
}

void RecordDialog::setBusy(bool busy)
{
    m_previewButton->setEnabled(!busy);
    m_saveButton->setEnabled(!busy);
    m_drives->setEnabled(!busy);
    m_runs->setEnabled(!busy);
    m_addRunsButton->setEnabled(!busy);
    m_removeRunsButton->setEnabled(!busy);
}

void RecordDialog::preview()
{
    start(Pending::Preview);
}

void RecordDialog::saveTo(const QString &pdfPath)
{
    m_savePath = pdfPath;
    start(Pending::Save);
}

void RecordDialog::chooseFileAndSave()
{
    QSettings s;
    s.beginGroup(QLatin1String(SettingsGroup));
    const QString folder = s.value(QStringLiteral("folder"), QDir::homePath()).toString();
    QString name = m_machine->text().trimmed();
    name.replace(QRegularExpression(QStringLiteral("[^\\w\\-]+")), QStringLiteral("-"));
    const QString suggested = QDir(folder).filePath((name.isEmpty() ? QStringLiteral("record") : name)
                                                    + QLatin1Char('-') + QDate::currentDate().toString(Qt::ISODate)
                                                    + QStringLiteral(".pdf"));
    QString path = QFileDialog::getSaveFileName(this, tr("Save the commissioning record"), suggested,
                                                tr("PDF files (*.pdf)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive))
        path += QStringLiteral(".pdf");
    s.setValue(QStringLiteral("folder"), QFileInfo(path).absolutePath());
    saveTo(path);
}

void RecordDialog::start(Pending what)
{
    if (m_gatherer->isBusy())
        return;
    QList<QPair<int, int>> drives;
    for (int i = 0; i < m_drives->count(); ++i)
        if (m_drives->item(i)->checkState() == Qt::Checked)
            drives.append(
                {m_drives->item(i)->data(ConnectionRole).toInt(), m_drives->item(i)->data(AddressRole).toInt()});
    if (drives.isEmpty()) {
        const QString message = tr("Choose at least one drive for the record.");
        m_message->setText(message);
        emit failed(message);
        return;
    }
    saveSettings();
    m_pending = what;
    setBusy(true);
    m_gatherer->gather(drives);
}

CommissioningRecord RecordDialog::recordOf(const QList<DriveRecord> &drives) const
{
    CommissioningRecord record;
    record.locale = QLocale();
    record.header.machine = m_machine->text().trimmed();
    record.header.customer = m_customer->text().trimmed();
    record.header.site = m_site->text().trimmed();
    record.header.engineer = m_engineer->text().trimmed();
    record.header.notes = m_notes->toPlainText().left(RecordHeader::MaxNotesLength);
    record.header.stamp();
    record.drives = drives;
    return record;
}

void RecordDialog::onGathered(const QList<DriveRecord> &records, const QStringList &problems)
{
    setBusy(false);
    const Pending what = std::exchange(m_pending, Pending::None);
    if (records.isEmpty()) {
        const QString message = tr("No drive could be read: %1").arg(problems.join(QLatin1String("; ")));
        m_message->setText(message);
        emit failed(message);
        return;
    }
    CommissioningRecord record = recordOf(records);
    if (Error e = RecordRuns::attach(m_runFiles, &record.drives, record.locale)) {
        const QString message = tr("No record was made: %1").arg(e.message);
        m_message->setText(message);
        emit failed(message);
        return;
    }
    if (what == Pending::Preview)
        showPreview(record);
    else if (what == Pending::Save)
        write(record);
    if (!problems.isEmpty())
        m_message->setText(m_message->text() + QLatin1Char('\n')
                           + tr("Left out: %1").arg(problems.join(QLatin1String("; "))));
}

void RecordDialog::showPreview(const CommissioningRecord &record)
{
    const QByteArray json = RecordJson::toJson(record);
    RecordRenderer renderer(record, RecordJson::sha256(json));
    renderer.setPageSize(QPageSize::PageSizeId(m_pageSize->currentData().toInt()));
    const QList<QImage> images = renderer.renderImages(PreviewDpi, PreviewMaxPages);
    qDeleteAll(m_pages);
    m_pages.clear();
    for (const QImage &image : images) {
        auto *label = new QLabel;
        label->setPixmap(QPixmap::fromImage(image));
        label->setFrameShape(QFrame::Box);
        m_pagesLayout->insertWidget(m_pagesLayout->count() - 1, label, 0, Qt::AlignHCenter);
        m_pages.append(label);
    }
    m_message->setText(tr("Preview of the first %n page(s).", nullptr, int(images.size())));
    emit previewShown(int(images.size()));
}

void RecordDialog::write(const CommissioningRecord &record)
{
    const QByteArray json = RecordJson::toJson(record);
    const QString sha = RecordJson::sha256(json);
    RecordRenderer renderer(record, sha);
    renderer.setPageSize(QPageSize::PageSizeId(m_pageSize->currentData().toInt()));
    const QFileInfo info(m_savePath);
    const QString jsonPath = info.absoluteDir().filePath(info.completeBaseName() + QStringLiteral(".json"));
    int pages = 0;
    Error e = renderer.writePdf(m_savePath, &pages);
    if (!e) {
        QSaveFile file(jsonPath);
        if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size() || !file.commit())
            e = {ErrorCode::FileError, tr("Cannot write %1: %2").arg(jsonPath, file.errorString())};
    }
    if (e) {
        m_message->setText(e.message);
        emit failed(e.message);
        return;
    }
    m_sha256 = sha;
    QString text = tr("Saved %1 (%n page(s)) and %2. SHA-256 of the JSON: %3", nullptr, pages)
                       .arg(QDir::toNativeSeparators(m_savePath), QDir::toNativeSeparators(jsonPath), sha);
    if (RecordFont::needsCjk(record.locale) && RecordFont::cjkFamily().isEmpty())
        text += QLatin1Char('\n') + tr("No Chinese font is installed: Chinese text is missing from the PDF.");
    m_message->setText(text);
    emit recordSaved(m_savePath, jsonPath, sha);
}

} // namespace dd
