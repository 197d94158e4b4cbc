#include "core/report/verificationjournal.h"

#include "core/drive/drivetypes.h"
#include "core/drive/restorereport.h"
#include "core/params/parameterdictionary.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
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

QString VerificationJournal::path(Family family, int address) const
{
    return QStringLiteral("%1/%2-%3.json").arg(m_directory, familyId(family)).arg(address);
}

VerificationJournal::Entry VerificationJournal::read(Family family, int address) const
{
    Entry entry;
    QFile file(path(family, address));
    if (file.size() > MaxJournalSize || !file.open(QIODevice::ReadOnly))
        return entry;
    const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String("drivedesk-journal"))
        return entry;
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
    for (const QJsonValue &item : root.value(QStringLiteral("backups")).toArray()) {
        const QJsonObject o = item.toObject();
        entry.backups.append({o.value(QStringLiteral("role")).toString(), o.value(QStringLiteral("path")).toString(),
                              o.value(QStringLiteral("checksum")).toString(),
                              timeFrom(o.value(QStringLiteral("when")))});
    }
    return entry;
}

Error VerificationJournal::write(Family family, int address, const Entry &entry)
{
    QJsonObject root{{QStringLiteral("format"), QStringLiteral("drivedesk-journal")}, {QStringLiteral("version"), 1}};
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

    if (!QDir().mkpath(m_directory))
        return {ErrorCode::FileError, tr("Cannot create the folder %1 for the verification journal.").arg(m_directory)};
    QSaveFile file(path(family, address));
    const QByteArray bytes = QJsonDocument(root).toJson();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        return {ErrorCode::FileError,
                tr("Cannot write the verification journal %1: %2").arg(file.fileName(), file.errorString())};
    return {};
}

Error VerificationJournal::recordVerification(Family family, int address, const RecordVerification &verification)
{
    Entry entry = read(family, address);
    entry.verification = verification;
    return write(family, address, entry);
}

Error VerificationJournal::recordBackup(Family family, int address, const BackupReference &backup)
{
    Entry entry = read(family, address);
    entry.backups.prepend(backup);
    while (entry.backups.size() > MaxBackups)
        entry.backups.removeLast();
    return write(family, address, entry);
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
