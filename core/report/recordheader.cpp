#include "core/report/recordheader.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QSysInfo>

namespace dd {

QStringList RecordHeader::fieldNames()
{
    return {QStringLiteral("machine"), QStringLiteral("customer"), QStringLiteral("site"), QStringLiteral("engineer"),
            QStringLiteral("notes")};
}

Error RecordHeader::load(const QString &path)
{
    QFile file(path);
    const QFileInfo info(path);
    if (!info.exists())
        return {ErrorCode::FileError, tr("The header file %1 does not exist.").arg(path)};
    if (info.isDir())
        return {ErrorCode::FileError, tr("%1 is a folder, not a header file.").arg(path)};
    if (info.size() > MaxFileSize)
        return {ErrorCode::Malformed,
                tr("The header file %1 is %2 bytes; a header file is at most %3 bytes.")
                    .arg(path)
                    .arg(info.size())
                    .arg(MaxFileSize)};
    if (!file.open(QIODevice::ReadOnly))
        return {ErrorCode::FileError, tr("Cannot read the header file %1: %2").arg(path, file.errorString())};
    return loadFromJson(file.readAll(), path);
}

Error RecordHeader::loadFromJson(const QByteArray &json, const QString &sourceName)
{
    if (json.size() > MaxFileSize)
        return {ErrorCode::Malformed, tr("%1: a header file is at most %2 bytes.").arg(sourceName).arg(MaxFileSize)};
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return {ErrorCode::Malformed,
                tr("%1 is not valid JSON (at byte %2: %3).")
                    .arg(sourceName)
                    .arg(parseError.offset)
                    .arg(parseError.errorString())};
    if (!doc.isObject())
        return {ErrorCode::Malformed,
                tr("%1: a header file is one JSON object, e.g. {\"machine\": \"Press 3\", \"engineer\": \"Li Wei\"}.")
                    .arg(sourceName)};
    const QJsonObject root = doc.object();
    const QStringList names = fieldNames();
    RecordHeader read = *this;
    QString *fields[] = {&read.machine, &read.customer, &read.site, &read.engineer, &read.notes};
    for (auto it = root.begin(); it != root.end(); ++it) {
        const int at = int(names.indexOf(it.key()));
        if (at < 0)
            return {ErrorCode::Malformed,
                    tr("%1: unknown field \"%2\"; a header has the fields %3.")
                        .arg(sourceName, it.key(), names.join(QLatin1String(", ")))};
        if (!it.value().isString())
            return {ErrorCode::Malformed,
                    tr("%1: the field \"%2\" must be text (a JSON string).").arg(sourceName, it.key())};
        const QString text = it.value().toString();
        const int limit = it.key() == QLatin1String("notes") ? MaxNotesLength : MaxFieldLength;
        if (text.size() > limit)
            return {ErrorCode::Malformed,
                    tr("%1: the field \"%2\" is %3 characters long; at most %4 are allowed.")
                        .arg(sourceName, it.key())
                        .arg(text.size())
                        .arg(limit)};
        for (QChar c : text)
            if (c.category() == QChar::Other_Control && c != QLatin1Char('\n') && c != QLatin1Char('\t'))
                return {ErrorCode::Malformed,
                        tr("%1: the field \"%2\" holds a control character (U+%3).")
                            .arg(sourceName, it.key(),
                                 QString::number(c.unicode(), 16).rightJustified(4, QLatin1Char('0')))};
        *fields[at] = text;
    }
    *this = read;
    return {};
}

QJsonObject RecordHeader::fieldsJson() const
{
    return {{QStringLiteral("machine"), machine},
            {QStringLiteral("customer"), customer},
            {QStringLiteral("site"), site},
            {QStringLiteral("engineer"), engineer},
            {QStringLiteral("notes"), notes}};
}

void RecordHeader::stamp()
{
    QDateTime now = QDateTime::currentDateTimeUtc();
    now.setTime(QTime(now.time().hour(), now.time().minute(), now.time().second()));
    created = now;
    toolVersion = QStringLiteral(DRIVEDESK_VERSION);
    computer = QSysInfo::machineHostName();
}

} // namespace dd
