#include "tests/support/clirun.h"

#include <QDir>
#include <QEventLoop>
#include <QJsonDocument>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTimer>

#include <csignal>
#include <sys/prctl.h>

namespace dd::test {

QJsonObject CliRun::json() const
{
    return QJsonDocument::fromJson(out.trimmed()).object();
}

QList<QJsonObject> CliRun::jsonLines() const
{
    QList<QJsonObject> lines;
    for (const QByteArray &line : out.split('\n')) {
        if (!line.trimmed().isEmpty())
            lines << QJsonDocument::fromJson(line).object();
    }
    return lines;
}

int CliRun::txFrames() const
{
    int n = 0;
    for (const QByteArray &line : err.split('\n')) {
        const QList<QByteArray> words = line.simplified().split(' ');
        if (words.size() > 2 && words.at(1) == "TX")
            ++n;
    }
    return n;
}

QString cliPath()
{
    const QString dir = QProcessEnvironment::systemEnvironment().value(QStringLiteral("DRIVEDESK_BINARY_DIR"));
    return QDir(dir).filePath(QStringLiteral("app/drivedesk-cli"));
}

QProcess *startCli(const QStringList &arguments)
{
    return startCli(arguments, {});
}

QProcess *startCli(const QStringList &arguments, const QHash<QString, QString> &environment)
{
    auto *p = new QProcess;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C")); // untranslated messages
    env.insert(QStringLiteral("LANGUAGE"), QStringLiteral("en"));
    // The CLI's own files (the verification journal, user dictionaries) stay out of the home
    // folder: one data folder per test process, unless the test names another.
    static QTemporaryDir dataHome;
    env.insert(QStringLiteral("XDG_DATA_HOME"), dataHome.path());
    for (auto it = environment.begin(); it != environment.end(); ++it) {
        if (it.value().isEmpty())
            env.remove(it.key());
        else
            env.insert(it.key(), it.value());
    }
    p->setProcessEnvironment(env);
    // Dies with the test (a sanitizer abort must not leave it holding ctest's pipe).
    p->setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGKILL); });
    p->start(cliPath(), arguments);
    return p;
}

CliRun waitCli(QProcess *p, int timeoutMs)
{
    CliRun r;
    if (p->state() != QProcess::NotRunning) {
        QEventLoop loop;
        QObject::connect(p, &QProcess::finished, &loop, &QEventLoop::quit);
        QObject::connect(p, &QProcess::errorOccurred, &loop, &QEventLoop::quit);
        QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
        loop.exec();
    }
    if (p->state() != QProcess::NotRunning) {
        p->kill();
        p->waitForFinished(5000);
    } else {
        r.finished = p->exitStatus() == QProcess::NormalExit && p->error() != QProcess::FailedToStart;
        r.exitCode = p->exitCode();
    }
    r.out = p->readAllStandardOutput();
    r.err = p->readAllStandardError();
    return r;
}

CliRun runCli(const QStringList &arguments, int timeoutMs)
{
    return runCli(arguments, {}, timeoutMs);
}

CliRun runCli(const QStringList &arguments, const QHash<QString, QString> &environment, int timeoutMs)
{
    QProcess *p = startCli(arguments, environment);
    CliRun r = waitCli(p, timeoutMs);
    delete p;
    return r;
}

bool waitForOutput(QProcess *p, const QByteArray &text, int timeoutMs, QByteArray *seen)
{
    QByteArray all;
    QEventLoop loop;
    auto check = [&] {
        all += p->readAllStandardOutput();
        all += p->readAllStandardError();
        if (all.contains(text))
            loop.quit();
    };
    QObject::connect(p, &QProcess::readyReadStandardOutput, &loop, check);
    QObject::connect(p, &QProcess::readyReadStandardError, &loop, check);
    QObject::connect(p, &QProcess::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    check();
    if (!all.contains(text) && p->state() != QProcess::NotRunning)
        loop.exec();
    if (seen)
        *seen = all;
    return all.contains(text);
}

} // namespace dd::test
