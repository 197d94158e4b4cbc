#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/params/parameterset.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <optional>

namespace dd {

class ParameterDictionary;

// A drive's parameter set saved to a file: the "drivedesk-backup" JSON format, version 1
// (docs/backup-format.md, docs/backup-schema.json). Saving is atomic (QSaveFile); loading
// validates everything — structure, types, checksum, family, indices, ranges — before it
// changes the object, and reports the first problem as a typed, translated Error.
class BackupFile
{
    Q_DECLARE_TR_FUNCTIONS(dd::BackupFile)

public:
    static constexpr qint64 MaxFileSize = 4 * 1024 * 1024;
    static constexpr int FormatVersion = 1;
    static constexpr int MaxParameters = 65536;
    static constexpr int MaxLinkEntries = 32;
    static QString formatName(); // "drivedesk-backup"
    // The value of the optional root field "scope" of a file that holds only the parameters
    // changed from the dictionary's defaults (absent or "all": a full backup).
    static QString changedOnlyScope(); // "changed-from-defaults"

    BackupFile(); // toolVersion = this build, created = now

    QString toolVersion() const { return m_toolVersion; }
    void setToolVersion(const QString &version) { m_toolVersion = version; }
    QDateTime created() const { return m_created; } // UTC, whole seconds
    void setCreated(const QDateTime &time);
    std::optional<Family> family() const { return m_family; }
    void setFamily(Family family) { m_family = family; }
    int address() const { return m_address; } // 0..255
    void setAddress(int address) { m_address = address; }
    QString firmware() const { return m_firmware; } // "" when the family has none / unknown
    void setFirmware(const QString &firmware) { m_firmware = firmware; }
    QString model() const { return m_model; } // "" when unknown
    void setModel(const QString &model) { m_model = model; }
    // Free-form link settings, scalar values only: e.g. {"port": "COM3", "baud": 19200,
    // "framing": "8N1"} or {"can": "can0", "bitrate": 1000000}.
    QJsonObject link() const { return m_link; }
    void setLink(const QJsonObject &link) { m_link = link; }
    // Values with source Unknown are not saved; a loaded file's write-only values have
    // source LastWritten, all others ReadFromDrive.
    const ParameterSet &values() const { return m_values; }
    void setValues(const ParameterSet &values) { m_values = values; }
    // Only the parameters that differ from the dictionary's defaults (saved as "scope":
    // "changed-from-defaults"): a restore of it touches only those.
    bool isChangedOnly() const { return m_changedOnly; }
    void setChangedOnly(bool changedOnly) { m_changedOnly = changedOnly; }

    // The file's bytes. Fails (nothing produced) when the family is unset, the address is
    // outside 0..255, or a value is not in the dictionary or outside its range.
    Error toJson(const ParameterDictionary &dictionary, QByteArray *out) const;
    Error save(const QString &path, const ParameterDictionary &dictionary) const;
    Error save(const QString &path) const; // with the bundled dictionary of family()

    // `dictionary` null: the bundled dictionary of the file's family.
    Error load(const QString &path, const ParameterDictionary *dictionary = nullptr);
    Error loadFromJson(const QByteArray &json, const QString &sourceName,
                       const ParameterDictionary *dictionary = nullptr);

    // May this file be restored to that drive? Another family: never. Another firmware (or
    // one side unknown while the other is known): only with force.
    Error checkCompatible(Family targetFamily, const QString &targetFirmware, bool force) const;

    // "index=value\n" for every known value, ascending index, decimal ASCII.
    static QByteArray canonicalValues(const ParameterSet &values);
    // "sha256:" + lower-case hex SHA-256 of canonicalValues().
    static QString checksum(const ParameterSet &values);

private:
    Error parse(const QJsonObject &root, const QString &source, const ParameterDictionary *dictionary);

    QString m_toolVersion;
    QDateTime m_created;
    std::optional<Family> m_family;
    int m_address = 0;
    QString m_firmware;
    QString m_model;
    QJsonObject m_link;
    ParameterSet m_values;
    bool m_changedOnly = false;
};

} // namespace dd
