#pragma once

#include <QString>
#include <QStringList>
#include <optional>

namespace dd {

// The three drive families DriveDesk speaks. The string ids are part of the CLI surface,
// the backup-file format and the dictionaries: never change them.
enum class Family { ServoCan, ServoModbus, Shuoke };

QString familyId(Family family);                       // "servo-can", "servo-modbus", "shuoke"
std::optional<Family> familyFromId(const QString &id); // case-insensitive
QStringList familyIds();
QList<Family> allFamilies();

} // namespace dd
