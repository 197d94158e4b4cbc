#include "core/params/jsonfieldreader.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QRegularExpression>

#include <cmath>
#include <limits>

namespace dd {

JsonFieldReader::JsonFieldReader(const QJsonObject &object, const QString &where)
    : m_object(object)
    , m_where(where)
{
}

QString JsonFieldReader::prefix(const QString &field) const
{
    return tr("%1: field \"%2\"").arg(m_where, field);
}

void JsonFieldReader::fail(const QString &message)
{
    if (m_error.isEmpty())
        m_error = message;
}

Error JsonFieldReader::error() const
{
    if (ok())
        return Error::none();
    return Error{ErrorCode::Malformed, m_error};
}

QString JsonFieldReader::jsonTypeName(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null: return QStringLiteral("null");
    case QJsonValue::Bool: return QStringLiteral("boolean");
    case QJsonValue::Double: return QStringLiteral("number");
    case QJsonValue::String: return QStringLiteral("string");
    case QJsonValue::Array: return QStringLiteral("array");
    case QJsonValue::Object: return QStringLiteral("object");
    case QJsonValue::Undefined: break;
    }
    return QStringLiteral("undefined");
}

std::optional<qint64> JsonFieldReader::exactInteger(const QJsonValue &value, QString *problem)
{
    if (!value.isDouble()) {
        *problem = tr("must be an integer (found %1)").arg(jsonTypeName(value));
        return std::nullopt;
    }
    const double d = value.toDouble();
    const qint64 notInteger = std::numeric_limits<qint64>::min(); // never a valid value here
    const qint64 i = value.toInteger(notInteger);
    if (!std::isfinite(d) || std::fabs(d) > double(MaxExactInteger)
        || (i != notInteger && (i > MaxExactInteger || i < -MaxExactInteger))) {
        *problem = tr("holds a number too large to be exact (the limit is ±%1)").arg(MaxExactInteger);
        return std::nullopt;
    }
    if (i == notInteger) {
        *problem = tr("must be a whole number (found %1)").arg(d, 0, 'g', 17);
        return std::nullopt;
    }
    return i;
}

std::optional<QJsonValue> JsonFieldReader::fetch(const QString &field, Presence presence)
{
    if (!ok())
        return std::nullopt;
    const auto it = m_object.constFind(field);
    if (it == m_object.constEnd()) {
        if (presence == Required)
            fail(tr("%1: required field \"%2\" is missing").arg(m_where, field));
        return std::nullopt;
    }
    return it.value();
}

std::optional<qint64> JsonFieldReader::integer(const QString &field, Presence presence)
{
    const auto v = fetch(field, presence);
    if (!v)
        return std::nullopt;
    QString problem;
    const auto i = exactInteger(*v, &problem);
    if (!i)
        fail(prefix(field) + QLatin1Char(' ') + problem);
    return i;
}

std::optional<qint64> JsonFieldReader::integerIn(const QString &field, qint64 min, qint64 max, Presence presence)
{
    const auto i = integer(field, presence);
    if (i && (*i < min || *i > max)) {
        fail(tr("%1 = %2 is outside the allowed range %3 to %4")
                 .arg(prefix(field), QString::number(*i), QString::number(min), QString::number(max)));
        return std::nullopt;
    }
    return i;
}

std::optional<double> JsonFieldReader::number(const QString &field, Presence presence)
{
    const auto v = fetch(field, presence);
    if (!v)
        return std::nullopt;
    const double d = v->toDouble();
    if (!v->isDouble()) {
        fail(prefix(field) + QLatin1Char(' ') + tr("must be a number (found %1)").arg(jsonTypeName(*v)));
        return std::nullopt;
    }
    if (!std::isfinite(d) || std::fabs(d) > double(MaxExactInteger)) {
        fail(prefix(field) + QLatin1Char(' ')
             + tr("holds a number too large to be exact (the limit is ±%1)").arg(MaxExactInteger));
        return std::nullopt;
    }
    return d;
}

std::optional<QString> JsonFieldReader::string(const QString &field, int maxLength, Presence presence, bool allowEmpty)
{
    const auto v = fetch(field, presence);
    if (!v)
        return std::nullopt;
    if (!v->isString()) {
        fail(prefix(field) + QLatin1Char(' ') + tr("must be a string (found %1)").arg(jsonTypeName(*v)));
        return std::nullopt;
    }
    const QString s = v->toString();
    if (s.size() > maxLength) {
        fail(prefix(field) + QLatin1Char(' ') + tr("is longer than %1 characters").arg(maxLength));
        return std::nullopt;
    }
    if (!allowEmpty && s.trimmed().isEmpty()) {
        fail(prefix(field) + QLatin1Char(' ') + tr("must not be empty"));
        return std::nullopt;
    }
    return s;
}

std::optional<bool> JsonFieldReader::boolean(const QString &field, Presence presence)
{
    const auto v = fetch(field, presence);
    if (!v)
        return std::nullopt;
    if (!v->isBool()) {
        fail(prefix(field) + QLatin1Char(' ') + tr("must be true or false (found %1)").arg(jsonTypeName(*v)));
        return std::nullopt;
    }
    return v->toBool();
}

std::optional<QJsonObject> JsonFieldReader::object(const QString &field, Presence presence)
{
    const auto v = fetch(field, presence);
    if (!v)
        return std::nullopt;
    if (!v->isObject()) {
        fail(prefix(field) + QLatin1Char(' ') + tr("must be an object (found %1)").arg(jsonTypeName(*v)));
        return std::nullopt;
    }
    return v->toObject();
}

std::optional<QJsonArray> JsonFieldReader::array(const QString &field, int maxSize, Presence presence)
{
    const auto v = fetch(field, presence);
    if (!v)
        return std::nullopt;
    if (!v->isArray()) {
        fail(prefix(field) + QLatin1Char(' ') + tr("must be an array (found %1)").arg(jsonTypeName(*v)));
        return std::nullopt;
    }
    const QJsonArray a = v->toArray();
    if (a.size() > maxSize) {
        fail(prefix(field) + QLatin1Char(' ') + tr("has more than %1 entries").arg(maxSize));
        return std::nullopt;
    }
    return a;
}

std::optional<LocalizedText> JsonFieldReader::localized(const QString &field, int maxLength, Presence presence)
{
    const auto o = object(field, presence);
    if (!o)
        return std::nullopt;
    static const QRegularExpression languageCode(QStringLiteral("^[a-z]{2,3}(_[A-Z]{2})?$"));
    LocalizedText text;
    for (auto it = o->constBegin(); it != o->constEnd(); ++it) {
        const QString sub = QStringLiteral("%1.%2").arg(field, it.key());
        if (!languageCode.match(it.key()).hasMatch()) {
            fail(tr("%1: \"%2\" is not a language code (use e.g. \"en\", \"zh\", \"zh_CN\")")
                     .arg(prefix(field), it.key()));
            return std::nullopt;
        }
        if (!it.value().isString()) {
            fail(prefix(sub) + QLatin1Char(' ') + tr("must be a string (found %1)").arg(jsonTypeName(it.value())));
            return std::nullopt;
        }
        const QString s = it.value().toString();
        if (s.size() > maxLength) {
            fail(prefix(sub) + QLatin1Char(' ') + tr("is longer than %1 characters").arg(maxLength));
            return std::nullopt;
        }
        text.set(it.key(), s);
    }
    for (const char *required : {"en", "zh"}) {
        const QString language = QLatin1String(required);
        if (text.text(language).trimmed().isEmpty()) {
            fail(tr("%1 needs a non-empty \"%2\" text").arg(prefix(field), language));
            return std::nullopt;
        }
    }
    return text;
}

bool JsonFieldReader::checkKnownFields(const QStringList &allowed)
{
    if (!ok())
        return false;
    for (auto it = m_object.constBegin(); it != m_object.constEnd(); ++it) {
        if (it.key().startsWith(QLatin1Char('_')) || allowed.contains(it.key()))
            continue;
        fail(tr("%1: unknown field \"%2\"").arg(m_where, it.key()));
        return false;
    }
    return true;
}

Error JsonFieldReader::readFile(const QString &path, qint64 maxSize, QByteArray *out)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return Error{ErrorCode::FileError,
                     tr("Cannot open %1: %2").arg(QDir::toNativeSeparators(path), file.errorString())};
    }
    // Read at most maxSize + 1 bytes: works for files whose size() is unknown, too.
    const QByteArray data = file.read(maxSize + 1);
    if (file.error() != QFileDevice::NoError) {
        return Error{ErrorCode::FileError,
                     tr("Cannot read %1: %2").arg(QDir::toNativeSeparators(path), file.errorString())};
    }
    if (data.size() > maxSize) {
        return Error{ErrorCode::FileError,
                     tr("%1 is larger than %2 bytes; it is not a file DriveDesk wrote")
                         .arg(QDir::toNativeSeparators(path), QString::number(maxSize))};
    }
    *out = data;
    return Error::none();
}

Error JsonFieldReader::parseObject(const QByteArray &json, const QString &source, QJsonObject *out)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const bool atEnd = parseError.offset >= json.size() - 1;
        const QString hint = (json.trimmed().isEmpty() || atEnd) ? tr(" (is the file empty or truncated?)") : QString();
        return Error{ErrorCode::Malformed,
                     tr("%1 is not valid JSON: %2 at byte %3%4")
                         .arg(source, parseError.errorString(), QString::number(parseError.offset), hint)};
    }
    if (!doc.isObject()) {
        return Error{ErrorCode::Malformed, tr("%1: the top level must be a JSON object").arg(source)};
    }
    *out = doc.object();
    return Error::none();
}

} // namespace dd
