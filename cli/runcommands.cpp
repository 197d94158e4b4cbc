#include "cli/runcommands.h"

#include "cli/clidescribe.h"
#include "cli/clijournal.h"
#include "cli/restoredescribe.h"
#include "core/drive/drive.h"
#include "core/params/parameterdictionary.h"
#include "core/protocol/familytraits.h"
#include "core/report/verificationjournal.h"
#include "core/tuning/runcompatibility.h"
#include "core/tuning/runparameterapply.h"
#include "core/tuning/spectrum.h"

#include <QJsonArray>
#include <cmath>

namespace dd {

namespace {
// The metrics a parameter change is judged by, as the example reads.
const QStringList &comparedKeys()
{
    static const QStringList k = {QStringLiteral("overshoot"), QStringLiteral("settlingTime2"),
                                  QStringLiteral("riseTime")};
    return k;
}
} // namespace

bool RunsCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 64, tr("RUN.ddrun [RUN2.ddrun ...]"), error))
        return false;
    for (const QString &path : inv.positionals) {
        TuningRun run;
        if (Error e = TuningRun::load(path, &run)) {
            *error = e.message;
            return false;
        }
        m_runs.append(run);
    }
    return true;
}

void RunsCommand::start()
{
    QJsonArray runs;
    QStringList lines;
    QString header = QStringLiteral("%1").arg(QString(), -20);
    for (const TuningRun &r : std::as_const(m_runs))
        header += QStringLiteral("%1").arg(r.label.left(18), -20);
    lines << header;
    for (const QString &k : StepMetrics::keys()) {
        QString row = QStringLiteral("%1").arg(k, -20);
        for (const TuningRun &r : std::as_const(m_runs))
            row += QStringLiteral("%1").arg(CliDescribe::metric(r.metrics.byKey(k), k), -20);
        lines << row;
    }
    for (const TuningRun &r : std::as_const(m_runs)) {
        QJsonArray tuning;
        for (const TuningSnapshotEntry &e : r.tuning)
            tuning.append(QJsonObject{{QStringLiteral("key"), e.key},
                                      {QStringLiteral("role"), e.role},
                                      {QStringLiteral("value"), double(e.value)}});
        runs.append(QJsonObject{{QStringLiteral("run"), r.label},
                                {QStringLiteral("test"), r.test},
                                {QStringLiteral("metrics"), r.metrics.valuesJson()},
                                {QStringLiteral("notes"), QJsonArray::fromStringList(r.metrics.notes())},
                                {QStringLiteral("tuning"), tuning}});
    }
    // Parameter differences between consecutive runs, with what they did to the metrics.
    QJsonArray differences;
    for (int i = 1; i < m_runs.size(); ++i) {
        const TuningRun &a = m_runs.at(i - 1), &b = m_runs.at(i);
        QStringList changes;
        QJsonArray params;
        for (const TuningSnapshotEntry &eb : b.tuning) {
            for (const TuningSnapshotEntry &ea : a.tuning) {
                if (ea.index == eb.index && ea.value != eb.value) {
                    changes << QStringLiteral("%1 %2 → %3").arg(eb.key).arg(ea.value).arg(eb.value);
                    params.append(QJsonObject{{QStringLiteral("key"), eb.key},
                                              {QStringLiteral("role"), eb.role},
                                              {QStringLiteral("from"), double(ea.value)},
                                              {QStringLiteral("to"), double(eb.value)}});
                }
            }
        }
        // Not like for like (another drive, dictionary, test or step size; a snapshot that
        // lists a parameter twice): say so rather than "no tuning parameter differs".
        const QStringList why = RunCompatibility::snapshotProblems(a) + RunCompatibility::snapshotProblems(b)
            + RunCompatibility::differences(a, b);
        QJsonObject difference{{QStringLiteral("from"), a.label},
                               {QStringLiteral("to"), b.label},
                               {QStringLiteral("comparable"), why.isEmpty()}};
        if (!why.isEmpty()) {
            lines << tr("%1 → %2: not comparable: %3").arg(a.label, b.label, why.join(QLatin1Char(' ')));
            difference.insert(QStringLiteral("reasons"), QJsonArray::fromStringList(why));
            differences.append(difference);
            continue;
        }
        QStringList effects;
        for (const QString &k : comparedKeys())
            effects << QStringLiteral("%1 %2 → %3")
                           .arg(k, CliDescribe::metric(a.metrics.byKey(k), k),
                                CliDescribe::metric(b.metrics.byKey(k), k));
        const QString what = changes.isEmpty() ? tr("no tuning parameter differs") : changes.join(QStringLiteral(", "));
        lines << QStringLiteral("%1 → %2: %3: %4").arg(a.label, b.label, what, effects.join(QStringLiteral(", ")));
        difference.insert(QStringLiteral("parameters"), params);
        differences.append(difference);
    }
    succeed({{QStringLiteral("runs"), runs}, {QStringLiteral("differences"), differences}},
            lines.join(QLatin1Char('\n')));
}

bool SpectrumCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 2, 2, tr("RUN.ddrun CHANNEL"), error))
        return false;
    if (inv.has(QStringLiteral("peaks"))) {
        bool ok = false;
        m_peaks = inv.value(QStringLiteral("peaks")).toInt(&ok);
        if (!ok || m_peaks < 1 || m_peaks > 100) {
            *error = tr("--peaks must be a whole number from 1 to 100, not \"%1\".")
                         .arg(inv.value(QStringLiteral("peaks")));
            return false;
        }
    }
    if (inv.has(QStringLiteral("from"))) {
        bool ok = false;
        m_fromHz = inv.value(QStringLiteral("from")).toDouble(&ok);
        if (!ok || !std::isfinite(m_fromHz) || m_fromHz < 0.0) {
            *error = tr("--from must be a frequency ≥ 0 Hz, not \"%1\".").arg(inv.value(QStringLiteral("from")));
            return false;
        }
    }
    if (inv.has(QStringLiteral("between"))) {
        const QStringList parts = inv.value(QStringLiteral("between")).split(QLatin1Char(':'));
        bool ok1 = false, ok2 = false;
        if (parts.size() == 2) {
            m_t1 = parts.at(0).toDouble(&ok1);
            m_t2 = parts.at(1).toDouble(&ok2);
        }
        if (!ok1 || !ok2 || !std::isfinite(m_t1) || !std::isfinite(m_t2) || m_t1 >= m_t2) {
            *error = tr("--between must be T1:T2, seconds from the trigger with T1 < T2 (e.g. 0.05:0.3), not \"%1\".")
                         .arg(inv.value(QStringLiteral("between")));
            return false;
        }
        m_between = true;
    }
    if (Error e = TuningRun::load(inv.positionals.at(0), &m_run)) {
        *error = e.message;
        return false;
    }
    m_channel = inv.positionals.at(1);
    if (!m_run.capture.channels.contains(m_channel)) {
        *error = tr("%1 has no channel \"%2\" (it has %3).")
                     .arg(inv.positionals.at(0), m_channel, m_run.capture.channels.join(QStringLiteral(", ")));
        return false;
    }
    return true;
}

void SpectrumCommand::start()
{
    QString why;
    Spectrum s;
    if (m_between) {
        // Only the stretch asked for, e.g. after a step's own transient; the gaps bridged
        // inside it are noted as for the whole capture.
        s = Spectrum::compute(m_run.capture, m_channel, m_peaks, &why, m_fromHz, m_t1, m_t2);
    } else {
        s = Spectrum::compute(m_run.capture, m_channel, m_peaks, &why, m_fromHz);
    }
    if (s.isEmpty()) {
        fail({ErrorCode::InvalidArgument, why}, {}, CliExit::Usage);
        return;
    }
    QJsonArray peaks;
    QStringList lines;
    lines << tr("Spectrum of %1: %2 points at %3 Hz, %4 window, resolution %5 Hz, Nyquist %6 Hz")
                 .arg(m_channel)
                 .arg(s.points)
                 .arg(s.sampleRate, 0, 'f', 1)
                 .arg(s.window)
                 .arg(s.resolutionHz, 0, 'f', 3)
                 .arg(s.nyquistHz, 0, 'f', 1);
    for (const Spectrum::Peak &p : s.peaks) {
        QJsonObject peak{{QStringLiteral("hz"), p.hz},
                         {QStringLiteral("magnitude"), p.magnitude},
                         {QStringLiteral("nearNyquist"), p.nearNyquist}};
        if (p.aliasOfHz > 0.0)
            peak.insert(QStringLiteral("aliasOfHz"), p.aliasOfHz);
        peaks.append(peak);
        QString line = QStringLiteral("  %1 Hz  %2").arg(p.hz, 8, 'f', 2).arg(p.magnitude, 0, 'g', 4);
        if (p.aliasOfHz > 0.0)
            line += QStringLiteral("  ") + tr("(may be an alias of %1 Hz)").arg(p.aliasOfHz, 0, 'f', 1);
        else if (p.nearNyquist)
            line += QStringLiteral("  ") + tr("(near the Nyquist frequency)");
        lines << line;
    }
    lines << s.notes;
    succeed({{QStringLiteral("channel"), m_channel},
             {QStringLiteral("window"), s.window},
             {QStringLiteral("resolutionHz"), s.resolutionHz},
             {QStringLiteral("sampleRate"), s.sampleRate},
             {QStringLiteral("nyquistHz"), s.nyquistHz},
             {QStringLiteral("usableBandHz"), QJsonArray{s.usableFromHz, s.usableToHz}},
             {QStringLiteral("points"), s.points},
             {QStringLiteral("peaks"), peaks},
             {QStringLiteral("notes"), QJsonArray::fromStringList(s.notes)}},
            lines.join(QLatin1Char('\n')));
}

// --- apply-run ---------------------------------------------------------------------------

bool ApplyRunCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("RUN.ddrun"), error))
        return false;
    m_path = inv.positionals.at(0);
    if (Error e = TuningRun::load(m_path, &m_run)) {
        *error = e.message;
        return false;
    }
    if (Error e = RunParameterApply::check(m_run, context()->globals.connection.family, *context()->dictionary)) {
        *error = QStringLiteral("%1: %2").arg(m_path, e.message);
        return false;
    }
    m_dryRun = inv.has(QStringLiteral("dry-run"));
    m_force = inv.has(QStringLiteral("force"));
    return true;
}

void ApplyRunCommand::start()
{
    // A run of another drive model is refused like a bad file: exit 2, nothing written.
    if (Error e = RunParameterApply::checkDrive(m_run, drive()->identity())) {
        e.message = QStringLiteral("%1: %2").arg(m_path, e.message);
        return fail(e, {}, CliExit::Usage);
    }
    m_apply = new RunParameterApply(drive(), this);
    connect(m_apply, &RunParameterApply::finished, this, &ApplyRunCommand::report);
    if (Error e = m_apply->apply(m_run, m_dryRun, m_force))
        fail(e, {}, e.code == ErrorCode::InvalidArgument ? std::optional<CliExit>(CliExit::Usage) : std::nullopt);
}

void ApplyRunCommand::interrupt(int)
{
    out()->note(tr("Finishing the writes in progress so that the report is complete; every write is verified as "
                   "it goes."));
}

void ApplyRunCommand::report(const Error &error)
{
    const ParameterDictionary &dict = m_apply->dictionary();
    const RestoreReport &r = m_apply->report();
    QList<QPair<QString, QString>> rows;
    QJsonObject json{{QStringLiteral("file"), m_path},
                     {QStringLiteral("run"), m_run.label},
                     {QStringLiteral("dryRun"), r.dryRun},
                     {QStringLiteral("forced"), m_force},
                     {QStringLiteral("snapshot"), int(m_run.tuning.size())},
                     {QStringLiteral("selected"), RestoreDescribe::selected(dict, r, &rows)}};
    RestoreDescribe::insertOutcomes(dict, r, &json);
    if (!r.dryRun && !r.selected.isEmpty())
        CliJournal::verification(
            context(),
            VerificationJournal::fromRestore(r, dict, m_path, BackupFile::checksum(m_apply->file().values())));
    if (error) {
        if (!r.selected.isEmpty() && !out()->isJson()) {
            out()->line(CliDescribe::table(rows));
            for (const QString &line : RestoreDescribe::incomplete(dict, r))
                out()->line(line);
        }
        return fail(error, json);
    }
    if (r.selected.isEmpty())
        return succeed(json, tr("The drive's tuning parameters already match %1; nothing to write.").arg(m_path));
    QString text = CliDescribe::table(rows);
    if (r.dryRun) {
        text += tr("Dry run: %n parameter(s) would be written; nothing was sent.", nullptr, int(r.selected.size()));
    } else {
        text += tr("%n parameter(s) written and verified.", nullptr, int(r.written().size()));
        if (familyTraits(context()->globals.connection.family).eeOperations)
            out()->note(tr("The values are in the drive's RAM; `ee set` stores them to EEPROM."));
    }
    succeed(json, text);
}

} // namespace dd
