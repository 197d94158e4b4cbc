#include "core/report/verificationjournal.h"

#include "core/drive/drivetypes.h"
#include "core/drive/restorereport.h"
#include "core/params/parameterdictionary.h"
#include "core/report/driverecord.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>

namespace dd {

namespace {

constexpr qint64 MaxJournalSize = 4 * 1024 * 1024;

QString outcomeId(WriteOutcome o)
{
    switch (o) {
    case WriteOutcome::Verified: return QStringLiteral("verified");
    case WriteOutcome::WriteOnly: return QStringLiteral("written-only");
    case WriteOutcome::Mismatch: return QStringLiteral("mismatch");
    case WriteOutcome::NotWritten: return QStringLiteral("failed");
    case WriteOutcome::Unknown:
    case WriteOutcome::ReadBackFailed: return QStringLiteral("unconfirmed");
    }
    return QStringLiteral("unconfirmed");
}

RecordVerification::Entry entryFrom(const ParameterWriteResult &w, const ParameterDictionary &dictionary)
{
    RecordVerification::Entry e;
    e.index = w.index;
    const ParameterInfo *p = dictionary.byIndex(w.index);
    e.key = p ? p->key : QString::number(w.index);
    e.requested = w.requested;
    e.hasReadBack = w.readable && w.written && !w.readBackFailed;
    e.readBack = w.readBack;
    e.outcome = outcomeId(w.outcome);
    if (!e.isVerified())
        e.message = w.error;
    return e;
}

QString timeText(const QDateTime &t)
{
    return t.isValid() ? t.toUTC().toString(Qt::ISODate) : QString();
}

QDateTime timeFrom(const QJsonValue &v)
{
    QDateTime t = QDateTime::fromString(v.toString(), Qt::ISODate);
    return t.isValid() ? t.toUTC() : QDateTime();
}

} // namespace

VerificationJournal::VerificationJournal(const QString &directory)
    : m_directory(directory)
{
}

QString VerificationJournal::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + QStringLiteral("/drivedesk/journal");
}

QString VerificationJournal::path(const JournalKey &key) const
{
    return m_directory + QLatin1Char('/') + key.fileName();
}

VerificationJournal::Entry VerificationJournal::read(const JournalKey &key, Error *error) const
{
    Entry entry;
    QFile file(path(key));
    if (!file.exists())
        return entry;
    auto damaged = [&](const QString &why) {
        if (error)
            *error = {ErrorCode::FileError,
                      tr("The verification journal %1 is damaged (%2): it is left as it is and its history is "
                         "not used.")
                          .arg(QDir::toNativeSeparators(file.fileName()), why)};
        return Entry();
    };
    if (file.size() > MaxJournalSize)
        return damaged(tr("larger than %n MiB", nullptr, int(MaxJournalSize / (1024 * 1024))));
    if (!file.open(QIODevice::ReadOnly))
        return damaged(file.errorString());
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return damaged(tr("not JSON at byte %1: %2").arg(parseError.offset).arg(parseError.errorString()));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String("drivedesk-journal"))
        return damaged(tr("not a drivedesk-journal"));
    if (JournalKey::fromJson(root.value(QStringLiteral("drive")).toObject()) != key)
        return damaged(tr("it names another drive"));
    const QJsonObject v = root.value(QStringLiteral("verification")).toObject();
    if (!v.isEmpty()) {
        RecordVerification &r = entry.verification;
        r.kind = v.value(QStringLiteral("kind")).toString();
        r.when = timeFrom(v.value(QStringLiteral("when")));
        r.sourceFile = v.value(QStringLiteral("sourceFile")).toString();
        r.sourceChecksum = v.value(QStringLiteral("sourceChecksum")).toString();
        for (const QJsonValue &item : v.value(QStringLiteral("entries")).toArray()) {
            const QJsonObject o = item.toObject();
            RecordVerification::Entry e;
            e.index = o.value(QStringLiteral("index")).toInt();
            e.key = o.value(QStringLiteral("key")).toString();
            e.requested = qint64(o.value(QStringLiteral("requested")).toDouble());
            e.hasReadBack = o.value(QStringLiteral("readBack")).isDouble();
            e.readBack = qint64(o.value(QStringLiteral("readBack")).toDouble());
            e.outcome = o.value(QStringLiteral("outcome")).toString();
            e.message = o.value(QStringLiteral("message")).toString();
            r.entries.append(e);
        }
        if (r.kind != QLatin1String("restore") && r.kind != QLatin1String("write"))
            r = RecordVerification();
    }
    const QJsonObject ee = root.value(QStringLiteral("ee")).toObject();
    entry.ee.operation = ee.value(QStringLiteral("operation")).toString();
    entry.ee.when = timeFrom(ee.value(QStringLiteral("when")));
    entry.ee.ok = ee.value(QStringLiteral("ok")).toBool();
    entry.ee.message = ee.value(QStringLiteral("message")).toString();
    for (const QJsonValue &item : root.value(QStringLiteral("backups")).toArray()) {
        const QJsonObject o = item.toObject();
        entry.backups.append({o.value(QStringLiteral("role")).toString(), o.value(QStringLiteral("path")).toString(),
                              o.value(QStringLiteral("checksum")).toString(),
                              timeFrom(o.value(QStringLiteral("when")))});
    }
    return entry;
}

Error VerificationJournal::write(const JournalKey &key, const Entry &entry)
{
    QJsonObject root{{QStringLiteral("format"), QStringLiteral("drivedesk-journal")},
                     {QStringLiteral("version"), 2},
                     {QStringLiteral("drive"), key.toJson()}};
    const RecordVerification &r = entry.verification;
    if (!r.isEmpty()) {
        QJsonArray entries;
        for (const RecordVerification::Entry &e : r.entries)
            entries.append(QJsonObject{{QStringLiteral("index"), e.index},
                                       {QStringLiteral("key"), e.key},
                                       {QStringLiteral("requested"), double(e.requested)},
                                       {QStringLiteral("readBack"),
                                        e.hasReadBack ? QJsonValue(double(e.readBack)) : QJsonValue(QJsonValue::Null)},
                                       {QStringLiteral("outcome"), e.outcome},
                                       {QStringLiteral("message"), e.message}});
        root.insert(QStringLiteral("verification"),
                    QJsonObject{{QStringLiteral("kind"), r.kind},
                                {QStringLiteral("when"), timeText(r.when)},
                                {QStringLiteral("sourceFile"), r.sourceFile},
                                {QStringLiteral("sourceChecksum"), r.sourceChecksum},
                                {QStringLiteral("entries"), entries}});
    }
    QJsonArray backups;
    for (const BackupReference &b : entry.backups)
        backups.append(QJsonObject{{QStringLiteral("role"), b.role},
                                   {QStringLiteral("path"), b.path},
                                   {QStringLiteral("checksum"), b.checksum},
                                   {QStringLiteral("when"), timeText(b.when)}});
    root.insert(QStringLiteral("backups"), backups);
    if (!entry.ee.isEmpty())
        root.insert(QStringLiteral("ee"),
                    QJsonObject{{QStringLiteral("operation"), entry.ee.operation},
                                {QStringLiteral("when"), timeText(entry.ee.when)},
                                {QStringLiteral("ok"), entry.ee.ok},
                                {QStringLiteral("message"), entry.ee.message}});

    QSaveFile file(path(key));
    const QByteArray bytes = QJsonDocument(root).toJson();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        return {ErrorCode::FileError,
                tr("Cannot write the verification journal %1: %2").arg(file.fileName(), file.errorString())};
    return {};
}

void VerificationJournal::attach(const JournalKey &key, DriveRecord *record) const
{
    Error error;
    const Entry entry = read(key, &error);
    record->verification = entry.verification;
    record->backups = entry.backups;
    record->eeOperation = entry.ee;
    record->identification = key.identifiedBy() + QLatin1Char(' ') + key.cannotTellApart();
    record->journalError = error.message;
}

Error VerificationJournal::update(const JournalKey &key, const std::function<void(Entry &)> &change)
{
    if (!QDir().mkpath(m_directory))
        return {ErrorCode::FileError, tr("Cannot create the folder %1 for the verification journal.").arg(m_directory)};
    QLockFile lock(path(key) + QStringLiteral(".lock"));
    if (!lock.tryLock(LockTimeoutMs))
        return {ErrorCode::FileError,
                tr("The verification journal %1 is locked by another DriveDesk process (%2); nothing was noted in it.")
                    .arg(QDir::toNativeSeparators(path(key)),
                         lock.error() == QLockFile::LockFailedError
                             ? tr("still busy after %n s", nullptr, LockTimeoutMs / 1000)
                             : tr("the lock file cannot be made"))};
    Error damaged;
    Entry entry = read(key, &damaged);
    if (damaged)
        return damaged;
    change(entry);
    return write(key, entry);
}

Error VerificationJournal::recordVerification(const JournalKey &key, const RecordVerification &verification)
{
    return update(key, [&verification](Entry &entry) { entry.verification = verification; });
}

Error VerificationJournal::recordRestore(const JournalKey &key, const RestoreReport &report,
                                         const ParameterDictionary &dictionary, const QString &file,
                                         const QString &checksum)
{
    if (report.dryRun || report.selected.isEmpty())
        return {};
    const RecordVerification verification = fromRestore(report, dictionary, file, checksum);
    const BackupReference backup{QStringLiteral("restore"), QFileInfo(file).absoluteFilePath(), checksum,
                                 QDateTime::currentDateTimeUtc()};
    return update(key, [&](Entry &entry) {
        entry.verification = verification;
        if (file.isEmpty()) // from another drive (GUI fleet apply): no file to refer to
            return;
        entry.backups.prepend(backup);
        while (entry.backups.size() > MaxBackups)
            entry.backups.removeLast();
    });
}

Error VerificationJournal::recordEeOperation(const JournalKey &key, const RecordEeOperation &operation)
{
    return update(key, [&operation](Entry &entry) { entry.ee = operation; });
}

Error VerificationJournal::recordBackup(const JournalKey &key, const BackupReference &backup)
{
    return update(key, [&backup](Entry &entry) {
        entry.backups.prepend(backup);
        while (entry.backups.size() > MaxBackups)
            entry.backups.removeLast();
    });
}

RecordVerification VerificationJournal::fromWrites(const QList<ParameterWriteResult> &writes,
                                                   const ParameterDictionary &dictionary)
{
    RecordVerification v;
    v.kind = QStringLiteral("write");
    v.when = QDateTime::currentDateTimeUtc();
    for (const ParameterWriteResult &w : writes)
        v.entries.append(entryFrom(w, dictionary));
    return v;
}

RecordEeOperation VerificationJournal::fromEe(EeOperation operation, const Error &error)
{
    return {eeMnemonic(operation), QDateTime::currentDateTimeUtc(), !error.isError(), error.message};
}

RecordVerification VerificationJournal::fromRestore(const RestoreReport &report, const ParameterDictionary &dictionary,
                                                    const QString &file, const QString &checksum)
{
    RecordVerification v;
    v.kind = QStringLiteral("restore");
    v.when = QDateTime::currentDateTimeUtc();
    v.sourceFile = file;
    v.sourceChecksum = checksum;
    for (const DiffEntry &d : report.selected) {
        const ParameterWriteResult *w = report.result(d.index);
        RecordVerification::Entry e;
        if (w) {
            e = entryFrom(*w, dictionary);
        } else {
            e.index = d.index;
            e.key = d.key;
            e.requested = d.fileValue.value_or(0);
        }
        e.outcome = RestoreReport::outcomeId(report.outcome(d.index));
        if (e.isVerified())
            e.message.clear();
        else if (!w)
            e.message = tr("not attempted: the restore stopped before this parameter");
        v.entries.append(e);
    }
    return v;
}

} // namespace dd
