#pragma once

#include "core/report/commissioningrecord.h"

#include <QByteArray>
#include <QString>

namespace dd {

// The commissioning record as JSON: format "drivedesk-record", version 1
// (docs/record.md, docs/record-schema.json). The bytes are deterministic for a record (keys
// sorted, indented), and their SHA-256 is what the PDF prints, so that paper and file can be
// matched: `sha256sum RECORD.json` gives the same hex.
class RecordJson
{
public:
    static constexpr int FormatVersion = 1;
    static QString formatName(); // "drivedesk-record"

    static QByteArray toJson(const CommissioningRecord &record);
    // Lower-case hex SHA-256 of `json`.
    static QString sha256(const QByteArray &json);
};

} // namespace dd
