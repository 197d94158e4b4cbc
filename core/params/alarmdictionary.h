#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/params/localizedtext.h"

#include <QCoreApplication>
#include <QLocale>
#include <QMap>
#include <optional>

namespace dd {

// Alarm code -> text (English, Chinese) for one drive family. Bundled tables live at
// :/drivedesk/alarms/<family>.json; the seeds name no alarm codes beyond "0 = no alarm",
// so an unnamed code reads "Alarm N" (the file's fallback template). Users may supply their
// own table (docs/dictionaries.md).
class AlarmDictionary
{
    Q_DECLARE_TR_FUNCTIONS(dd::AlarmDictionary)

public:
    static constexpr qint64 MaxFileSize = 4 * 1024 * 1024;
    static constexpr int FormatVersion = 1;
    static constexpr int MaxAlarms = 65536;
    static QString formatName(); // "drivedesk-alarms"

    struct Alarm
    {
        qint64 code = 0;
        LocalizedText text;
        LocalizedText remedy; // optional: what to check
    };

    AlarmDictionary() = default;

    static QString resourcePath(Family family); // ":/drivedesk/alarms/<family>.json"
    static QString userFilePath(Family family); // <AppDataLocation>/alarms/<family>.json
    static const AlarmDictionary &bundled(Family family);

    Error loadBundled(Family family);
    Error loadFromFile(const QString &path, std::optional<Family> expectedFamily = std::nullopt);
    Error loadFromJson(const QByteArray &json, const QString &sourceName,
                       std::optional<Family> expectedFamily = std::nullopt);
    // The user's file if present and valid, else the bundled one (the user file's error is
    // returned so that the caller can warn).
    Error loadForFamily(Family family);

    bool isLoaded() const { return m_loaded; }
    Family family() const { return m_family; }
    int size() const { return m_alarms.size(); }
    bool contains(qint64 code) const { return m_alarms.contains(code); }
    QList<qint64> codes() const { return m_alarms.keys(); }
    const Alarm *alarm(qint64 code) const;

    // The alarm's text in `locale`'s language; for a code without an entry the fallback
    // template with the code filled in ("Alarm 12" / "报警 12").
    QString text(qint64 code, const QLocale &locale = QLocale()) const;
    QString remedy(qint64 code, const QLocale &locale = QLocale()) const; // "" when none

private:
    bool m_loaded = false;
    Family m_family = Family::ServoCan;
    LocalizedText m_fallback;
    QMap<qint64, Alarm> m_alarms;
};

} // namespace dd
