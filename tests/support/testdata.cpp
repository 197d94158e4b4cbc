#include "tests/support/testdata.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>

namespace dd::test {

QString dataDir()
{
    const QByteArray env = qgetenv("DRIVEDESK_SOURCE_DIR");
    if (!env.isEmpty())
        return QFile::decodeName(env) + QStringLiteral("/tests/data");
    QDir dir(QCoreApplication::applicationDirPath());
    for (int up = 0; up < 5 && !dir.exists(QStringLiteral("tests/data")); ++up)
        dir.cdUp();
    return dir.filePath(QStringLiteral("tests/data"));
}

} // namespace dd::test
