// Helpers shared by the fault-injection tests (tst_fault*.cpp): the backup workflow as the
// CLI and the GUI run it, waiting with a bound (a hang is a failure, not a stuck test), and
// the checks every fault test makes on files and on write reports.
#pragma once

#include "drive/drive.h"
#include "drive/drivereply.h"
#include "params/backupfile.h"
#include "params/parameterdictionary.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QtTest>

#include <functional>

namespace dd::faultcheck {

// Waits for a reply; false if it did not finish within `ms` (the operation hangs).
inline bool waitFinished(DriveReply *r, int ms)
{
    if (r->isFinished()) {
        QCoreApplication::processEvents(); // deliver the queued finished()
        return true;
    }
    QSignalSpy done(r, &DriveReply::finished);
    return done.wait(ms);
}

inline bool waitUntil(const std::function<bool()> &cond, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!cond() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return cond();
}

inline QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

struct BackupOutcome
{
    Error error;          // of the read or of the save
    bool finished = true; // false: the read did not finish in time (a hang)
    qint64 elapsedMs = 0;
    QMap<int, qint64> values;
};

// The backup workflow: read every readable parameter of the drive's dictionary and, only
// when every one was read, save them atomically (BackupFile::save, QSaveFile).
inline BackupOutcome backupToFile(Drive *drive, const QString &path, int hangMs = 8000)
{
    BackupOutcome out;
    QElapsedTimer t;
    t.start();
    QList<int> indices;
    for (const ParameterInfo &p : drive->parameterDictionary().parameters())
        if (p.isReadable())
            indices.append(p.index);
    DriveReply *r = drive->readParameters(indices);
    out.finished = waitFinished(r, hangMs);
    out.elapsedMs = t.elapsed();
    if (!out.finished) {
        out.error = {ErrorCode::Timeout, QStringLiteral("the backup hangs")};
        return out;
    }
    r->deleteLater();
    if (!r->ok()) {
        out.error = r->error();
        return out;
    }
    out.values = r->parameters();
    BackupFile file;
    file.setFamily(drive->family());
    file.setAddress(drive->address());
    ParameterSet set;
    for (auto it = out.values.cbegin(); it != out.values.cend(); ++it)
        set.set(it.key(), it.value());
    file.setValues(set);
    out.error = file.save(path, drive->parameterDictionary());
    return out;
}

// What the user reads about a failed backup must say what failed: a typed error and a
// message longer than a word.
inline bool isClearError(const Error &e)
{
    return e.isError() && e.message.size() > 20;
}

// The guarantee for a write report, checked against the drive's actual values afterwards:
// "verified" only when the drive holds the requested value; "not written" only when it still
// holds the old one — except for a write that was on its way when the link died (its answer
// never came: at most `inFlight` of them); "written, not verified" is unconfirmed (either
// value) and says why. Returns an empty string when the report is honest, else what is wrong.
inline QString dishonesty(const QList<ParameterWriteResult> &results,
                          const std::function<qint64(int index)> &actual,
                          const std::function<qint64(int index)> &old, int inFlight = 0)
{
    for (const ParameterWriteResult &r : results) {
        const qint64 now = actual(r.index);
        if (r.verified && now != r.requested)
            return QStringLiteral("P%1 reported verified but the drive holds %2, not %3")
                .arg(r.index).arg(now).arg(r.requested);
        if (!r.written && now != old(r.index) && inFlight-- <= 0)
            return QStringLiteral("P%1 reported not written but the drive holds %2 (was %3)")
                .arg(r.index).arg(now).arg(old(r.index));
        if (!r.verified && r.error.isEmpty())
            return QStringLiteral("P%1 not verified without a reason").arg(r.index);
    }
    return {};
}

} // namespace dd::faultcheck
