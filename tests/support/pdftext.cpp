#include "tests/support/pdftext.h"

#include <QProcess>
#include <QStringList>

namespace dd::test {

namespace {

QString runTool(const QString &tool, const QStringList &arguments, QString *error)
{
    QProcess p;
    p.start(tool, arguments);
    if (!p.waitForFinished(30000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        if (error)
            *error = QStringLiteral("%1 failed (%2); install poppler-utils (packaging/install-deps.sh): %3")
                         .arg(tool, p.errorString(), QString::fromLocal8Bit(p.readAllStandardError()));
        return QString();
    }
    return QString::fromUtf8(p.readAllStandardOutput());
}

} // namespace

QString pdfText(const QString &path, int firstPage, int lastPage, QString *error)
{
    QStringList args{QStringLiteral("-layout"), QStringLiteral("-enc"), QStringLiteral("UTF-8")};
    if (firstPage > 0)
        args << QStringLiteral("-f") << QString::number(firstPage);
    if (lastPage > 0)
        args << QStringLiteral("-l") << QString::number(lastPage);
    args << path << QStringLiteral("-");
    return runTool(QStringLiteral("pdftotext"), args, error);
}

QString pdfInfo(const QString &path, QString *error)
{
    return runTool(QStringLiteral("pdfinfo"), {path}, error);
}

} // namespace dd::test
