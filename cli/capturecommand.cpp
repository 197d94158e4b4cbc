#include "cli/capturecommand.h"

#include "cli/clivalues.h"

#include "core/drive/drive.h"
#include "core/params/parameterdictionary.h"
#include "core/tuning/capturesession.h"
#include "core/tuning/tuningrun.h"

#include <QDateTime>
#include <QFileInfo>
#include <cmath>

namespace dd {

namespace {
bool positive(const CliInvocation &inv, const char *name, double min, double max, double *out, QString *error)
{
    const QString key = QLatin1String(name);
    if (!inv.has(key))
        return true;
    bool ok = false;
    const double v = inv.value(key).toDouble(&ok);
    if (!ok || !std::isfinite(v) || v < min || v > max) {
        *error = CaptureCommand::tr("--%1 must be a number from %2 to %3, not \"%4\".")
                     .arg(key)
                     .arg(min)
                     .arg(max)
                     .arg(inv.value(key));
        return false;
    }
    *out = v;
    return true;
}
} // namespace

bool CaptureCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("CHANNEL,..."), error))
        return false;
    for (const QString &c : inv.positionals.at(0).split(QLatin1Char(','), Qt::SkipEmptyParts))
        if (!m_channels.contains(c.trimmed()))
            m_channels << c.trimmed();
    if (m_channels.isEmpty()) {
        *error = tr("Name at least one channel, e.g. speed,current.");
        return false;
    }
    if (inv.has(QStringLiteral("trigger"))) {
        if (Error e = TriggerSpec::parse(inv.value(QStringLiteral("trigger")), &m_settings.trigger)) {
            *error = e.message;
            return false;
        }
        if (m_settings.trigger.kind == TriggerSpec::Kind::MotionStart) {
            *error = tr("The motion trigger belongs to step tests: use drivedesk-cli step.");
            return false;
        }
        if (m_settings.trigger.isLevel() && !m_channels.contains(m_settings.trigger.channel)) {
            *error = tr("The trigger channel %1 must be one of the captured channels (%2).")
                         .arg(m_settings.trigger.channel, m_channels.join(QLatin1Char(',')));
            return false;
        }
    }
    if (!positive(inv, "duration", 0.01, 600.0, &m_settings.durationS, error)
        || !positive(inv, "timeout", 0.0, 3600.0, &m_settings.timeoutS, error))
        return false;
    if (inv.has(QStringLiteral("pre"))) {
        // The same --pre as step's: a share of the record or seconds before the trigger.
        const auto pre = CliValues::preTrigger(inv.value(QStringLiteral("pre")), m_settings.durationS, error);
        if (!pre)
            return false;
        m_settings.prePercent = pre->percent ? pre->value : 100.0 * pre->value / m_settings.durationS;
    }
    if (inv.has(QStringLiteral("mode"))) {
        const auto mode = CaptureSettings::modeFromId(inv.value(QStringLiteral("mode")));
        if (!mode || *mode == CaptureSettings::Mode::Normal) {
            *error = tr("--mode must be single or auto, not \"%1\".").arg(inv.value(QStringLiteral("mode")));
            return false;
        }
        m_settings.mode = *mode;
    }
    m_output = inv.value(QStringLiteral("output"));
    if (m_output.isEmpty()) {
        *error = tr("Name the run file: -o RUN.ddrun.");
        return false;
    }
    m_notes = inv.value(QStringLiteral("notes"));
    return true;
}

void CaptureCommand::start()
{
    const QList<ChannelInfo> offered = drive()->channels();
    for (const QString &c : std::as_const(m_channels)) {
        bool known = false;
        for (const ChannelInfo &i : offered)
            known = known || i.id == c;
        if (!known) {
            QStringList ids;
            for (const ChannelInfo &i : offered)
                ids << i.id;
            fail({ErrorCode::InvalidArgument,
                  tr("This drive has no channel %1 (it has %2).").arg(c, ids.join(QStringLiteral(", ")))},
                 {}, CliExit::Usage);
            return;
        }
    }
    m_session = new CaptureSession(drive(), this);
    connect(m_session, &CaptureSession::captured, this, &CaptureCommand::onCaptured);
    connect(m_session, &CaptureSession::failed, this, [this](const Error &e) { fail(e); });
    connect(m_session, &CaptureSession::watching, this,
            [this] { out()->note(tr("Armed: waiting for the trigger %1.").arg(m_settings.trigger.toString())); });
    m_session->start(m_settings, m_channels);
}

void CaptureCommand::interrupt(int)
{
    if (m_session)
        m_session->stop();
    fail({ErrorCode::Cancelled, tr("Capture cancelled before the trigger came.")});
}

void CaptureCommand::onCaptured(const CaptureData &capture)
{
    TuningRun run;
    run.created = QDateTime::currentDateTimeUtc();
    const DriveIdentity id = drive()->identity();
    run.family = familyId(drive()->family());
    run.address = drive()->address();
    run.model = id.model;
    run.firmware = id.firmware;
    run.linkKind = context()->globals.isCanLink() ? QStringLiteral("can") : QStringLiteral("serial");
    run.linkDescription = id.link.isEmpty() ? context()->globals.connection.linkName() : id.link;
    run.settings = m_settings;
    run.capture = capture;
    for (const QString &c : std::as_const(m_channels)) {
        QString unit;
        for (const ChannelInfo &i : drive()->channels())
            if (i.id == c)
                unit = i.unit;
        run.units << unit;
    }
    run.notes = m_notes;
    run.label = QFileInfo(m_output).completeBaseName();

    // The tuning parameters as the drive has them now (read, not assumed).
    const ParameterDictionary &dict = drive()->parameterDictionary();
    QList<int> indices;
    for (const TuningEntry &e : dict.tuning())
        indices << e.index;
    auto save = [this, run](const QMap<int, qint64> &values) mutable {
        const ParameterDictionary &d = drive()->parameterDictionary();
        for (const TuningEntry &e : d.tuning())
            if (values.contains(e.index))
                run.tuning.append({e.index, d.byIndex(e.index)->key, e.role, values.value(e.index)});
        if (Error e = run.save(m_output)) {
            fail(e);
            return;
        }
        const IntervalStats &s = run.capture.interval;
        const QString text = tr("%1: %2 samples (%3 before the trigger), trigger %4, interval %5 ms (%6 Hz), %7 "
                                "gap(s), %8 tuning parameter(s)")
                                 .arg(m_output)
                                 .arg(run.capture.time.size())
                                 .arg(run.capture.preTriggerSamples)
                                 .arg(run.capture.triggerSource)
                                 .arg(s.mean * 1000.0, 0, 'f', 3)
                                 .arg(s.mean > 0 ? 1.0 / s.mean : 0.0, 0, 'f', 1)
                                 .arg(run.capture.gaps.size())
                                 .arg(run.tuning.size());
        succeed({{QStringLiteral("file"), m_output},
                 {QStringLiteral("samples"), int(run.capture.time.size())},
                 {QStringLiteral("preTriggerSamples"), run.capture.preTriggerSamples},
                 {QStringLiteral("trigger"), run.capture.triggerSource},
                 {QStringLiteral("sampleInterval"), s.mean},
                 {QStringLiteral("gaps"), int(run.capture.gaps.size())}},
                text);
    };
    if (indices.isEmpty()) {
        save({});
        return;
    }
    onFinished(drive()->readParameters(indices), [this, save](DriveReply *r) mutable {
        if (!r->ok()) {
            fail(r->error());
            return;
        }
        save(r->parameters());
    });
}

} // namespace dd
