#include "core/link/serialaccess.h"

#include <QFile>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace dd {

QString SerialAccessProblem::command() const
{
    if (group.isEmpty())
        return {};
    return QStringLiteral("sudo usermod -aG %1 $USER").arg(group);
}

QString SerialAccessProblem::message() const
{
    if (group.isEmpty())
        return tr("You may not use the serial port %1 (permission denied), and no group gives access to it. "
                  "Ask the administrator of this computer for access.")
            .arg(port);
    if (alreadyMember)
        return tr("You may not use the serial port %1 yet: you were added to the group '%2' after you logged "
                  "in. Log out and log in again (or restart the computer).")
            .arg(port, group);
    return tr("You may not use the serial port %1: it belongs to the group '%2', and you are not a member. "
              "Add yourself once with\n    %3\nthen log out and log in again (or restart the computer).")
        .arg(port, group, command());
}

std::optional<SerialAccessProblem> serialAccessProblem(const QString &port)
{
#ifdef Q_OS_UNIX
    const QByteArray path = QFile::encodeName(port);
    if (::access(path.constData(), R_OK | W_OK) == 0 || errno != EACCES)
        return std::nullopt;
    SerialAccessProblem p;
    p.port = port;
    struct stat st = {};
    if (::stat(path.constData(), &st) != 0)
        return p;
    const bool groupMayUse = (st.st_mode & S_IRGRP) && (st.st_mode & S_IWGRP) && st.st_gid != 0;
    const struct group *g = groupMayUse ? ::getgrgid(st.st_gid) : nullptr;
    if (!g)
        return p;
    p.group = QString::fromLocal8Bit(g->gr_name);
    if (const struct passwd *me = ::getpwuid(::getuid())) {
        for (char **member = g->gr_mem; member && *member; ++member)
            if (qstrcmp(*member, me->pw_name) == 0)
                p.alreadyMember = true;
    }
    return p;
#else
    Q_UNUSED(port);
    return std::nullopt;
#endif
}

} // namespace dd
