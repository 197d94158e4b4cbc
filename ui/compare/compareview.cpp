#include "ui/compare/compareview.h"

#include "core/common/csvfield.h"
#include "core/fleet/parametercomparison.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"
#include "ui/bus/drivedirectory.h"
#include "ui/panels/backup/transferoperation.h"

#include <QCheckBox>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSaveFile>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

CompareView::CompareView(DriveDirectory *directory, QWidget *parent)
    : QDialog(parent)
    , m_directory(directory)
{
    setObjectName(QStringLiteral("compareView"));
    resize(900, 560);
    m_addDrive = new QPushButton(this);
    m_addDrive->setObjectName(QStringLiteral("addDrive"));
    m_addFile = new QPushButton(this);
    m_addFile->setObjectName(QStringLiteral("addFile"));
    m_addDefaults = new QPushButton(this);
    m_addDefaults->setObjectName(QStringLiteral("addDefaults"));
    m_export = new QPushButton(this);
    m_export->setObjectName(QStringLiteral("exportCsv"));
    m_onlyDifferences = new QCheckBox(this);
    m_onlyDifferences->setObjectName(QStringLiteral("onlyDifferences"));
    m_search = new QLineEdit(this);
    m_search->setObjectName(QStringLiteral("search"));
    m_search->setClearButtonEnabled(true);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("compareMessage"));
    m_message->setWordWrap(true);
    m_table = new QTableWidget(this);
    m_table->setObjectName(QStringLiteral("compareTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);

    auto *top = new QHBoxLayout;
    top->addWidget(m_addDrive);
    top->addWidget(m_addFile);
    top->addWidget(m_addDefaults);
    top->addStretch(1);
    top->addWidget(m_onlyDifferences);
    top->addWidget(m_search);
    top->addWidget(m_export);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_message);
    layout->addWidget(m_table, 1);

    connect(m_addDrive, &QPushButton::clicked, this, &CompareView::chooseDrive);
    connect(m_addFile, &QPushButton::clicked, this, &CompareView::chooseFile);
    connect(m_addDefaults, &QPushButton::clicked, this,
            [this] { showError(addDefaults(m_sources.isEmpty() ? Family::ServoModbus : m_sources.first().family)); });
    connect(m_export, &QPushButton::clicked, this, &CompareView::chooseExport);
    connect(m_onlyDifferences, &QCheckBox::toggled, this, &CompareView::applyFilter);
    connect(m_search, &QLineEdit::textChanged, this, &CompareView::applyFilter);
    retranslate();
    rebuild();
}

CompareView::~CompareView() = default;

const ParameterDictionary &CompareView::dictionary() const
{
    return ParameterDictionary::bundled(m_sources.isEmpty() ? Family::ServoModbus : m_sources.first().family);
}

Error CompareView::add(const ParameterSource &source)
{
    QList<ParameterSource> all = m_sources;
    all << source;
    if (Error e = ParameterComparison::checkFamilies(all)) {
        e.message = tr("%1 is not added: %2").arg(source.label, e.message);
        showError(e);
        return e;
    }
    m_sources = all;
    m_error.clear();
    rebuild();
    emit sourcesChanged();
    return {};
}

Error CompareView::addFile(const QString &path)
{
    BackupFile file;
    if (Error e = file.load(path)) {
        showError(e);
        return e;
    }
    const Family family = file.family().value_or(Family::ServoModbus);
    return add(ParameterSource::file(file, path, ParameterDictionary::bundled(family)));
}

Error CompareView::addDefaults(Family family)
{
    ParameterSource s = ParameterSource::defaults(ParameterDictionary::bundled(family));
    if (s.values.isEmpty()) {
        const Error e{ErrorCode::NotSupported,
                      tr("The %1 dictionary gives no default values (its manual publishes none); a dictionary "
                         "file of your own can add them.")
                          .arg(familyId(family))};
        showError(e);
        return e;
    }
    return add(s);
}

void CompareView::addDrive(int connectionId, int address)
{
    auto out = std::make_shared<TransferOutcome>();
    ++m_pending;
    m_directory->hub()->run(connectionId, address, TransferOperation::backup(out),
                            [this, out, address](const DriveResult &r) {
                                --m_pending;
                                if (r.error) {
                                    Error e = r.error;
                                    e.message = tr("drive %1 could not be read: %2").arg(address).arg(e.message);
                                    showError(e);
                                    emit failed(e);
                                    return;
                                }
                                const BackupFile &b = out->backup;
                                add(ParameterSource::drive(b.family().value_or(Family::ServoModbus), address,
                                                           b.firmware(), b.model(), b.values()));
                            });
}

void CompareView::removeSource(int column)
{
    if (column < 0 || column >= m_sources.size())
        return;
    m_sources.removeAt(column);
    rebuild();
    emit sourcesChanged();
}

int CompareView::differenceCount() const
{
    return ParameterComparison::compute(dictionary(), m_sources).differenceCount();
}

QString CompareView::message() const
{
    return m_message->text();
}

void CompareView::showError(const Error &error)
{
    if (!error)
        return;
    m_error = error.message;
    m_message->setText(m_error);
}

void CompareView::rebuild()
{
    const ParameterComparison c = ParameterComparison::compute(dictionary(), m_sources);
    QStringList headers{tr("Parameter")};
    for (const ParameterSource &s : m_sources)
        headers << (s.firmware.isEmpty() ? s.label : tr("%1\nfirmware %2").arg(s.label, s.firmware));
    m_table->clear();
    m_table->setColumnCount(int(headers.size()));
    m_table->setHorizontalHeaderLabels(headers);
    m_table->setRowCount(int(c.rows().size()));
    const QColor differs(255, 226, 170);
    for (int r = 0; r < c.rows().size(); ++r) {
        const ParameterComparison::Row &row = c.rows().at(r);
        QString label = dictionary().label(row.index);
        if (row.communication)
            label += tr(" (communication)");
        auto *name = new QTableWidgetItem(label);
        name->setData(Qt::UserRole, row.differs);
        m_table->setItem(r, 0, name);
        for (int k = 0; k < row.values.size(); ++k) {
            const auto &v = row.values.at(k);
            auto *item = new QTableWidgetItem(v ? QString::number(*v) : QStringLiteral("—"));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, k + 1, item);
        }
        if (row.differs) {
            for (int k = 0; k < m_table->columnCount(); ++k) {
                m_table->item(r, k)->setBackground(differs);
                QFont f = m_table->item(r, k)->font();
                f.setBold(true);
                m_table->item(r, k)->setFont(f);
            }
        }
    }
    m_table->resizeColumnToContents(0);
    QString text = m_error;
    if (m_error.isEmpty() && !m_sources.isEmpty()) {
        text = tr("%n parameter(s) differ.", nullptr, c.differenceCount());
        if (c.firmwareDiffers())
            text += QLatin1Char(' ')
                + tr("The firmware differs between the sources: values may mean different things.");
    }
    m_message->setText(text);
    m_export->setEnabled(!m_sources.isEmpty());
    applyFilter();
}

void CompareView::applyFilter()
{
    const bool only = m_onlyDifferences->isChecked();
    const QString search = m_search->text().trimmed();
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const QTableWidgetItem *name = m_table->item(r, 0);
        const bool differs = name->data(Qt::UserRole).toBool();
        const bool match = search.isEmpty() || name->text().contains(search, Qt::CaseInsensitive);
        m_table->setRowHidden(r, (only && !differs) || !match);
    }
}

void CompareView::setOnlyDifferences(bool on)
{
    m_onlyDifferences->setChecked(on);
}

void CompareView::setSearchText(const QString &text)
{
    m_search->setText(text);
}

Error CompareView::exportCsv(const QString &path) const
{
    const ParameterComparison c = ParameterComparison::compute(dictionary(), m_sources);
    QList<QByteArray> header{QByteArrayLiteral("key"), QByteArrayLiteral("name")};
    for (const ParameterSource &s : m_sources)
        header << csvField(s.id);
    header << QByteArrayLiteral("differs");
    QByteArray bytes = header.join(',') + '\n';
    for (const ParameterComparison::Row &row : c.rows()) {
        const ParameterInfo *p = dictionary().byIndex(row.index);
        QList<QByteArray> cells{csvField(row.key), csvField(p ? p->displayName() : QString())};
        for (const auto &v : row.values)
            cells << (v ? QByteArray::number(*v) : QByteArray());
        cells << (row.differs ? QByteArrayLiteral("yes") : QByteArrayLiteral("no"));
        bytes += cells.join(',') + '\n';
    }
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.commit())
        return {ErrorCode::FileError, tr("Cannot write %1: %2").arg(path, f.errorString())};
    return {};
}

void CompareView::chooseDrive()
{
    QMenu menu(this);
    for (int id : m_directory->connections())
        for (int a : m_directory->drives(id))
            menu.addAction(tr("%1: drive %2").arg(m_directory->connectionSettings(id).linkName()).arg(a), this,
                           [this, id, a] { addDrive(id, a); });
    if (menu.isEmpty())
        menu.addAction(tr("No drive on an open link"))->setEnabled(false);
    menu.exec(m_addDrive->mapToGlobal(QPoint(0, m_addDrive->height())));
}

void CompareView::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Add a backup file"), QString(),
                                                      tr("DriveDesk backups (*.json *.ddbackup);;All files (*)"));
    if (!path.isEmpty())
        addFile(path);
}

void CompareView::chooseExport()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the comparison"), QString(),
                                                      tr("CSV files (*.csv)"));
    if (!path.isEmpty())
        showError(exportCsv(path));
}

void CompareView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        rebuild();
    }
    QDialog::changeEvent(event);
}

void CompareView::retranslate()
{
    setWindowTitle(tr("Compare parameters"));
    m_addDrive->setText(tr("Add drive…"));
    m_addFile->setText(tr("Add file…"));
    m_addDefaults->setText(tr("Add defaults"));
    m_export->setText(tr("Export CSV…"));
    m_onlyDifferences->setText(tr("Only differences"));
    m_search->setPlaceholderText(tr("Search parameters"));
}

} // namespace dd
