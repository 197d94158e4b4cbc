#pragma once

#include <QCoreApplication>
#include <QString>
#include <optional>

namespace dd {

// A serial port this user may not open ("permission denied"), and what to do about it. On
// Debian, /dev/ttyUSB0 and /dev/ttyS0 belong to the group dialout, which a new user is not in.
struct SerialAccessProblem
{
    Q_DECLARE_TR_FUNCTIONS(dd::SerialAccess)
public:
    QString port;
    QString group;              // the device's group when the group may read and write it, else empty
    bool alreadyMember = false; // in the group already, but not in this login session

    // "sudo usermod -aG dialout $USER"; empty when no group would help.
    QString command() const;
    // The whole advice, translated: what is wrong, the command, then log in again.
    QString message() const;
};

// Asks the system whether this user may read and write `port` (access(2), without opening
// it). Returns the problem when it says "permission denied", nothing otherwise (a port that
// does not exist, or that another program holds, is not a permission problem). The open
// error paths of the serial links call it to replace their message.
std::optional<SerialAccessProblem> serialAccessProblem(const QString &port);

} // namespace dd
