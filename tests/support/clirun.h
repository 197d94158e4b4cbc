#pragma once

#include <QByteArray>
#include <QHash>
#include <QJsonObject>
#include <QList>
#include <QProcess>
#include <QStringList>

namespace dd::test {

// The outcome of one run of the real drivedesk-cli executable.
struct CliRun
{
    int exitCode = -1;
    bool finished = false; // false: it had to be killed after the timeout
    QByteArray out;
    QByteArray err;

    QJsonObject json() const;             // stdout as one JSON document
    QList<QJsonObject> jsonLines() const; // stdout as JSON lines
    int txFrames() const;                 // "TX" lines of --trace on stderr
    QString text() const { return QString::fromUtf8(out + err); }
};

// $DRIVEDESK_BINARY_DIR/app/drivedesk-cli
QString cliPath();
// Runs the CLI and waits for it with an event loop (so that a simulator living in the test
// process keeps answering); kills it after timeoutMs.
CliRun runCli(const QStringList &arguments, int timeoutMs = 30000);
// The same with changes to the environment (by default LC_ALL=C and LANGUAGE=en, for
// untranslated messages): each entry sets a variable, or removes it when its value is empty.
CliRun runCli(const QStringList &arguments, const QHash<QString, QString> &environment, int timeoutMs = 30000);
// Starts the CLI and returns the running process (the caller waits, signals, deletes).
QProcess *startCli(const QStringList &arguments);
QProcess *startCli(const QStringList &arguments, const QHash<QString, QString> &environment);
// Waits (event loop) for a started process; collects its output.
CliRun waitCli(QProcess *process, int timeoutMs = 30000);
// Waits (event loop) until the process printed `text` on stdout or stderr, or timeoutMs.
bool waitForOutput(QProcess *process, const QByteArray &text, int timeoutMs, QByteArray *seen);

} // namespace dd::test
