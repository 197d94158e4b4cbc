#pragma once

#include "core/common/error.h"
#include "core/params/localizedtext.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>

namespace dd {

// Strict, typed access to the fields of one JSON object of a file DriveDesk reads
// (dictionaries, alarm tables, backups). Every failure produces a translated message that
// names the place (`where`, e.g. "servo-can.json: parameters[4] (P4)") and the field.
// Only the first failure is kept; after it every accessor returns nullopt, so a parser can
// read all fields and check ok() once.
//
// Integers: JSON numbers are read as whole numbers within ±2^53 (the range a double holds
// exactly, see MaxExactInteger); larger magnitudes and fractions are rejected.
class JsonFieldReader
{
    Q_DECLARE_TR_FUNCTIONS(dd::JsonFieldReader)

public:
    enum Presence { Required, Optional };
    static constexpr qint64 MaxExactInteger = 9007199254740992LL; // 2^53

    JsonFieldReader(const QJsonObject &object, const QString &where);

    bool has(const QString &field) const { return m_object.contains(field); }
    std::optional<qint64> integer(const QString &field, Presence presence = Required);
    // integer() plus a range check (message names the range).
    std::optional<qint64> integerIn(const QString &field, qint64 min, qint64 max, Presence presence = Required);
    std::optional<double> number(const QString &field, Presence presence = Required);
    std::optional<QString> string(const QString &field, int maxLength, Presence presence = Required,
                                  bool allowEmpty = true);
    std::optional<bool> boolean(const QString &field, Presence presence = Required);
    std::optional<QJsonObject> object(const QString &field, Presence presence = Required);
    std::optional<QJsonArray> array(const QString &field, int maxSize, Presence presence = Required);
    // {"en": "...", "zh": "...", other language codes...}; en and zh required, non-empty.
    std::optional<LocalizedText> localized(const QString &field, int maxLength, Presence presence = Required);
    // Fails on a field not in `allowed`; names starting with '_' are comments and allowed.
    bool checkKnownFields(const QStringList &allowed);

    bool ok() const { return m_error.isEmpty(); }
    QString errorMessage() const { return m_error; }
    Error error() const;               // ErrorCode::Malformed with errorMessage(), or none
    void fail(const QString &message); // keeps only the first failure
    const QString &where() const { return m_where; }

    // Shared helpers of the file readers.
    static QString jsonTypeName(const QJsonValue &value); // "string", "number", ... (untranslated)
    // A whole number within ±2^53, or nullopt (and *problem says why, translated).
    static std::optional<qint64> exactInteger(const QJsonValue &value, QString *problem);
    // Reads a regular file of at most maxSize bytes.
    static Error readFile(const QString &path, qint64 maxSize, QByteArray *out);
    // Parses a JSON document whose top level must be an object.
    static Error parseObject(const QByteArray &json, const QString &source, QJsonObject *out);

private:
    std::optional<QJsonValue> fetch(const QString &field, Presence presence);
    QString prefix(const QString &field) const;

    QJsonObject m_object;
    QString m_where;
    QString m_error;
};

} // namespace dd
