#include "core/params/backupfile.h"

#include "core/params/jsonfieldreader.h"
#include "core/params/parameterdictionary.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QSaveFile>
#include <QSet>
#include <QVector>

#include <cmath>

namespace dd {

static const QStringList &rootFields()
{
    static const QStringList fields = {
        QStringLiteral("format"),     QStringLiteral("formatVersion"), QStringLiteral("toolVersion"),
        QStringLiteral("created"),    QStringLiteral("family"),        QStringLiteral("address"),
        QStringLiteral("firmware"),   QStringLiteral("model"),         QStringLiteral("link"),
        QStringLiteral("parameters"), QStringLiteral("checksum"),      QStringLiteral("scope")};
    return fields;
}

static const QStringList &entryFields()
{
    static const QStringList fields = {QStringLiteral("index"),      QStringLiteral("key"),  QStringLiteral("name"),
                                       QStringLiteral("value"),      QStringLiteral("unit"), QStringLiteral("access"),
                                       QStringLiteral("lastWritten")};
    return fields;
}

QString BackupFile::changedOnlyScope()
{
    return QStringLiteral("changed-from-defaults");
}

QString BackupFile::formatName()
{
    return QStringLiteral("drivedesk-backup");
}

BackupFile::BackupFile()
    : m_toolVersion(QStringLiteral(DRIVEDESK_VERSION))
{
    setCreated(QDateTime::currentDateTimeUtc());
}

void BackupFile::setCreated(const QDateTime &time)
{
    QDateTime t = time.toUTC();
    t.setTime(QTime(t.time().hour(), t.time().minute(), t.time().second()));
    m_created = t;
}

QByteArray BackupFile::canonicalValues(const ParameterSet &values)
{
    QByteArray out;
    for (auto it = values.entries().constBegin(); it != values.entries().constEnd(); ++it) {
        if (!it->isKnown())
            continue;
        out += QByteArray::number(it.key()) + '=' + QByteArray::number(it->value) + '\n';
    }
    return out;
}

QString BackupFile::checksum(const ParameterSet &values)
{
    const QByteArray hash = QCryptographicHash::hash(canonicalValues(values), QCryptographicHash::Sha256);
    return QStringLiteral("sha256:") + QString::fromLatin1(hash.toHex());
}

Error BackupFile::toJson(const ParameterDictionary &dictionary, QByteArray *out) const
{
    if (!m_family)
        return Error{ErrorCode::InvalidArgument, tr("The backup has no drive family")};
    if (dictionary.isEmpty() || dictionary.family() != *m_family) {
        return Error{ErrorCode::InvalidArgument,
                     tr("The dictionary does not belong to %1 drives").arg(familyId(*m_family))};
    }
    if (m_address < 0 || m_address > 255) {
        return Error{ErrorCode::OutOfRange, tr("Drive address %1 is outside 0 to 255").arg(m_address)};
    }
    QJsonArray parameters;
    for (auto it = m_values.entries().constBegin(); it != m_values.entries().constEnd(); ++it) {
        if (!it->isKnown())
            continue;
        const ParameterInfo *p = dictionary.byIndex(it.key());
        if (!p) {
            return Error{
                ErrorCode::InvalidArgument,
                tr("Parameter %1 is not in the %2 dictionary").arg(QString::number(it.key()), familyId(*m_family))};
        }
        if (Error e = dictionary.validateValue(p->index, it->value))
            return e;
        QJsonObject entry;
        entry.insert(QStringLiteral("index"), p->index);
        entry.insert(QStringLiteral("key"), p->key);
        entry.insert(QStringLiteral("name"), p->name.english());
        entry.insert(QStringLiteral("value"), it->value);
        entry.insert(QStringLiteral("unit"), p->unit);
        entry.insert(QStringLiteral("access"), accessId(p->access));
        if (p->access == Access::WriteOnly)
            entry.insert(QStringLiteral("lastWritten"), true);
        parameters.append(entry);
    }
    QJsonObject root;
    root.insert(QStringLiteral("format"), formatName());
    root.insert(QStringLiteral("formatVersion"), FormatVersion);
    root.insert(QStringLiteral("toolVersion"), m_toolVersion);
    root.insert(QStringLiteral("created"), m_created.toString(Qt::ISODate));
    root.insert(QStringLiteral("family"), familyId(*m_family));
    root.insert(QStringLiteral("address"), m_address);
    root.insert(QStringLiteral("firmware"), m_firmware);
    root.insert(QStringLiteral("model"), m_model);
    root.insert(QStringLiteral("link"), m_link);
    if (m_changedOnly)
        root.insert(QStringLiteral("scope"), changedOnlyScope());
    root.insert(QStringLiteral("parameters"), parameters);
    root.insert(QStringLiteral("checksum"), checksum(m_values));
    const QByteArray bytes = QJsonDocument(root).toJson(QJsonDocument::Indented);
    // Never produce a file that load() refuses (over-long texts, nested link settings...).
    BackupFile check;
    if (Error e = check.parse(root, tr("the backup"), &dictionary))
        return Error{ErrorCode::InvalidArgument, e.message};
    *out = bytes;
    return Error::none();
}

Error BackupFile::save(const QString &path) const
{
    if (!m_family)
        return Error{ErrorCode::InvalidArgument, tr("The backup has no drive family")};
    return save(path, ParameterDictionary::bundled(*m_family));
}

Error BackupFile::save(const QString &path, const ParameterDictionary &dictionary) const
{
    QByteArray bytes;
    if (Error e = toJson(dictionary, &bytes))
        return e;
    const QString shown = QDir::toNativeSeparators(path);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return Error{
            ErrorCode::FileError,
            tr("Cannot write %1: %2. Is the folder writable and the disk not full?").arg(shown, file.errorString())};
    }
    // Qt 6.4's QSaveFile::commit() ignores a failed flush inside close() and then commits a
    // truncated file (seen with a full disk / file-size limit): flush and check first.
    if (file.write(bytes) != bytes.size() || !file.flush()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return Error{ErrorCode::FileError,
                     tr("Cannot write %1: %2. The previous file, if any, is unchanged.").arg(shown, why)};
    }
    if (!file.commit()) {
        return Error{
            ErrorCode::FileError,
            tr("Cannot write %1: %2. The previous file, if any, is unchanged.").arg(shown, file.errorString())};
    }
    return Error::none();
}

Error BackupFile::load(const QString &path, const ParameterDictionary *dictionary)
{
    QByteArray data;
    if (Error e = JsonFieldReader::readFile(path, MaxFileSize, &data))
        return e;
    return loadFromJson(data, QFileInfo(path).fileName(), dictionary);
}

Error BackupFile::loadFromJson(const QByteArray &json, const QString &source, const ParameterDictionary *dictionary)
{
    if (json.size() > MaxFileSize) {
        return Error{ErrorCode::FileError,
                     tr("%1 is larger than %2 bytes; it is not a file DriveDesk wrote")
                         .arg(source, QString::number(MaxFileSize))};
    }
    QJsonObject root;
    if (Error e = JsonFieldReader::parseObject(json, source, &root))
        return e;
    BackupFile parsed;
    if (Error e = parsed.parse(root, source, dictionary))
        return e;
    *this = parsed;
    return Error::none();
}

// Link settings: a flat object of strings, booleans and exact numbers.
static bool checkLink(const QJsonObject &link, const QString &source, QString *error)
{
    if (link.size() > BackupFile::MaxLinkEntries) {
        *error = BackupFile::tr("%1: field \"link\" has more than %2 entries")
                     .arg(source, QString::number(BackupFile::MaxLinkEntries));
        return false;
    }
    for (auto it = link.constBegin(); it != link.constEnd(); ++it) {
        const QString where = QStringLiteral("link.%1").arg(it.key().left(64));
        if (it.key().isEmpty() || it.key().size() > 64) {
            *error = BackupFile::tr("%1: field \"%2\" has an empty or too long name").arg(source, where);
            return false;
        }
        const QJsonValue v = it.value();
        bool ok = v.isBool() || (v.isString() && v.toString().size() <= 256);
        if (v.isDouble()) {
            QString problem;
            ok = JsonFieldReader::exactInteger(v, &problem).has_value()
                || (std::isfinite(v.toDouble()) && std::fabs(v.toDouble()) <= double(JsonFieldReader::MaxExactInteger));
        }
        if (!ok) {
            *error = BackupFile::tr("%1: field \"%2\" must be a string (up to 256 characters), a number "
                                    "within ±2^53 or true/false (found %3)")
                         .arg(source, where, JsonFieldReader::jsonTypeName(v));
            return false;
        }
    }
    return true;
}

Error BackupFile::parse(const QJsonObject &root, const QString &source, const ParameterDictionary *dictionary)
{
    JsonFieldReader r(root, source);
    r.checkKnownFields(rootFields());
    const auto format = r.string(QStringLiteral("format"), 64);
    if (format && *format != formatName()) {
        return Error{
            ErrorCode::Malformed,
            tr("%1 is not a DriveDesk backup file (format \"%2\", expected \"%3\")").arg(source, *format, formatName())};
    }
    const auto version = r.integer(QStringLiteral("formatVersion"));
    if (version && *version != FormatVersion) {
        return Error{ErrorCode::NotSupported,
                     tr("%1: backup format version %2 is not supported; this DriveDesk reads version %3. "
                        "Use the DriveDesk version that wrote the file, or a newer one.")
                         .arg(source, QString::number(*version), QString::number(FormatVersion))};
    }
    const auto familyText = r.string(QStringLiteral("family"), 64);
    if (!r.ok())
        return r.error();
    const auto family = familyFromId(*familyText);
    if (!family || *familyText != familyId(*family)) {
        return Error{ErrorCode::NotSupported,
                     tr("%1: unknown drive family \"%2\" (known: %3)")
                         .arg(source, *familyText, familyIds().join(QStringLiteral(", ")))};
    }
    const ParameterDictionary &dict = dictionary ? *dictionary : ParameterDictionary::bundled(*family);
    if (dict.isEmpty() || dict.family() != *family) {
        return Error{ErrorCode::InvalidArgument,
                     tr("%1 is a backup of a %2 drive, but the dictionary given "
                        "is for %3 drives")
                         .arg(source, familyId(*family), familyId(dict.family()))};
    }
    const auto toolVersion = r.string(QStringLiteral("toolVersion"), 64, JsonFieldReader::Required, false);
    const auto createdText = r.string(QStringLiteral("created"), 64);
    const auto address = r.integerIn(QStringLiteral("address"), 0, 255);
    const auto firmware = r.string(QStringLiteral("firmware"), 64);
    const auto model = r.string(QStringLiteral("model"), 64);
    const auto link = r.object(QStringLiteral("link"));
    const auto entries = r.array(QStringLiteral("parameters"), MaxParameters);
    const auto checksumText = r.string(QStringLiteral("checksum"), 80);
    const auto scope = r.string(QStringLiteral("scope"), 64, JsonFieldReader::Optional);
    if (!r.ok())
        return r.error();
    if (scope && *scope != changedOnlyScope() && *scope != QLatin1String("all")) {
        return Error{ErrorCode::Malformed,
                     tr("%1: field \"scope\" must be \"all\" or \"%2\" (found \"%3\")")
                         .arg(source, changedOnlyScope(), scope->left(64))};
    }
    const QDateTime created = QDateTime::fromString(*createdText, Qt::ISODate);
    if (!created.isValid()) {
        return Error{ErrorCode::Malformed,
                     tr("%1: field \"created\" = \"%2\" is not an ISO 8601 date and time").arg(source, *createdText)};
    }
    QString linkProblem;
    if (!checkLink(*link, source, &linkProblem))
        return Error{ErrorCode::Malformed, linkProblem};
    static const QRegularExpression checksumPattern(QStringLiteral("^sha256:[0-9a-f]{64}$"));
    if (!checksumPattern.match(*checksumText).hasMatch()) {
        return Error{ErrorCode::Malformed,
                     tr("%1: field \"checksum\" must be \"sha256:\" followed by 64 "
                        "lower-case hex digits")
                         .arg(source)};
    }

    // Structure of every entry first, then the checksum, then the dictionary's rules.
    struct Entry
    {
        int position;
        int index;
        QString key;
        qint64 value;
        QString access;
        std::optional<bool> lastWritten;
    };
    QVector<Entry> list;
    ParameterSet values;
    for (int i = 0; i < entries->size(); ++i) {
        QString where = QStringLiteral("%1: parameters[%2]").arg(source, QString::number(i));
        const QJsonValue v = entries->at(i);
        if (!v.isObject()) {
            return Error{ErrorCode::Malformed,
                         tr("%1 must be an object (found %2)").arg(where, JsonFieldReader::jsonTypeName(v))};
        }
        if (v.toObject().value(QStringLiteral("key")).isString())
            where += QStringLiteral(" (%1)").arg(v.toObject().value(QStringLiteral("key")).toString().left(64));
        JsonFieldReader e(v.toObject(), where);
        e.checkKnownFields(entryFields());
        const auto index = e.integerIn(QStringLiteral("index"), 0, ParameterDictionary::MaxIndex);
        const auto key = e.string(QStringLiteral("key"), 64, JsonFieldReader::Required, false);
        e.string(QStringLiteral("name"), 256);
        const auto value = e.integer(QStringLiteral("value"));
        e.string(QStringLiteral("unit"), 32);
        const auto access = e.string(QStringLiteral("access"), 2);
        const auto lastWritten = e.boolean(QStringLiteral("lastWritten"), JsonFieldReader::Optional);
        if (!e.ok())
            return e.error();
        if (values.contains(int(*index))) {
            return Error{ErrorCode::Malformed,
                         tr("%1: index %2 appears more than once").arg(where, QString::number(*index))};
        }
        values.set(int(*index), *value);
        list.append(Entry{i, int(*index), *key, *value, *access, lastWritten});
    }
    if (checksum(values) != *checksumText) {
        return Error{ErrorCode::ChecksumError,
                     tr("%1: the checksum does not match the values: the file was changed or damaged "
                        "after DriveDesk wrote it. Restore refuses it; use an intact copy.")
                         .arg(source)};
    }

    for (const Entry &entry : qAsConst(list)) {
        const QString where = QStringLiteral("%1: parameters[%2] (%3)")
                                  .arg(source, QString::number(entry.position), entry.key);
        const ParameterInfo *p = dict.byIndex(entry.index);
        if (!p) {
            return Error{ErrorCode::Malformed,
                         tr("%1: there is no parameter %2 for %3 drives")
                             .arg(where, QString::number(entry.index), familyId(*family))};
        }
        if (p->key.compare(entry.key, Qt::CaseInsensitive) != 0) {
            return Error{ErrorCode::Malformed,
                         tr("%1: index %2 is %3 in the dictionary, not \"%4\"")
                             .arg(where, QString::number(entry.index), p->key, entry.key)};
        }
        if (entry.access != accessId(p->access)) {
            return Error{ErrorCode::Malformed,
                         tr("%1: access \"%2\" differs from the dictionary's \"%3\"")
                             .arg(where, entry.access, accessId(p->access))};
        }
        const bool writeOnly = p->access == Access::WriteOnly;
        if (writeOnly != entry.lastWritten.value_or(false)) {
            return Error{ErrorCode::Malformed,
                         writeOnly ? tr("%1: a write-only value must be marked \"lastWritten\": true").arg(where)
                                   : tr("%1: \"lastWritten\" is only allowed on write-only values").arg(where)};
        }
        if (!p->inRange(entry.value)) {
            return Error{
                ErrorCode::OutOfRange,
                tr("%1: value %2 is outside the allowed range %3 to %4")
                    .arg(where, QString::number(entry.value), QString::number(p->min), QString::number(p->max))};
        }
        values.set(entry.index, entry.value, writeOnly ? ValueSource::LastWritten : ValueSource::ReadFromDrive);
    }

    m_toolVersion = *toolVersion;
    setCreated(created);
    m_family = *family;
    m_address = int(*address);
    m_firmware = *firmware;
    m_model = *model;
    m_link = *link;
    m_values = values;
    m_changedOnly = scope && *scope == changedOnlyScope();
    return Error::none();
}

Error BackupFile::checkCompatible(Family targetFamily, const QString &targetFirmware, bool force) const
{
    if (!m_family)
        return Error{ErrorCode::InvalidArgument, tr("The backup has no drive family")};
    if (*m_family != targetFamily) {
        return Error{ErrorCode::NotSupported,
                     tr("This backup is of a %1 drive; it cannot be restored to a %2 drive")
                         .arg(familyId(*m_family), familyId(targetFamily))};
    }
    const QString fileFirmware = m_firmware.trimmed();
    const QString driveFirmware = targetFirmware.trimmed();
    if (force || fileFirmware.compare(driveFirmware, Qt::CaseInsensitive) == 0)
        return Error::none();
    QString message;
    if (driveFirmware.isEmpty()) {
        message = tr("The backup was taken from firmware %1, but the drive's firmware version is unknown. "
                     "Parameters may differ between firmware versions: compare them first, then force the "
                     "restore if you are sure.")
                      .arg(fileFirmware);
    } else if (fileFirmware.isEmpty()) {
        message = tr("The backup does not record a firmware version; the drive has firmware %1. Compare the "
                     "parameters first, then force the restore if you are sure.")
                      .arg(driveFirmware);
    } else {
        message = tr("The backup was taken from firmware %1; the drive has firmware %2. Parameters may differ "
                     "between firmware versions: compare them first, then force the restore if you are sure.")
                      .arg(fileFirmware, driveFirmware);
    }
    return Error{ErrorCode::InvalidArgument, message};
}

} // namespace dd
