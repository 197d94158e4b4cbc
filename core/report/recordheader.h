#pragma once

#include "core/common/error.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>
#include <QString>

namespace dd {

// What the engineer writes at the top of a commissioning record, and what the tool adds
// (when, which DriveDesk, which computer). A header file (--header FILE.json, the GUI's
// form) holds the engineer's part: {"machine", "customer", "site", "engineer", "notes"},
// each an optional string (docs/record.md). Anything else in the file is refused with the
// reason, and a refused file changes nothing.
struct RecordHeader
{
    Q_DECLARE_TR_FUNCTIONS(dd::RecordHeader)
public:
    static constexpr qint64 MaxFileSize = 64 * 1024;
    static constexpr int MaxFieldLength = 200;
    static constexpr int MaxNotesLength = 4000;

    QString machine; // machine or project name
    QString customer;
    QString site;
    QString engineer;
    QString notes;     // several lines
    QDateTime created; // UTC, whole seconds
    QString toolVersion;
    QString computer;

    // The engineer's fields from a header file; on failure *this is unchanged.
    Error load(const QString &path);
    Error loadFromJson(const QByteArray &json, const QString &sourceName);
    // The engineer's fields as a header file holds them.
    QJsonObject fieldsJson() const;
    // Fills created (now), toolVersion (this build) and computer (the host name).
    void stamp();

    static QStringList fieldNames(); // machine, customer, site, engineer, notes
};

} // namespace dd
