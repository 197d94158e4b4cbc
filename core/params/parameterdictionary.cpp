#include "core/params/parameterdictionary.h"
#include "core/protocol/familytraits.h"

#include "core/common/coreresources.h"
#include "core/params/jsonfieldreader.h"
#include "core/params/paramslog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>

namespace dd {

namespace {

const QRegularExpression &keyPattern()
{
    static const QRegularExpression re(QStringLiteral("^[A-Za-z][A-Za-z0-9_.-]{0,63}$"));
    return re;
}

// "P12", "PA12", "p12", "12" (and the same with spaces after the prefix).
const QRegularExpression &numberPattern()
{
    static const QRegularExpression re(QStringLiteral("^(?:pa|p)?\\s*([0-9]{1,6})$"),
                                       QRegularExpression::CaseInsensitiveOption);
    return re;
}

const QRegularExpression &hexPattern()
{
    static const QRegularExpression re(QStringLiteral("^0x([0-9a-f]{1,4})$"),
                                       QRegularExpression::CaseInsensitiveOption);
    return re;
}

} // namespace

QString ParameterDictionary::formatName()
{
    return QStringLiteral("drivedesk-dictionary");
}

QString ParameterDictionary::resourcePath(Family family)
{
    return QStringLiteral(":/drivedesk/dictionaries/%1.json").arg(familyId(family));
}

QString ParameterDictionary::userFilePath(Family family)
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
        + QStringLiteral("/dictionaries/%1.json").arg(familyId(family));
}

const ParameterDictionary &ParameterDictionary::bundled(Family family)
{
    static const QHash<Family, ParameterDictionary> all = [] {
        QHash<Family, ParameterDictionary> dictionaries;
        for (Family f : allFamilies()) {
            ParameterDictionary d;
            const Error e = d.loadBundled(f);
            if (e)
                qCCritical(lcParams) << "bundled dictionary of" << familyId(f) << "is broken:" << e.message;
            dictionaries.insert(f, d);
        }
        return dictionaries;
    }();
    return *all.constFind(family);
}

Error ParameterDictionary::loadBundled(Family family)
{
    ensureCoreResources();
    return loadFromFile(resourcePath(family), family);
}

QString ParameterDictionary::simulatorResourcePath(Family family)
{
    ensureCoreResources();
    const QString path = QStringLiteral(":/drivedesk/dictionaries/simulator/%1.json").arg(familyId(family));
    return QFileInfo::exists(path) ? path : QString();
}

const ParameterDictionary &ParameterDictionary::bundledSimulator(Family family)
{
    static const QHash<Family, ParameterDictionary> all = [] {
        QHash<Family, ParameterDictionary> dictionaries;
        for (Family f : allFamilies()) {
            ParameterDictionary d;
            const QString path = simulatorResourcePath(f);
            if (path.isEmpty()) {
                d = bundled(f);
            } else if (const Error e = d.loadFromFile(path, f)) {
                qCCritical(lcParams) << "bundled simulator dictionary of" << familyId(f) << "is broken:" << e.message;
                d = bundled(f);
            }
            dictionaries.insert(f, d);
        }
        return dictionaries;
    }();
    return *all.constFind(family);
}

Error ParameterDictionary::loadFromFile(const QString &path, std::optional<Family> expectedFamily)
{
    QByteArray data;
    if (Error e = JsonFieldReader::readFile(path, MaxFileSize, &data))
        return e;
    return loadFromJson(data, QFileInfo(path).fileName(), expectedFamily);
}

Error ParameterDictionary::loadFromJson(const QByteArray &json, const QString &sourceName,
                                        std::optional<Family> expectedFamily)
{
    QJsonObject root;
    if (Error e = JsonFieldReader::parseObject(json, sourceName, &root))
        return e;
    ParameterDictionary parsed;
    if (Error e = parsed.parse(root, sourceName, expectedFamily))
        return e;
    *this = parsed;
    return Error::none();
}

Error ParameterDictionary::loadForFamily(Family family)
{
    const QString user = userFilePath(family);
    Error userError;
    if (QFileInfo::exists(user)) {
        userError = loadFromFile(user, family);
        if (!userError) {
            qCInfo(lcParams) << "using the user's dictionary" << user;
            return Error::none();
        }
        qCWarning(lcParams) << "ignoring the user's dictionary:" << userError.message;
    }
    if (Error e = loadBundled(family))
        return e;
    return userError;
}

static std::optional<ParameterInfo> parseEntry(const QJsonValue &value, int position, const QString &source,
                                               Family family, ValueType defaultType, QString *error)
{
    QString where = QStringLiteral("%1: parameters[%2]").arg(source, QString::number(position));
    if (!value.isObject()) {
        *error = ParameterDictionary::tr("%1 must be an object (found %2)")
                     .arg(where, JsonFieldReader::jsonTypeName(value));
        return std::nullopt;
    }
    const QJsonObject o = value.toObject();
    // Name the entry by its key as early as possible, so that every message says which one.
    if (o.value(QStringLiteral("key")).isString())
        where += QStringLiteral(" (%1)").arg(o.value(QStringLiteral("key")).toString().left(64));
    JsonFieldReader r(o, where);
    r.checkKnownFields({QStringLiteral("index"), QStringLiteral("key"), QStringLiteral("name"),
                        QStringLiteral("description"), QStringLiteral("unit"), QStringLiteral("type"),
                        QStringLiteral("min"), QStringLiteral("max"), QStringLiteral("default"),
                        QStringLiteral("access"), QStringLiteral("readCommand"), QStringLiteral("register"),
                        QStringLiteral("communication"), QStringLiteral("models")});
    ParameterInfo p;
    const auto index = r.integerIn(QStringLiteral("index"), 0, ParameterDictionary::MaxIndex);
    const auto key = r.string(QStringLiteral("key"), 64, JsonFieldReader::Required, false);
    if (key && index && r.ok()) {
        if (!keyPattern().match(*key).hasMatch()) {
            r.fail(ParameterDictionary::tr("%1: key \"%2\" must start with a letter and hold only letters, "
                                           "digits, '_', '.' and '-'")
                       .arg(where, *key));
        } else {
            const auto m = numberPattern().match(*key);
            if (m.hasMatch() && m.captured(1).toInt() != *index)
                r.fail(ParameterDictionary::tr("%1: key \"%2\" names parameter %3 but the index is %4")
                           .arg(where, *key, m.captured(1), QString::number(*index)));
        }
    }
    const auto name = r.localized(QStringLiteral("name"), 200);
    const auto description = r.localized(QStringLiteral("description"), 4000);
    const auto unit = r.string(QStringLiteral("unit"), 32);
    const auto typeId = r.string(QStringLiteral("type"), 16, JsonFieldReader::Optional);
    ValueType type = defaultType;
    if (typeId && r.ok()) {
        if (const auto t = valueTypeFromId(*typeId))
            type = *t;
        else
            r.fail(ParameterDictionary::tr("%1: field \"type\" = \"%2\" is not one of uint8, int16, uint16, "
                                           "int32, uint32")
                       .arg(where, *typeId));
    }
    const auto min = r.integer(QStringLiteral("min"));
    const auto max = r.integer(QStringLiteral("max"));
    const auto defaultValue = r.integer(QStringLiteral("default"), JsonFieldReader::Optional);
    const auto accessText = r.string(QStringLiteral("access"), 2);
    const auto readCommand = r.integerIn(QStringLiteral("readCommand"), 0, 255, JsonFieldReader::Optional);
    const auto registerAddress = r.integerIn(QStringLiteral("register"), 0, 65535, JsonFieldReader::Optional);
    const auto communication = r.boolean(QStringLiteral("communication"), JsonFieldReader::Optional);
    const auto models = r.array(QStringLiteral("models"), 32, JsonFieldReader::Optional);
    if (!r.ok()) {
        *error = r.errorMessage();
        return std::nullopt;
    }

    p.index = int(*index);
    p.key = *key;
    p.name = *name;
    p.description = *description;
    p.unit = *unit;
    p.type = type;
    p.min = *min;
    p.max = *max;
    p.defaultValue = defaultValue;
    p.readCommand = readCommand ? int(*readCommand) : -1;
    p.registerAddress = registerAddress ? int(*registerAddress) : -1;
    p.communication = communication.value_or(false);
    const auto access = accessFromId(*accessText);
    if (!access) {
        *error = ParameterDictionary::tr("%1: field \"access\" = \"%2\" is not one of rw, ro, wo")
                     .arg(where, *accessText);
        return std::nullopt;
    }
    p.access = *access;
    if (p.min > p.max) {
        *error = ParameterDictionary::tr("%1: min %2 is greater than max %3")
                     .arg(where, QString::number(p.min), QString::number(p.max));
        return std::nullopt;
    }
    if (p.min < valueTypeMin(type) || p.max > valueTypeMax(type)) {
        *error = ParameterDictionary::tr("%1: the range %2 to %3 does not fit the type %4 (%5 to %6)")
                     .arg(where, QString::number(p.min), QString::number(p.max), valueTypeId(type),
                          QString::number(valueTypeMin(type)), QString::number(valueTypeMax(type)));
        return std::nullopt;
    }
    if (p.defaultValue && !p.inRange(*p.defaultValue)) {
        *error = ParameterDictionary::tr("%1: default %2 is outside the range %3 to %4")
                     .arg(where, QString::number(*p.defaultValue), QString::number(p.min), QString::number(p.max));
        return std::nullopt;
    }
    if (p.access == Access::WriteOnly && p.readCommand >= 0) {
        *error = ParameterDictionary::tr("%1: a write-only parameter cannot have a readCommand").arg(where);
        return std::nullopt;
    }
    const ParameterAddressing addressing = familyTraits(family).parameterAddressing;
    if (addressing == ParameterAddressing::ReadCommand && p.access != Access::WriteOnly && p.readCommand < 0) {
        *error = ParameterDictionary::tr("%1: a readable %2 parameter needs a readCommand").arg(where, familyId(family));
        return std::nullopt;
    }
    if (addressing == ParameterAddressing::Register && p.registerAddress < 0) {
        *error = ParameterDictionary::tr("%1: a %2 parameter needs a register").arg(where, familyId(family));
        return std::nullopt;
    }
    if (models) {
        for (int i = 0; i < models->size(); ++i) {
            const QJsonValue m = models->at(i);
            if (!m.isString() || m.toString().trimmed().isEmpty() || m.toString().size() > 32) {
                *error = ParameterDictionary::tr("%1: models[%2] must be a model name").arg(where, QString::number(i));
                return std::nullopt;
            }
            p.models.append(m.toString());
        }
    }
    return p;
}

Error ParameterDictionary::parse(const QJsonObject &root, const QString &source, std::optional<Family> expected)
{
    JsonFieldReader r(root, source);
    r.checkKnownFields({QStringLiteral("format"), QStringLiteral("formatVersion"), QStringLiteral("family"),
                        QStringLiteral("description"), QStringLiteral("valueType"), QStringLiteral("parameters"),
                        QStringLiteral("tuning")});
    const auto format = r.string(QStringLiteral("format"), 64);
    if (format && *format != formatName()) {
        return Error{ErrorCode::Malformed,
                     tr("%1 is not a DriveDesk parameter dictionary (format \"%2\", "
                        "expected \"%3\")")
                         .arg(source, *format, formatName())};
    }
    const auto version = r.integer(QStringLiteral("formatVersion"));
    if (version && *version != FormatVersion) {
        return Error{ErrorCode::NotSupported,
                     tr("%1: dictionary format version %2 is not supported "
                        "(this DriveDesk reads version %3)")
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
        if (expected && *family != *expected) {
            return Error{
                ErrorCode::InvalidArgument,
                tr("%1 is a dictionary for %2 drives, not for %3").arg(source, familyId(*family), familyId(*expected))};
        }
    }
    const auto description = r.localized(QStringLiteral("description"), 4000, JsonFieldReader::Optional);
    const auto typeText = r.string(QStringLiteral("valueType"), 16);
    std::optional<ValueType> valueType;
    if (typeText) {
        valueType = valueTypeFromId(*typeText);
        if (!valueType)
            r.fail(tr("%1: field \"valueType\" = \"%2\" is not one of uint8, int16, uint16, int32, uint32")
                       .arg(source, *typeText));
    }
    const auto entries = r.array(QStringLiteral("parameters"), MaxIndex + 1);
    const auto tuning = r.array(QStringLiteral("tuning"), 64, JsonFieldReader::Optional);
    if (!r.ok())
        return r.error();
    if (entries->isEmpty())
        return Error{ErrorCode::Malformed, tr("%1: the dictionary has no parameters").arg(source)};

    QHash<int, QString> keyOfIndex;
    QHash<QString, QString> keyOfLowerKey;
    QHash<int, QString> keyOfRegister;
    QVector<ParameterInfo> parameters;
    parameters.reserve(entries->size());
    for (int i = 0; i < entries->size(); ++i) {
        QString message;
        const auto p = parseEntry(entries->at(i), i, source, *family, *valueType, &message);
        if (!p)
            return Error{ErrorCode::Malformed, message};
        const QString where = QStringLiteral("%1: parameters[%2] (%3)").arg(source, QString::number(i), p->key);
        if (keyOfIndex.contains(p->index)) {
            return Error{ErrorCode::Malformed,
                         tr("%1: index %2 is already used by %3")
                             .arg(where, QString::number(p->index), keyOfIndex.value(p->index))};
        }
        const QString lowerKey = p->key.toLower();
        if (keyOfLowerKey.contains(lowerKey)) {
            return Error{ErrorCode::Malformed,
                         tr("%1: key \"%2\" is already used (keys are case-insensitive)")
                             .arg(where, keyOfLowerKey.value(lowerKey))};
        }
        if (p->registerAddress >= 0 && keyOfRegister.contains(p->registerAddress)) {
            return Error{ErrorCode::Malformed,
                         tr("%1: register %2 is already used by %3")
                             .arg(where, QString::number(p->registerAddress), keyOfRegister.value(p->registerAddress))};
        }
        keyOfIndex.insert(p->index, p->key);
        keyOfLowerKey.insert(lowerKey, p->key);
        if (p->registerAddress >= 0)
            keyOfRegister.insert(p->registerAddress, p->key);
        parameters.append(*p);
    }
    std::sort(parameters.begin(), parameters.end(),
              [](const ParameterInfo &a, const ParameterInfo &b) { return a.index < b.index; });

    ParameterDictionary result;
    result.m_family = *family;
    result.m_source = source;
    result.m_description = description.value_or(LocalizedText());
    result.m_parameters = parameters;
    result.rebuildIndexes();
    if (tuning) {
        if (Error e = result.parseTuning(*tuning, source))
            return e;
    }
    *this = result;
    return Error::none();
}

Error ParameterDictionary::parseTuning(const QJsonArray &group, const QString &source)
{
    QHash<QString, int> roleAt;
    QHash<int, int> indexAt;
    for (int i = 0; i < group.size(); ++i) {
        const QString where = QStringLiteral("%1: tuning[%2]").arg(source, QString::number(i));
        if (!group.at(i).isObject())
            return {ErrorCode::Malformed, tr("%1 must be an object with \"key\" and \"role\"").arg(where)};
        JsonFieldReader r(group.at(i).toObject(), where);
        r.checkKnownFields({QStringLiteral("key"), QStringLiteral("role")});
        const auto key = r.string(QStringLiteral("key"), 64);
        const auto role = r.string(QStringLiteral("role"), 64);
        if (!r.ok())
            return r.error();
        const ParameterInfo *p = byKey(*key);
        if (!p)
            return {ErrorCode::Malformed, tr("%1: no parameter has the key \"%2\"").arg(where, *key)};
        if (!p->isReadable())
            return {ErrorCode::Malformed,
                    tr("%1: %2 is write-only; a tuning parameter must be readable").arg(where, p->key)};
        if (!TuningEntry::knownRoles().contains(*role))
            return {ErrorCode::Malformed,
                    tr("%1: unknown role \"%2\" (known: %3)")
                        .arg(where, *role, TuningEntry::knownRoles().join(QStringLiteral(", ")))};
        if (roleAt.contains(*role))
            return {ErrorCode::Malformed,
                    tr("%1: role \"%2\" is already given to tuning[%3]")
                        .arg(where, *role, QString::number(roleAt.value(*role)))};
        if (indexAt.contains(p->index))
            return {ErrorCode::Malformed,
                    tr("%1: %2 is already in tuning[%3]").arg(where, p->key, QString::number(indexAt.value(p->index)))};
        roleAt.insert(*role, i);
        indexAt.insert(p->index, i);
        m_tuning.append({p->index, *role});
    }
    return Error::none();
}

QString ParameterDictionary::roleOf(int index) const
{
    for (const TuningEntry &e : m_tuning)
        if (e.index == index)
            return e.role;
    return {};
}

int ParameterDictionary::indexOfRole(const QString &role) const
{
    for (const TuningEntry &e : m_tuning)
        if (e.role == role)
            return e.index;
    return -1;
}

void ParameterDictionary::rebuildIndexes()
{
    m_byIndex.clear();
    m_byKey.clear();
    m_byName.clear();
    for (int i = 0; i < m_parameters.size(); ++i) {
        const ParameterInfo &p = m_parameters.at(i);
        m_byIndex.insert(p.index, i);
        m_byKey.insert(p.key.toLower(), i);
        QSet<QString> names;
        for (const QString &n : p.name.allTexts())
            names.insert(n.trimmed().toCaseFolded());
        for (const QString &n : names) {
            auto it = m_byName.find(n);
            if (it == m_byName.end())
                m_byName.insert(n, i);
            else if (*it != i)
                *it = -1; // shared by two parameters: ambiguous
        }
    }
}

QList<int> ParameterDictionary::indices() const
{
    QList<int> out;
    out.reserve(m_parameters.size());
    for (const ParameterInfo &p : m_parameters)
        out.append(p.index);
    return out;
}

const ParameterInfo *ParameterDictionary::byIndex(int index) const
{
    const auto it = m_byIndex.constFind(index);
    return it == m_byIndex.constEnd() ? nullptr : &m_parameters.at(*it);
}

const ParameterInfo *ParameterDictionary::byKey(const QString &key) const
{
    const auto it = m_byKey.constFind(key.trimmed().toLower());
    return it == m_byKey.constEnd() ? nullptr : &m_parameters.at(*it);
}

const ParameterInfo *ParameterDictionary::byName(const QString &name) const
{
    const auto it = m_byName.constFind(name.trimmed().toCaseFolded());
    if (it == m_byName.constEnd() || *it < 0)
        return nullptr;
    return &m_parameters.at(*it);
}

const ParameterInfo *ParameterDictionary::find(const QString &text) const
{
    const QString t = text.trimmed();
    if (t.isEmpty())
        return nullptr;
    if (const ParameterInfo *p = byKey(t))
        return p;
    auto m = numberPattern().match(t);
    if (m.hasMatch())
        return byIndex(m.captured(1).toInt());
    m = hexPattern().match(t);
    if (m.hasMatch())
        return byIndex(m.captured(1).toInt(nullptr, 16));
    return byName(t);
}

Error ParameterDictionary::resolve(const QString &text, int *index) const
{
    if (const ParameterInfo *p = find(text)) {
        *index = p->index;
        return Error::none();
    }
    const QString example = isEmpty() ? QStringLiteral("P1") : m_parameters.first().key;
    return Error{ErrorCode::InvalidArgument,
                 tr("Unknown parameter \"%1\" for %2 drives: give a number (12), a key (%3) or a name")
                     .arg(text.trimmed(), familyId(m_family), example)};
}

Error ParameterDictionary::resolveList(const QStringList &items, QList<int> *indices) const
{
    QList<int> out;
    for (const QString &item : items) {
        for (const QString &part : item.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            if (part.trimmed().isEmpty())
                continue;
            int index = -1;
            if (Error e = resolve(part, &index))
                return e;
            if (!out.contains(index))
                out.append(index);
        }
    }
    *indices = out;
    return Error::none();
}

QString ParameterDictionary::displayName(int index, const QLocale &locale) const
{
    if (const ParameterInfo *p = byIndex(index))
        return p->name.text(locale);
    return QStringLiteral("P%1").arg(index);
}

QString ParameterDictionary::label(int index, const QLocale &locale) const
{
    if (const ParameterInfo *p = byIndex(index))
        return QStringLiteral("%1 %2").arg(p->key, p->name.text(locale));
    return QStringLiteral("P%1").arg(index);
}

Error ParameterDictionary::validateValue(int index, qint64 value) const
{
    const ParameterInfo *p = byIndex(index);
    if (!p) {
        return Error{ErrorCode::InvalidArgument,
                     tr("There is no parameter %1 for %2 drives").arg(QString::number(index), familyId(m_family))};
    }
    if (p->inRange(value))
        return Error::none();
    const QString message = p->unit.isEmpty()
        ? tr("%1: %2 is outside the allowed range %3 to %4")
              .arg(label(index), QString::number(value), QString::number(p->min), QString::number(p->max))
        : tr("%1: %2 %5 is outside the allowed range %3 to %4 %5")
              .arg(label(index), QString::number(value), QString::number(p->min), QString::number(p->max), p->unit);
    return Error{ErrorCode::OutOfRange, message};
}

Error ParameterDictionary::validateWrite(int index, qint64 value) const
{
    if (Error e = validateValue(index, value))
        return e;
    const ParameterInfo *p = byIndex(index);
    if (!p->isWritable()) {
        return Error{ErrorCode::NotSupported,
                     tr("%1 is read-only: the drive does not accept a new value").arg(label(index))};
    }
    return Error::none();
}

} // namespace dd
