#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/params/localizedtext.h"
#include "core/params/parameterinfo.h"
#include "core/params/tuningentry.h"

#include <QCoreApplication>
#include <QHash>
#include <QLocale>
#include <QVector>
#include <optional>

namespace dd {

// The parameters of one drive family: names (English, Chinese), units, ranges, access.
// Bundled dictionaries live at :/drivedesk/dictionaries/<family>.json; users may supply
// their own (docs/dictionaries.md). Loading validates the whole file and reports the first
// problem naming the entry and the field; a failed load leaves the dictionary unchanged.
class ParameterDictionary
{
    Q_DECLARE_TR_FUNCTIONS(dd::ParameterDictionary)

public:
    static constexpr qint64 MaxFileSize = 4 * 1024 * 1024;
    static constexpr int MaxIndex = 65535;
    static constexpr int FormatVersion = 1;
    static QString formatName(); // "drivedesk-dictionary"

    ParameterDictionary() = default;

    static QString resourcePath(Family family); // ":/drivedesk/dictionaries/<family>.json"
    // <AppDataLocation>/dictionaries/<family>.json: a user's dictionary that replaces the
    // bundled one (loadForFamily()).
    static QString userFilePath(Family family);
    // The bundled dictionary of a family, loaded once (thread-safe).
    static const ParameterDictionary &bundled(Family family);
    // ":/drivedesk/dictionaries/simulator/<family>.json": the family's dictionary as
    // DriveDesk's simulator answers it, naming the simulator's own loop-gain parameters in
    // its "tuning" group (docs/tuning.md). Empty path when the family has none.
    static QString simulatorResourcePath(Family family);
    // That dictionary, loaded once (thread-safe); the family's bundled one when it has none.
    static const ParameterDictionary &bundledSimulator(Family family);

    Error loadBundled(Family family);
    Error loadFromFile(const QString &path, std::optional<Family> expectedFamily = std::nullopt);
    Error loadFromJson(const QByteArray &json, const QString &sourceName,
                       std::optional<Family> expectedFamily = std::nullopt);
    // The user's file if one exists at userFilePath(), else the bundled dictionary. When the
    // user's file is invalid the bundled dictionary is loaded and the user file's error is
    // returned, so that the caller can warn.
    Error loadForFamily(Family family);

    bool isEmpty() const { return m_parameters.isEmpty(); }
    int size() const { return m_parameters.size(); }
    Family family() const { return m_family; } // meaningful when !isEmpty()
    QString sourceName() const { return m_source; }
    LocalizedText description() const { return m_description; }
    const QVector<ParameterInfo> &parameters() const { return m_parameters; } // ascending index
    QList<int> indices() const;
    // The "tuning" group: the parameters that tune the drive's loops, with their roles, in
    // the dictionary's order. Empty when the dictionary names none.
    const QVector<TuningEntry> &tuning() const { return m_tuning; }
    QString roleOf(int index) const;            // "" when the parameter has no tuning role
    int indexOfRole(const QString &role) const; // -1 when no parameter plays it

    const ParameterInfo *byIndex(int index) const;
    const ParameterInfo *byKey(const QString &key) const; // case-insensitive
    // English, Chinese or any other language's name, case-insensitive; nullptr when unknown
    // or when two parameters share the name.
    const ParameterInfo *byName(const QString &name) const;
    // What a user types: a key ("PA12", "start-speed"), a number ("12", "0x25"), a number
    // with a P / PA prefix ("P12", "pa12"), or a name. Keys win over numbers over names.
    const ParameterInfo *find(const QString &text) const;
    // find() with a translated error.
    Error resolve(const QString &text, int *index) const;
    // Each item may hold several comma-separated references ("P4,P75"). Duplicates are
    // dropped; the order is kept.
    Error resolveList(const QStringList &items, QList<int> *indices) const;

    // OutOfRange with a translated message naming the parameter and its allowed range;
    // InvalidArgument for an index not in the dictionary.
    Error validateValue(int index, qint64 value) const;
    // validateValue() that also refuses read-only parameters (NotSupported).
    Error validateWrite(int index, qint64 value) const;

    // The parameter's name in `locale`'s language (English fallback); "P<n>" when unknown.
    QString displayName(int index, const QLocale &locale = QLocale()) const;
    // "PA51 Drive address" — key and name, as lists and messages show a parameter.
    QString label(int index, const QLocale &locale = QLocale()) const;

private:
    Error parse(const QJsonObject &root, const QString &source, std::optional<Family> expected);
    Error parseTuning(const QJsonArray &group, const QString &source);
    void rebuildIndexes();

    Family m_family = Family::ServoCan;
    QString m_source;
    LocalizedText m_description;
    QVector<ParameterInfo> m_parameters;
    QVector<TuningEntry> m_tuning;
    QHash<int, int> m_byIndex;    // index -> position
    QHash<QString, int> m_byKey;  // lower-case key -> position
    QHash<QString, int> m_byName; // case-folded name -> position, -1 when ambiguous
};

} // namespace dd
