// Helpers shared by the fault-injection tests (tst_fault*.cpp): the backup workflow as the
// CLI and the GUI run it, waiting with a bound (a hang is a failure, not a stuck test), and
// the checks every fault test makes on files and on write reports.
#pragma once

#include "core/drive/drive.h"
#include "core/drive/drivereply.h"
#include "core/drive/parametertransfer.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"
#include "tests/support/replywait.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QtTest>

#include <functional>

namespace dd::faultcheck {

// Waits for a reply; false if it did not finish within `ms` (the operation hangs).
using test::waitFinished;

using test::waitUntil;

inline QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

struct BackupOutcome
{
    Error error;          // of the backup or of the save
    bool finished = true; // false: the backup did not finish in time (a hang)
    qint64 elapsedMs = 0;
    BackupFile file;
};

// Runs `start` on a ParameterTransfer and waits for finished(); false on a hang.
inline bool runTransfer(ParameterTransfer &t, const std::function<void()> &start, int hangMs, Error *error)
{
    bool done = false;
    QObject::connect(&t, &ParameterTransfer::finished, &t, [&](const Error &e) {
        done = true;
        *error = e;
    });
    start();
    QElapsedTimer timer;
    timer.start();
    while (!done && timer.elapsed() < hangMs)
        QCoreApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents, 5);
    return done;
}

// The backup workflow of the CLI and the GUI: ParameterTransfer::backup() (identify, read
// every readable parameter) and, only when it succeeded, BackupFile::save() (atomic).
inline BackupOutcome backupToFile(Drive *drive, const QString &path, int hangMs = 8000)
{
    BackupOutcome out;
    QElapsedTimer t;
    t.start();
    ParameterTransfer transfer(drive);
    out.finished = runTransfer(
        transfer, [&] { transfer.backup(); }, hangMs, &out.error);
    out.elapsedMs = t.elapsed();
    if (!out.finished) {
        out.error = {ErrorCode::Timeout, QStringLiteral("the backup hangs")};
        return out;
    }
    if (out.error.isError())
        return out;
    out.file = transfer.backupFile();
    out.error = out.file.save(path, transfer.dictionary());
    return out;
}

struct RestoreOutcome
{
    Error error;
    bool finished = true;
    qint64 elapsedMs = 0;
    RestoreReport report;
};

// The restore workflow: ParameterTransfer::restore() (identify, check the file fits, read,
// diff, write the differences, each read back).
inline RestoreOutcome restoreFrom(Drive *drive, const BackupFile &file, int hangMs = 8000)
{
    RestoreOutcome out;
    QElapsedTimer t;
    t.start();
    ParameterTransfer transfer(drive);
    out.finished = runTransfer(
        transfer, [&] { transfer.restore(file, RestoreOptions()); }, hangMs, &out.error);
    out.elapsedMs = t.elapsed();
    out.report = transfer.report();
    if (!out.finished)
        out.error = {ErrorCode::Timeout, QStringLiteral("the restore hangs")};
    return out;
}

// The restore's view of itself, for messages: "P10 verified, P12 unconfirmed, ...".
inline QString describe(const RestoreReport &r)
{
    QStringList parts;
    for (const DiffEntry &e : r.selected)
        parts << QStringLiteral("%1 %2").arg(e.key, RestoreReport::outcomeId(r.outcome(e.index)));
    return parts.join(QStringLiteral(", "));
}

// What the user reads about a failed backup must say what failed: a typed error and a
// message longer than a word.
inline bool isClearError(const Error &e)
{
    return e.isError() && e.message.size() > 20;
}

// The guarantee for a write report, checked against the drive's actual values afterwards:
// "verified" only when the drive holds the requested value; "not written" (without
// readBackFailed: refused, or never sent) only when it still holds the old one;
// "readBackFailed" (no answer: unknown) either; every unverified one says why. Returns an
// empty string when the report is honest, else what is wrong.
inline QString dishonesty(const QList<ParameterWriteResult> &results, const std::function<qint64(int index)> &actual,
                          const std::function<qint64(int index)> &old)
{
    for (const ParameterWriteResult &r : results) {
        const qint64 now = actual(r.index);
        if (r.verified && now != r.requested)
            return QStringLiteral("P%1 reported verified but the drive holds %2, not %3")
                .arg(r.index)
                .arg(now)
                .arg(r.requested);
        if (!r.written && !r.readBackFailed && now != old(r.index))
            return QStringLiteral("P%1 reported not written but the drive holds %2 (was %3)")
                .arg(r.index)
                .arg(now)
                .arg(old(r.index));
        if (!r.verified && r.error.isEmpty())
            return QStringLiteral("P%1 not verified without a reason").arg(r.index);
    }
    return {};
}

} // namespace dd::faultcheck
