#include "core/drive/parametertransfer.h"

#include "core/drive/drive.h"
#include "core/params/parameterdictionary.h"

#include <QJsonObject>

namespace dd {

ParameterTransfer::ParameterTransfer(Drive *drive, QObject *parent)
    : QObject(parent)
    , m_drive(drive)
{
}

ParameterTransfer::~ParameterTransfer() = default;

const ParameterDictionary &ParameterTransfer::dictionary() const
{
    if (m_dictionary)
        return *m_dictionary;
    if (m_drive && m_drive->dictionary())
        return *m_drive->dictionary();
    return ParameterDictionary::bundled(m_drive ? m_drive->family() : Family::ServoModbus);
}

QList<int> ParameterTransfer::readableIndices(const ParameterDictionary &dictionary, const QString &model)
{
    QList<int> out;
    for (const ParameterInfo &p : dictionary.parameters()) {
        if (!p.isReadable())
            continue;
        if (!p.models.isEmpty() && (model.isEmpty() || !p.models.contains(model, Qt::CaseInsensitive)))
            continue;
        out << p.index;
    }
    return out;
}

QString ParameterTransfer::stageId(Stage stage)
{
    switch (stage) {
    case Stage::Idle: return QStringLiteral("idle");
    case Stage::Identify: return QStringLiteral("identify");
    case Stage::Read: return QStringLiteral("read");
    case Stage::Write: return QStringLiteral("write");
    }
    return {};
}

void ParameterTransfer::backup()
{
    begin(Job::Backup);
}

void ParameterTransfer::compare(const BackupFile &file)
{
    m_file = file;
    begin(Job::Compare);
}

void ParameterTransfer::restore(const BackupFile &file, const RestoreOptions &options)
{
    m_file = file;
    m_options = options;
    begin(Job::Restore);
}

void ParameterTransfer::begin(Job job)
{
    if (m_running) {
        emit finished({ErrorCode::Busy, tr("A backup or restore is already running on this drive.")});
        return;
    }
    m_job = job;
    m_running = true;
    m_stage = Stage::Idle;
    m_backup = BackupFile();
    m_driveValues.clear();
    m_report = RestoreReport();
    m_report.dryRun = job == Job::Restore && m_options.dryRun;
    if (!m_drive) {
        // Report from the event loop, as a reply would.
        QMetaObject::invokeMethod(
            this,
            [this] {
                end({ErrorCode::LinkClosed, tr("The drive is gone.")});
            },
            Qt::QueuedConnection);
        return;
    }
    // Keep the dictionary fixed for the whole job.
    m_dictionary = m_drive->dictionary();
    identify();
}

void ParameterTransfer::watch(DriveReply *reply, void (ParameterTransfer::*next)(DriveReply *))
{
    connect(reply, &DriveReply::progress, this, &ParameterTransfer::progress);
    connect(reply, &DriveReply::finished, this, [this, reply, next] {
        reply->deleteLater();
        (this->*next)(reply);
    });
}

void ParameterTransfer::identify()
{
    m_stage = Stage::Identify;
    watch(m_drive->refreshIdentity(), &ParameterTransfer::onIdentified);
}

void ParameterTransfer::onIdentified(DriveReply *reply)
{
    if (!reply->ok()) {
        Error e = reply->error();
        e.message = tr("The drive could not be identified: %1").arg(e.message);
        return end(e);
    }
    if (m_job == Job::Restore) {
        const DriveIdentity id = m_drive->identity();
        if (Error e = m_file.checkCompatible(id.family, id.firmware, m_options.force))
            return end(e);
    }
    readValues();
}

void ParameterTransfer::readValues()
{
    const QList<int> indices = readableIndices(dictionary(), m_drive->identity().model);
    if (indices.isEmpty())
        return end({ErrorCode::NotSupported, tr("The parameter dictionary lists no readable parameter.")});
    m_stage = Stage::Read;
    watch(m_drive->readParameters(indices), &ParameterTransfer::onRead);
}

void ParameterTransfer::onRead(DriveReply *reply)
{
    if (!reply->ok())
        return end(reply->error());
    const QMap<int, qint64> &values = reply->parameters();
    for (auto it = values.begin(); it != values.end(); ++it)
        m_driveValues.set(it.key(), it.value(), ValueSource::ReadFromDrive);
    // Write-only settings cannot be read; a drive that remembers what it last wrote to them
    // reports that as info "lastWritten" ("index" -> value): it goes into backups marked so.
    const QVariantMap lastWritten = reply->info().value(QStringLiteral("lastWritten")).toMap();
    for (auto it = lastWritten.begin(); it != lastWritten.end(); ++it) {
        bool ok = false;
        const int index = it.key().toInt(&ok);
        if (ok && !m_driveValues.contains(index))
            m_driveValues.set(index, it.value().toLongLong(), ValueSource::LastWritten);
    }
    afterRead();
}

void ParameterTransfer::afterRead()
{
    const DriveIdentity id = m_drive->identity();
    if (m_job == Job::Backup) {
        m_backup.setFamily(id.family);
        m_backup.setAddress(id.address);
        m_backup.setFirmware(id.firmware);
        m_backup.setModel(id.model);
        if (!id.link.isEmpty())
            m_backup.setLink({{QStringLiteral("description"), id.link}});
        m_backup.setValues(m_driveValues);
        return end({});
    }
    m_report.diff = ParameterDiff::compute(dictionary(), m_file.values(), m_driveValues);
    if (m_job == Job::Compare)
        return end({});
    if (Error e = m_report.diff.selectForWrite(m_options.only, &m_report.selected))
        return end(e);
    if (m_options.dryRun || m_report.selected.isEmpty())
        return end({});
    write();
}

void ParameterTransfer::write()
{
    m_stage = Stage::Write;
    QList<ParameterWrite> writes;
    for (const DiffEntry &e : std::as_const(m_report.selected))
        writes.append({e.index, e.fileValue.value_or(0)});
    watch(m_drive->writeParameters(writes), &ParameterTransfer::onWritten);
}

void ParameterTransfer::onWritten(DriveReply *reply)
{
    m_report.results = reply->writeResults();
    if (!reply->ok())
        return end(reply->error());
    if (!m_report.isComplete()) {
        const QList<int> bad = m_report.notWritten() + m_report.indices(RestoreReport::Outcome::Mismatch)
            + m_report.indices(RestoreReport::Outcome::Unconfirmed);
        QStringList keys;
        for (int i : bad)
            keys << dictionary().label(i);
        return end({ErrorCode::VerifyMismatch,
                    tr("Not every parameter was restored: %1.").arg(keys.join(QLatin1String(", ")))});
    }
    end({});
}

void ParameterTransfer::end(const Error &error)
{
    m_running = false;
    emit finished(error);
}

} // namespace dd
