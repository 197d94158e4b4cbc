#pragma once

#include "core/common/family.h"
#include "core/params/parameterset.h"

#include <QCoreApplication>
#include <QString>

namespace dd {

class BackupFile;
class ParameterDictionary;

// One column of a comparison: a drive's values as read, a backup file's, or the
// dictionary's defaults, with what is known about where they came from.
struct ParameterSource
{
    Q_DECLARE_TR_FUNCTIONS(dd::ParameterSource)
public:
    enum class Kind { Drive, File, Defaults };

    Kind kind = Kind::Defaults;
    Family family = Family::ServoModbus;
    QString label;    // "drive 3", "axis1.json", "defaults" (translated, for people)
    QString id;       // stable, for scripts: "drive:3", the file's path, "defaults"
    int address = -1; // drives and files: the address (a file's: where it was read from)
    QString firmware; // "" when unknown or none
    QString model;
    bool changedOnly = false; // a changed-only file, completed with the defaults
    ParameterSet values;

    static ParameterSource defaults(const ParameterDictionary &dictionary);
    // A changed-only file's left-out parameters count as their default.
    static ParameterSource file(const BackupFile &file, const QString &path, const ParameterDictionary &dictionary);
    static ParameterSource drive(Family family, int address, const QString &firmware, const QString &model,
                                 const ParameterSet &values);
    static QString kindId(Kind kind); // "drive", "file", "defaults"
};

} // namespace dd
