#include "core/params/alarmdictionary.h"

#include "core/common/coreresources.h"
#include "core/params/jsonfieldreader.h"
#include "core/params/paramslog.h"

#include <QFileInfo>
#include <QHash>
#include <QStandardPaths>
#include <QVector>

#include <limits>

namespace dd {

QString AlarmDictionary::formatName()
{
    return QStringLiteral("drivedesk-alarms");
}

QString AlarmDictionary::resourcePath(Family family)
{
    return QStringLiteral(":/drivedesk/alarms/%1.json").arg(familyId(family));
}

QString AlarmDictionary::userFilePath(Family family)
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
        + QStringLiteral("/alarms/%1.json").arg(familyId(family));
}

const AlarmDictionary &AlarmDictionary::bundled(Family family)
{
    static const QHash<Family, AlarmDictionary> all = [] {
        QHash<Family, AlarmDictionary> dictionaries;
        for (Family f : allFamilies()) {
            AlarmDictionary d;
            if (const Error e = d.loadBundled(f))
                qCCritical(lcParams) << "bundled alarm table of" << familyId(f) << "is broken:" << e.message;
            dictionaries.insert(f, d);
        }
        return dictionaries;
    }();
    return *all.constFind(family);
}

Error AlarmDictionary::loadBundled(Family family)
{
    ensureCoreResources();
    return loadFromFile(resourcePath(family), family);
}

Error AlarmDictionary::loadFromFile(const QString &path, std::optional<Family> expectedFamily)
{
    QByteArray data;
    if (Error e = JsonFieldReader::readFile(path, MaxFileSize, &data))
        return e;
    return loadFromJson(data, QFileInfo(path).fileName(), expectedFamily);
}

Error AlarmDictionary::loadForFamily(Family family)
{
    const QString user = userFilePath(family);
    Error userError;
    if (QFileInfo::exists(user)) {
        userError = loadFromFile(user, family);
        if (!userError)
            return Error::none();
        qCWarning(lcParams) << "ignoring the user's alarm table:" << userError.message;
    }
    if (Error e = loadBundled(family))
        return e;
    return userError;
}

Error AlarmDictionary::loadFromJson(const QByteArray &json, const QString &source, std::optional<Family> expectedFamily)
{
    QJsonObject root;
    if (Error e = JsonFieldReader::parseObject(json, source, &root))
        return e;
    JsonFieldReader r(root, source);
    r.checkKnownFields({QStringLiteral("format"), QStringLiteral("formatVersion"), QStringLiteral("family"),
                        QStringLiteral("description"), QStringLiteral("fallback"), QStringLiteral("alarms")});
    const auto format = r.string(QStringLiteral("format"), 64);
    if (format && *format != formatName()) {
        return Error{
            ErrorCode::Malformed,
            tr("%1 is not a DriveDesk alarm table (format \"%2\", expected \"%3\")").arg(source, *format, formatName())};
    }
    const auto version = r.integer(QStringLiteral("formatVersion"));
    if (version && *version != FormatVersion) {
        return Error{ErrorCode::NotSupported,
                     tr("%1: alarm table format version %2 is not supported (this DriveDesk reads version %3)")
                         .arg(source, QString::number(*version), QString::number(FormatVersion))};
    }
    const auto familyText = r.string(QStringLiteral("family"), 64);
    std::optional<Family> family;
    if (familyText) {
        family = familyFromId(*familyText);
        if (!family) {
            return Error{ErrorCode::NotSupported,
                         tr("%1: unknown drive family \"%2\" (known: %3)")
                             .arg(source, *familyText, familyIds().join(QStringLiteral(", ")))};
        }
        if (expectedFamily && *family != *expectedFamily) {
            return Error{ErrorCode::InvalidArgument,
                         tr("%1 is an alarm table for %2 drives, not for %3")
                             .arg(source, familyId(*family), familyId(*expectedFamily))};
        }
    }
    r.localized(QStringLiteral("description"), 4000, JsonFieldReader::Optional);
    auto fallback = r.localized(QStringLiteral("fallback"), 200, JsonFieldReader::Optional);
    const auto entries = r.array(QStringLiteral("alarms"), MaxAlarms);
    if (!r.ok())
        return r.error();
    if (fallback) {
        for (const QString &language : fallback->languages()) {
            if (!fallback->text(language).contains(QLatin1String("%1"))) {
                return Error{ErrorCode::Malformed,
                             tr("%1: field \"fallback.%2\" must contain %3 where the code goes")
                                 .arg(source, language, QStringLiteral("%1"))};
            }
        }
    } else {
        fallback = LocalizedText(QStringLiteral("Alarm %1"), QStringLiteral("报警 %1"));
    }

    QMap<qint64, Alarm> alarms;
    for (int i = 0; i < entries->size(); ++i) {
        const QString where = QStringLiteral("%1: alarms[%2]").arg(source, QString::number(i));
        const QJsonValue v = entries->at(i);
        if (!v.isObject()) {
            return Error{ErrorCode::Malformed,
                         tr("%1 must be an object (found %2)").arg(where, JsonFieldReader::jsonTypeName(v))};
        }
        JsonFieldReader e(v.toObject(), where);
        e.checkKnownFields({QStringLiteral("code"), QStringLiteral("text"), QStringLiteral("remedy")});
        const auto code = e.integerIn(QStringLiteral("code"), std::numeric_limits<qint32>::min(),
                                      std::numeric_limits<qint32>::max());
        const auto text = e.localized(QStringLiteral("text"), 500);
        const auto remedy = e.localized(QStringLiteral("remedy"), 4000, JsonFieldReader::Optional);
        if (!e.ok())
            return e.error();
        if (alarms.contains(*code)) {
            return Error{ErrorCode::Malformed, tr("%1: code %2 is listed twice").arg(where, QString::number(*code))};
        }
        alarms.insert(*code, Alarm{*code, *text, remedy.value_or(LocalizedText())});
    }

    m_loaded = true;
    m_family = *family;
    m_fallback = *fallback;
    m_alarms = alarms;
    return Error::none();
}

const AlarmDictionary::Alarm *AlarmDictionary::alarm(qint64 code) const
{
    const auto it = m_alarms.constFind(code);
    return it == m_alarms.constEnd() ? nullptr : &*it;
}

QString AlarmDictionary::text(qint64 code, const QLocale &locale) const
{
    if (const Alarm *a = alarm(code))
        return a->text.text(locale);
    if (!m_fallback.isEmpty())
        return m_fallback.text(locale).arg(code);
    return tr("Alarm %1").arg(code);
}

QString AlarmDictionary::remedy(qint64 code, const QLocale &locale) const
{
    const Alarm *a = alarm(code);
    return a && !a->remedy.isEmpty() ? a->remedy.text(locale) : QString();
}

} // namespace dd
