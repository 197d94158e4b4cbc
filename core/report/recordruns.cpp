#include "core/report/recordruns.h"

#include "core/common/family.h"
#include "core/params/parameterdictionary.h"
#include "core/protocol/familytraits.h"
#include "core/report/runplot.h"

#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>

namespace dd {

namespace {

// The unit a metric is shown in, and the factor from the run file's value (seconds for times).
struct Shown
{
    QString unit;
    double factor = 1.0;
};

Shown shownAs(const QString &key, const TuningRun &run)
{
    auto unitOf = [&run](const QString &channel) { return run.units.value(run.capture.columnOf(channel)); };
    if (key == QLatin1String("riseTime") || key.startsWith(QLatin1String("settlingTime"))
        || key == QLatin1String("sampleInterval"))
        return {QStringLiteral("ms"), 1000.0};
    if (key == QLatin1String("overshoot"))
        return {QStringLiteral("%"), 1.0};
    const StepMetrics::Input input;
    if (key == QLatin1String("peakFollowingError"))
        return {unitOf(input.followingErrorChannel), 1.0};
    if (key == QLatin1String("peakTorque"))
        return {unitOf(input.torqueChannel), 1.0};
    if (key == QLatin1String("peakCurrent"))
        return {unitOf(input.currentChannel), 1.0};
    return {unitOf(run.metricsChannel), 1.0}; // steady-state error and ripple
}

} // namespace

QString RecordRuns::testName(const QString &test)
{
    if (test == QLatin1String("capture"))
        return tr("Capture");
    if (test == QLatin1String("velocity-step"))
        return tr("Velocity step");
    if (test == QLatin1String("position-step"))
        return tr("Position step");
    if (test == QLatin1String("reversal"))
        return tr("Reversal");
    return test;
}

QString RecordRuns::metricName(const QString &key)
{
    static const QHash<QString, const char *> names = {
        {QStringLiteral("riseTime"), QT_TR_NOOP("Rise time (10–90 %)")},
        {QStringLiteral("overshoot"), QT_TR_NOOP("Overshoot")},
        {QStringLiteral("settlingTime2"), QT_TR_NOOP("Settling time (±2 %)")},
        {QStringLiteral("settlingTime5"), QT_TR_NOOP("Settling time (±5 %)")},
        {QStringLiteral("steadyStateError"), QT_TR_NOOP("Steady-state error")},
        {QStringLiteral("steadyStateRipple"), QT_TR_NOOP("Steady-state ripple")},
        {QStringLiteral("peakFollowingError"), QT_TR_NOOP("Peak following error")},
        {QStringLiteral("peakTorque"), QT_TR_NOOP("Peak torque")},
        {QStringLiteral("peakCurrent"), QT_TR_NOOP("Peak current")},
        {QStringLiteral("sampleInterval"), QT_TR_NOOP("Sample interval")}};
    const char *name = names.value(key);
    return name ? tr(name) : key;
}

Error RecordRuns::load(const QString &path, RecordRunFile *out)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {ErrorCode::FileError, tr("Cannot open the run file %1: %2").arg(path, f.errorString())};
    if (f.size() > TuningRun::MaxFileSize)
        return {ErrorCode::Malformed,
                tr("%1 is larger than %2 MiB: not a run file").arg(path).arg(TuningRun::MaxFileSize >> 20)};
    const QByteArray bytes = f.readAll();
    RecordRunFile file;
    if (Error e = TuningRun::fromBytes(bytes, QFileInfo(path).fileName(), &file.run))
        return e;
    file.run.label = QFileInfo(path).completeBaseName();
    file.path = QFileInfo(path).absoluteFilePath();
    file.checksum = QStringLiteral("sha256:")
        + QString::fromLatin1(QCryptographicHash::hash(bytes, QCryptographicHash::Sha256).toHex());
    *out = file;
    return {};
}

RunRecord RecordRuns::toRecord(const RecordRunFile &file, const DriveRecord &drive, const QLocale &locale)
{
    const TuningRun &run = file.run;
    RunRecord r;
    r.title = run.label.isEmpty() ? testName(run.test) : run.label;
    r.file = file.path;
    r.checksum = file.checksum;
    r.test = run.test;
    r.when = run.created;
    r.samples = int(run.capture.time.size());
    r.meanIntervalMs = run.capture.interval.mean * 1000.0;
    const QList<CaptureGap> gaps = CaptureGap::of(run.capture.time);
    r.gaps = int(gaps.size());
    for (const CaptureGap &g : gaps)
        r.longestGapMs = std::max(r.longestGapMs, (g.to - g.from) * 1000.0);
    // Step metrics: those with a value or a reason (a plain capture has no step to measure).
    QHash<QString, QString> notes;
    for (const QString &line : run.metrics.notes()) {
        const qsizetype colon = line.indexOf(QLatin1String(": "));
        if (colon > 0)
            notes.insert(line.left(colon), line.mid(colon + 2));
    }
    for (const QString &key : StepMetrics::keys()) {
        const Metric &m = run.metrics.byKey(key);
        const QString note = m.reason.isEmpty() ? notes.value(key) : m.reason;
        if (!m.value && note.isEmpty())
            continue;
        const Shown shown = shownAs(key, run);
        RunRecord::Metric out;
        out.key = key;
        out.name = metricName(key);
        if (m.value)
            out.value = *m.value * shown.factor;
        out.unit = shown.unit;
        out.note = m.value ? QString() : note;
        r.metrics.append(out);
    }
    // The snapshot, named as the drive's dictionary names the parameters.
    QHash<int, const RecordParameter *> byIndex;
    for (const RecordParameter &p : drive.parameters)
        byIndex.insert(p.index, &p);
    const ParameterDictionary &bundled = ParameterDictionary::bundled(drive.family);
    for (const TuningSnapshotEntry &e : run.tuning) {
        RunRecord::SnapshotValue s;
        s.key = e.key;
        s.value = e.value;
        if (const RecordParameter *p = byIndex.value(e.index)) {
            s.name = p->name;
            s.unit = p->unit;
        } else if (const ParameterInfo *info = bundled.byIndex(e.index)) {
            s.name = info->displayName(locale);
            s.unit = info->unit;
        } else {
            s.name = e.role;
        }
        r.snapshot.append(s);
    }
    r.plot = RunPlot::render(run, locale);
    return r;
}

Error RecordRuns::attach(const QList<RecordRunFile> &runs, QList<DriveRecord> *drives, const QLocale &locale)
{
    QList<QPair<int, RunRecord>> attached;
    QStringList seen;
    for (const RecordRunFile &file : runs) {
        if (seen.contains(file.path))
            return {ErrorCode::InvalidArgument, tr("The run file %1 is chosen twice.").arg(file.path)};
        seen << file.path;
        const auto family = familyFromId(file.run.family);
        int found = -1;
        for (int i = 0; i < drives->size() && family; ++i)
            if (drives->at(i).family == *family && drives->at(i).address == file.run.address)
                found = i;
        if (found < 0) {
            QStringList inRecord;
            for (const DriveRecord &d : std::as_const(*drives))
                inRecord << tr("%1 at %2").arg(familyId(d.family)).arg(d.address);
            return {ErrorCode::InvalidArgument,
                    tr("The run %1 was taken on %2 at address %3, which is not in this record (it holds %4).")
                        .arg(QFileInfo(file.path).fileName(), file.run.family)
                        .arg(file.run.address)
                        .arg(inRecord.isEmpty() ? tr("no drive") : inRecord.join(QLatin1String(", ")))};
        }
        attached.append({found, toRecord(file, drives->at(found), locale)});
    }
    for (const auto &a : std::as_const(attached))
        (*drives)[a.first].runs.append(a.second);
    return {};
}

} // namespace dd
