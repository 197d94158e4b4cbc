#include "cli/stepcommand.h"

#include "cli/clidescribe.h"

#include "cli/clivalues.h"

#include "core/drive/drive.h"
#include "core/protocol/familytraits.h"
#include "core/tuning/steptest.h"

#include <QFileInfo>
#include <QJsonArray>
#include <cmath>

namespace dd {

namespace {
// Default maximum duration when --max-duration is not given: the commanded time and 2 s to
// stop and settle; a position step 10 s.
constexpr double StopAllowanceS = 2.0;
constexpr double PositionDurationS = 10.0;
// A position step's maximum speed when --max-speed is not given: its --speed and half again
// (the loop may overshoot the profile's speed a little; more than that is a fault).
constexpr double PositionSpeedMargin = 1.5;
} // namespace

StepCommand::StepCommand(CliContext *c)
    : CliCommand(QStringLiteral("step"), c)
{
}

bool StepCommand::prepare(const CliInvocation &inv, QString *error)
{
    m_enable = inv.has(QStringLiteral("enable"));
    if (!expectArguments(inv, 2, 2, tr("velocity SPEED | position DISTANCE | reversal SPEED"), error))
        return false;
    const auto kind = StepSpec::kindFromId(inv.positionals.at(0));
    if (!kind) {
        *error = tr("The step test must be velocity, position or reversal, not \"%1\".").arg(inv.positionals.at(0));
        return false;
    }
    m_spec.kind = *kind;
    const bool position = *kind == StepSpec::Kind::Position;
    if (position) {
        const auto d = CliValues::integer(inv.positionals.at(1), -2147483647, 2147483647, tr("distance"), error);
        if (!d)
            return false;
        m_spec.distance = *d;
        if (!inv.has(QStringLiteral("speed"))) {
            *error = tr("A position step needs --speed V.");
            return false;
        }
        const auto s = CliValues::integer(inv.value(QStringLiteral("speed")), 1, 2147483647, QStringLiteral("--speed"),
                                          error);
        if (!s)
            return false;
        m_spec.speed = qint32(*s);
        if (inv.has(QStringLiteral("duration"))) {
            *error = tr("--duration is for velocity and reversal steps; a position step ends when it arrives.");
            return false;
        }
    } else {
        const auto s = CliValues::integer(inv.positionals.at(1), -2147483647, 2147483647, tr("step speed"), error);
        if (!s)
            return false;
        m_spec.speed = qint32(*s);
        if (inv.has(QStringLiteral("speed"))) {
            *error = tr("--speed is for position steps; the speed of a %1 step is its argument.")
                         .arg(StepSpec::kindId(*kind));
            return false;
        }
        if (!inv.has(QStringLiteral("duration"))) {
            *error = tr("A %1 step needs --duration S.").arg(StepSpec::kindId(*kind));
            return false;
        }
        const auto d = CliValues::real(inv.value(QStringLiteral("duration")), 0.001, 3600, QStringLiteral("--duration"),
                                       error);
        if (!d)
            return false;
        m_spec.durationS = *d;
    }
    // The limits: without them nothing is sent (exit 2).
    if (inv.has(QStringLiteral("max-speed"))) {
        const auto v = CliValues::real(inv.value(QStringLiteral("max-speed")), 1e-9, 1e9, QStringLiteral("--max-speed"),
                                       error);
        if (!v)
            return false;
        m_limits.maxSpeed = *v;
    } else if (position) {
        m_limits.maxSpeed = std::ceil(m_spec.speed * PositionSpeedMargin);
    } else {
        *error = tr("A step test needs its limits: --max-speed V is missing (nothing was sent).");
        return false;
    }
    if (!inv.has(QStringLiteral("max-travel"))) {
        *error = tr("A step test needs its limits: --max-travel N is missing (nothing was sent).");
        return false;
    }
    const auto travel = CliValues::integer(inv.value(QStringLiteral("max-travel")), 1, 2147483647,
                                           QStringLiteral("--max-travel"), error);
    if (!travel)
        return false;
    m_limits.maxTravel = *travel;
    if (inv.has(QStringLiteral("max-duration"))) {
        const auto d = CliValues::real(inv.value(QStringLiteral("max-duration")), 0.001, 3600,
                                       QStringLiteral("--max-duration"), error);
        if (!d)
            return false;
        m_limits.maxDurationS = *d;
    } else {
        m_limits.maxDurationS = position ? PositionDurationS : m_spec.commandedSeconds() + StopAllowanceS;
    }
    if (inv.has(QStringLiteral("record"))) {
        const auto r = CliValues::real(inv.value(QStringLiteral("record")), 0.01, 600, QStringLiteral("--record"),
                                       error);
        if (!r)
            return false;
        m_spec.recordS = *r;
    }
    if (inv.has(QStringLiteral("pre"))) {
        // As capture's --pre: seconds before the motion command, or a share of the whole
        // record (pre + record).
        const auto pre = CliValues::preTrigger(inv.value(QStringLiteral("pre")), 10.0, error);
        if (!pre)
            return false;
        if (pre->percent) {
            const double record = m_spec.recordSeconds() > 0.0 ? m_spec.recordSeconds() : m_limits.maxDurationS;
            m_spec.preS = pre->value / (100.0 - pre->value) * record;
            if (m_spec.preS > 10.0) {
                *error = tr("--pre %1 is %2 s before the motion: at most 10 s.")
                             .arg(inv.value(QStringLiteral("pre")))
                             .arg(m_spec.preS, 0, 'f', 2);
                return false;
            }
        } else {
            m_spec.preS = pre->value;
        }
    }
    if (inv.has(QStringLiteral("counts-per-rev"))) {
        const auto c = CliValues::integer(inv.value(QStringLiteral("counts-per-rev")), 1, 1000000000,
                                          QStringLiteral("--counts-per-rev"), error);
        if (!c)
            return false;
        m_spec.countsPerRev = double(*c);
    }
    if (inv.has(QStringLiteral("channels"))) {
        for (const QString &c : inv.value(QStringLiteral("channels")).split(QLatin1Char(','), Qt::SkipEmptyParts))
            if (!m_spec.channels.contains(c.trimmed()))
                m_spec.channels << c.trimmed();
    }
    m_spec.returnToStart = !inv.has(QStringLiteral("no-return"));
    m_output = inv.value(QStringLiteral("output"));
    m_notes = inv.value(QStringLiteral("notes"));
    if (Error e = m_spec.check()) {
        *error = e.message;
        return false;
    }
    if (Error e = m_limits.check(m_spec)) {
        *error = e.message + QLatin1Char(' ') + tr("Nothing was sent.");
        return false;
    }
    // The travel and time at full speed (the stop comes on top once the drive's
    // deceleration is read): a test that cannot fit is refused before the link is opened.
    const double k = StepPlan::countsPerSpeedUnit(
        QString::fromLatin1(familyTraits(context()->globals.connection.family).speedUnit), m_spec.countsPerRev);
    if (k > 0.0) {
        if (Error e = StepPlan::predict(m_spec, k).check(m_limits)) {
            *error = e.message + QLatin1Char(' ') + tr("Nothing was sent.");
            return false;
        }
    }
    return true;
}

void StepCommand::start()
{
    if (!motionMaySwitchPowerOn(m_enable))
        return;
    m_test = new StepTest(drive(), this);
    connect(m_test, &StepTest::progress, this, [this](StepTest::Phase phase, const QString &message) {
        if (phase != StepTest::Phase::Done)
            out()->note(message);
    });
    connect(m_test, &StepTest::finished, this, &StepCommand::onFinished);
    if (Error e = m_test->start(m_spec, m_limits)) {
        // Refused before any command: only the connection's identification of the drive
        // was sent (say so: "nothing was sent" would not be true).
        e.message += QLatin1Char(' ') + tr("No command was sent after identifying the drive.");
        fail(e, {}, CliExit::Usage);
    }
}

void StepCommand::interrupt(int signalNumber)
{
    if (!m_test || !m_test->isRunning())
        return CliCommand::interrupt(signalNumber);
    if (m_interrupted) {
        // A second Ctrl-C: the strongest stop the family has.
        out()->note(tr("Second interrupt: emergency stop."));
        DriveReply *r = drive()->stop(true);
        connect(r, &DriveReply::finished, r, &QObject::deleteLater);
        return;
    }
    m_interrupted = true;
    m_test->abort(tr("Interrupted: the step test was stopped."));
}

void StepCommand::linkLost(const Error &why)
{
    if (m_test && m_test->isRunning())
        return m_test->linkLost(why); // its finished() reports it
    CliCommand::linkLost(why);
}

void StepCommand::onFinished(const StepResult &r)
{
    QJsonObject json{{QStringLiteral("test"), StepSpec::testId(m_spec.kind)},
                     {QStringLiteral("outcome"), StepResult::outcomeId(r.outcome)},
                     {QStringLiteral("speed"), m_spec.speed},
                     {QStringLiteral("limits"),
                      QJsonObject{{QStringLiteral("maxSpeed"), m_limits.maxSpeed},
                                  {QStringLiteral("maxTravel"), double(m_limits.maxTravel)},
                                  {QStringLiteral("maxDuration"), m_limits.maxDurationS}}},
                     {QStringLiteral("travel"),
                      QJsonObject{{QStringLiteral("farthest"), double(r.farthest)},
                                  {QStringLiteral("limit"), double(m_limits.maxTravel)},
                                  {QStringLiteral("predicted"), double(std::llround(r.predictedTravel))}}},
                     {QStringLiteral("predictedSeconds"), r.predictedSeconds},
                     {QStringLiteral("moved"), r.moved},
                     {QStringLiteral("stopConfirmed"), r.stopConfirmed},
                     {QStringLiteral("returnedToStart"), r.returnedToStart}};
    if (m_spec.kind == StepSpec::Kind::Position)
        json.insert(QStringLiteral("distance"), double(m_spec.distance));
    else
        json.insert(QStringLiteral("duration"), m_spec.durationS);
    if (r.positionKnown) {
        json.insert(QStringLiteral("startPosition"), double(r.startPosition));
        json.insert(QStringLiteral("endPosition"), double(r.endPosition));
    }
    if (!r.stoppedBy.isEmpty())
        json.insert(QStringLiteral("stoppedBy"), r.stoppedBy);
    if (!r.abortCause.isEmpty())
        json.insert(QStringLiteral("abortCause"), r.abortCause);
    if (!r.stopNote.isEmpty())
        json.insert(QStringLiteral("stopNote"), r.stopNote);
    if (!r.decelSource.isEmpty())
        json.insert(QStringLiteral("deceleration"), r.decelSource);

    QStringList lines;
    if (r.hasRun) {
        TuningRun run = r.run;
        run.linkKind = context()->globals.isCanLink() ? QStringLiteral("can") : QStringLiteral("serial");
        if (run.linkDescription.isEmpty())
            run.linkDescription = context()->globals.connection.linkName();
        run.notes = m_notes;
        if (!m_output.isEmpty()) {
            run.label = QFileInfo(m_output).completeBaseName();
            if (Error e = run.save(m_output))
                return fail(e, json);
            json.insert(QStringLiteral("file"), m_output);
        }
        json.insert(QStringLiteral("channels"), QJsonArray::fromStringList(run.capture.channels));
        json.insert(QStringLiteral("samples"), int(run.capture.time.size()));
        json.insert(QStringLiteral("metricsChannel"), run.metricsChannel);
        json.insert(QStringLiteral("metrics"), run.metrics.valuesJson());
        json.insert(QStringLiteral("resolutions"), run.metrics.resolutionsJson());
        json.insert(QStringLiteral("notes"), QJsonArray::fromStringList(run.metrics.notes()));
        QJsonArray tuning;
        for (const TuningSnapshotEntry &e : run.tuning)
            tuning.append(QJsonObject{{QStringLiteral("key"), e.key},
                                      {QStringLiteral("role"), e.role},
                                      {QStringLiteral("value"), double(e.value)}});
        json.insert(QStringLiteral("tuning"), tuning);

        const IntervalStats &s = run.capture.interval;
        lines << tr("%1 %2: %3 samples of %4, interval %5 ms (%6 Hz); metrics on %7")
                     .arg(run.test)
                     .arg(m_spec.kind == StepSpec::Kind::Position ? m_spec.distance : m_spec.speed)
                     .arg(run.capture.time.size())
                     .arg(run.capture.channels.join(QStringLiteral(",")))
                     .arg(s.mean * 1000.0, 0, 'f', 3)
                     .arg(s.mean > 0 ? 1.0 / s.mean : 0.0, 0, 'f', 1)
                     .arg(run.metricsChannel);
        for (const QString &k : StepMetrics::keys()) {
            const Metric &m = run.metrics.byKey(k);
            QString line = QStringLiteral("  %1 %2").arg(k, -20).arg(CliDescribe::metric(m, k, 2));
            if (m.value && m.resolution > 0)
                line += QStringLiteral("  (± %1)").arg(CliDescribe::metric(Metric{m.resolution, 0.0, {}}, k, 2));
            else if (!m.value)
                line += QStringLiteral("  ") + m.reason;
            lines << line;
        }
        QStringList gains;
        for (const TuningSnapshotEntry &e : run.tuning)
            gains << QStringLiteral("%1=%2").arg(e.key).arg(e.value);
        if (!gains.isEmpty())
            lines << tr("  tuning: %1").arg(gains.join(QLatin1Char(' ')));
        if (!m_output.isEmpty())
            lines << tr("  saved to %1").arg(m_output);
    }
    if (r.completed()) {
        lines << (r.returnedToStart ? tr("Back at the start position %1.").arg(r.startPosition)
                      : !m_spec.returnToStart
                      ? tr("Left at %1 (--no-return; started at %2).").arg(r.endPosition).arg(r.startPosition)
                      : r.stopNote);
        return succeed(json, lines.join(QLatin1Char('\n')));
    }
    if (!lines.isEmpty())
        out()->note(lines.join(QLatin1Char('\n')));
    Error e = r.error;
    if (e.code == ErrorCode::None)
        e.code = ErrorCode::Cancelled;
    e.message = r.stopNote.isEmpty() ? r.reason : r.reason + QLatin1Char(' ') + r.stopNote;
    if (r.abortCause.endsWith(QLatin1String("-limit"))) {
        // A limit tripped: its own error code ("limit", not a STOP's "cancelled").
        const CliExit code = r.moved && !r.stopConfirmed ? CliExit::DriveFailed : exitForFailure(e);
        out()->note(e.message);
        if (context()->globals.json) {
            QJsonObject doc = json;
            doc.insert(QStringLiteral("command"), name());
            doc.insert(QStringLiteral("ok"), false);
            doc.insert(QStringLiteral("exitCode"), int(code));
            doc.insert(
                QStringLiteral("error"),
                QJsonObject{{QStringLiteral("code"), QStringLiteral("limit")}, {QStringLiteral("message"), e.message}});
            out()->jsonLine(doc);
        }
        return finish(code);
    }
    if (r.moved && !r.stopConfirmed)
        return fail(e, json, CliExit::DriveFailed);
    fail(e, json); // refused by its prediction: OutOfRange, exit 2 (no motion sent)
}

} // namespace dd
