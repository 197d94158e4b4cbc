#include "core/tuning/tuningrun.h"

#include "core/common/family.h"
#include "core/params/tuningentry.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>
#include <cmath>

namespace dd {

namespace {
const QStringList &testTypes()
{
    static const QStringList t = {QStringLiteral("capture"), QStringLiteral("velocity-step"),
                                  QStringLiteral("position-step"), QStringLiteral("reversal")};
    return t;
}

QJsonValue number(double v)
{
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

// Small checked readers: each returns false and sets *why (translated) on a wrong type.
struct Reader
{
    const QString &source;
    QString *why;

    bool fail(const QString &message) const
    {
        *why = QStringLiteral("%1: %2").arg(source, message);
        return false;
    }
    bool object(const QJsonObject &o, const QString &field, QJsonObject *out, const QString &where) const
    {
        const QJsonValue v = o.value(field);
        if (!v.isObject())
            return fail(TuningRun::tr("%1 must be an object").arg(where + field));
        *out = v.toObject();
        return true;
    }
    bool string(const QJsonObject &o, const QString &field, QString *out, const QString &where,
                bool optional = false) const
    {
        const QJsonValue v = o.value(field);
        if (optional && v.isUndefined())
            return true;
        if (!v.isString())
            return fail(TuningRun::tr("%1 must be a string").arg(where + field));
        *out = v.toString();
        return true;
    }
    bool real(const QJsonObject &o, const QString &field, double *out, const QString &where, double min,
              double max) const
    {
        const QJsonValue v = o.value(field);
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            return fail(TuningRun::tr("%1 must be a number").arg(where + field));
        if (v.toDouble() < min || v.toDouble() > max)
            return fail(
                TuningRun::tr("%1 = %2 is outside %3 to %4")
                    .arg(where + field, QString::number(v.toDouble()), QString::number(min), QString::number(max)));
        *out = v.toDouble();
        return true;
    }
    bool integer(const QJsonObject &o, const QString &field, qint64 *out, const QString &where, qint64 min,
                 qint64 max) const
    {
        double d = 0.0;
        if (!real(o, field, &d, where, double(min), double(max)))
            return false;
        if (d != std::floor(d))
            return fail(TuningRun::tr("%1 must be a whole number").arg(where + field));
        *out = qint64(d);
        return true;
    }
};
} // namespace

QString TuningRun::formatName()
{
    return QStringLiteral("drivedesk-run");
}

QJsonObject TuningRun::toJson() const
{
    QJsonObject root;
    root.insert(QStringLiteral("format"), formatName());
    root.insert(QStringLiteral("formatVersion"), FormatVersion);
    root.insert(QStringLiteral("created"), created.toUTC().toString(Qt::ISODateWithMs));
    root.insert(QStringLiteral("drive"),
                QJsonObject{{QStringLiteral("family"), family},
                            {QStringLiteral("address"), address},
                            {QStringLiteral("model"), model},
                            {QStringLiteral("firmware"), firmware}});
    root.insert(QStringLiteral("link"),
                QJsonObject{{QStringLiteral("kind"), linkKind}, {QStringLiteral("description"), linkDescription}});
    root.insert(QStringLiteral("test"),
                QJsonObject{{QStringLiteral("type"), test}, {QStringLiteral("parameters"), testParameters}});
    root.insert(QStringLiteral("trigger"),
                QJsonObject{{QStringLiteral("expression"), settings.trigger.toString()},
                            {QStringLiteral("source"), capture.triggerSource},
                            {QStringLiteral("mode"), CaptureSettings::modeId(settings.mode)},
                            {QStringLiteral("prePercent"), settings.prePercent},
                            {QStringLiteral("duration"), settings.durationS},
                            {QStringLiteral("timeout"), settings.timeoutS},
                            {QStringLiteral("preTriggerSamples"), capture.preTriggerSamples}});
    const IntervalStats &s = capture.interval;
    root.insert(QStringLiteral("sampleInterval"),
                QJsonObject{{QStringLiteral("count"), s.count},
                            {QStringLiteral("mean"), s.mean},
                            {QStringLiteral("median"), s.median},
                            {QStringLiteral("min"), s.min},
                            {QStringLiteral("max"), s.max}});
    QJsonArray gaps;
    for (const CaptureGap &g : capture.gaps)
        gaps.append(QJsonObject{{QStringLiteral("from"), g.from}, {QStringLiteral("to"), g.to}});
    root.insert(QStringLiteral("gaps"), gaps);
    QJsonArray channels;
    QJsonObject samples;
    QJsonArray time;
    for (double t : capture.time)
        time.append(t);
    samples.insert(QStringLiteral("time"), time);
    for (int c = 0; c < capture.channels.size(); ++c) {
        channels.append(
            QJsonObject{{QStringLiteral("id"), capture.channels.at(c)}, {QStringLiteral("unit"), units.value(c)}});
        QJsonArray col;
        for (double v : capture.columns.at(c))
            col.append(number(v));
        samples.insert(capture.channels.at(c), col);
    }
    root.insert(QStringLiteral("channels"), channels);
    root.insert(QStringLiteral("samples"), samples);
    root.insert(QStringLiteral("metricsChannel"), metricsChannel);
    root.insert(QStringLiteral("metrics"), metrics.valuesJson());
    root.insert(QStringLiteral("resolution"), metrics.resolutionsJson());
    root.insert(QStringLiteral("metricNotes"), QJsonArray::fromStringList(metrics.notes()));
    QJsonArray snapshot;
    for (const TuningSnapshotEntry &e : tuning)
        snapshot.append(QJsonObject{{QStringLiteral("index"), e.index},
                                    {QStringLiteral("key"), e.key},
                                    {QStringLiteral("role"), e.role},
                                    {QStringLiteral("value"), double(e.value)}});
    root.insert(QStringLiteral("tuning"), snapshot);
    root.insert(QStringLiteral("notes"), notes);
    if (!outcome.isEmpty())
        root.insert(QStringLiteral("result"),
                    QJsonObject{{QStringLiteral("outcome"), outcome},
                                {QStringLiteral("abortCause"), abortCause},
                                {QStringLiteral("reason"), abortReason}});
    return root;
}

QByteArray TuningRun::toBytes() const
{
    return QJsonDocument(toJson()).toJson(QJsonDocument::Indented);
}

Error TuningRun::fromBytes(const QByteArray &bytes, const QString &source, TuningRun *out)
{
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &pe);
    if (pe.error != QJsonParseError::NoError)
        return {ErrorCode::Malformed,
                tr("%1 is not valid JSON: %2 at byte %3").arg(source, pe.errorString(), QString::number(pe.offset))};
    if (!doc.isObject())
        return {ErrorCode::Malformed, tr("%1: the top level must be an object").arg(source)};
    return fromJson(doc.object(), source, out);
}

Error TuningRun::fromJson(const QJsonObject &root, const QString &source, TuningRun *out)
{
    QString why;
    Reader r{source, &why};
    auto bad = [&why] { return Error{ErrorCode::Malformed, why}; };
    static const QStringList known = {
        QStringLiteral("format"),   QStringLiteral("formatVersion"),  QStringLiteral("created"),
        QStringLiteral("drive"),    QStringLiteral("link"),           QStringLiteral("test"),
        QStringLiteral("trigger"),  QStringLiteral("sampleInterval"), QStringLiteral("gaps"),
        QStringLiteral("channels"), QStringLiteral("samples"),        QStringLiteral("metricsChannel"),
        QStringLiteral("metrics"),  QStringLiteral("resolution"),     QStringLiteral("metricNotes"),
        QStringLiteral("tuning"),   QStringLiteral("notes"),          QStringLiteral("result")};
    for (auto it = root.begin(); it != root.end(); ++it)
        if (!known.contains(it.key()) && !it.key().startsWith(QLatin1Char('_')))
            return {ErrorCode::Malformed, tr("%1: unknown field \"%2\"").arg(source, it.key())};
    if (root.value(QStringLiteral("format")).toString() != formatName())
        return {ErrorCode::Malformed,
                tr("%1 is not a DriveDesk run file (format must be \"%2\")").arg(source, formatName())};
    if (!root.value(QStringLiteral("formatVersion")).isDouble())
        return {ErrorCode::Malformed,
                tr("%1: formatVersion must be a number (%2), not %3")
                    .arg(source, QString::number(FormatVersion),
                         QString::fromUtf8(QJsonDocument(QJsonArray{root.value(QStringLiteral("formatVersion"))})
                                               .toJson(QJsonDocument::Compact)
                                               .mid(1)
                                               .chopped(1)))};
    if (root.value(QStringLiteral("formatVersion")).toInt(-1) != FormatVersion)
        return {ErrorCode::NotSupported,
                tr("%1: run format version %2 is not supported (this DriveDesk reads %3)")
                    .arg(source, root.value(QStringLiteral("formatVersion")).toVariant().toString(),
                         QString::number(FormatVersion))};
    TuningRun run;
    QString createdText;
    if (!r.string(root, QStringLiteral("created"), &createdText, QString()))
        return bad();
    run.created = QDateTime::fromString(createdText, Qt::ISODateWithMs);
    if (!run.created.isValid())
        return {ErrorCode::Malformed, tr("%1: created \"%2\" is not an ISO 8601 time").arg(source, createdText)};

    QJsonObject drive, link, test, trigger, samples, interval;
    if (!r.object(root, QStringLiteral("drive"), &drive, QString())
        || !r.object(root, QStringLiteral("link"), &link, QString())
        || !r.object(root, QStringLiteral("test"), &test, QString())
        || !r.object(root, QStringLiteral("trigger"), &trigger, QString())
        || !r.object(root, QStringLiteral("samples"), &samples, QString())
        || !r.object(root, QStringLiteral("sampleInterval"), &interval, QString()))
        return bad();
    qint64 address = 0;
    if (!r.string(drive, QStringLiteral("family"), &run.family, QStringLiteral("drive."))
        || !r.integer(drive, QStringLiteral("address"), &address, QStringLiteral("drive."), 0, 65535)
        || !r.string(drive, QStringLiteral("model"), &run.model, QStringLiteral("drive."), true)
        || !r.string(drive, QStringLiteral("firmware"), &run.firmware, QStringLiteral("drive."), true))
        return bad();
    if (!familyFromId(run.family))
        return {ErrorCode::Malformed,
                tr("%1: drive.family \"%2\" is not a known family (%3)")
                    .arg(source, run.family, familyIds().join(QStringLiteral(", ")))};
    run.address = int(address);
    if (!r.string(link, QStringLiteral("kind"), &run.linkKind, QStringLiteral("link."))
        || !r.string(link, QStringLiteral("description"), &run.linkDescription, QStringLiteral("link.")))
        return bad();
    if (!r.string(test, QStringLiteral("type"), &run.test, QStringLiteral("test.")))
        return bad();
    if (!testTypes().contains(run.test))
        return {
            ErrorCode::Malformed,
            tr("%1: test.type \"%2\" is not one of %3").arg(source, run.test, testTypes().join(QStringLiteral(", ")))};
    if (test.contains(QStringLiteral("parameters")) && !test.value(QStringLiteral("parameters")).isObject())
        return {ErrorCode::Malformed, tr("%1: test.parameters must be an object").arg(source)};
    run.testParameters = test.value(QStringLiteral("parameters")).toObject();

    // Trigger and record settings.
    QString expression, mode;
    qint64 pre = 0;
    if (!r.string(trigger, QStringLiteral("expression"), &expression, QStringLiteral("trigger."))
        || !r.string(trigger, QStringLiteral("source"), &run.capture.triggerSource, QStringLiteral("trigger."))
        || !r.string(trigger, QStringLiteral("mode"), &mode, QStringLiteral("trigger."))
        || !r.real(trigger, QStringLiteral("prePercent"), &run.settings.prePercent, QStringLiteral("trigger."), 0, 100)
        || !r.real(trigger, QStringLiteral("duration"), &run.settings.durationS, QStringLiteral("trigger."), 1e-6,
                   86400)
        || !r.real(trigger, QStringLiteral("timeout"), &run.settings.timeoutS, QStringLiteral("trigger."), 0, 86400)
        || !r.integer(trigger, QStringLiteral("preTriggerSamples"), &pre, QStringLiteral("trigger."), 0, 1 << 30))
        return bad();
    if (Error e = TriggerSpec::parse(expression, &run.settings.trigger))
        return {ErrorCode::Malformed, QStringLiteral("%1: trigger.expression: %2").arg(source, e.message)};
    const auto m = CaptureSettings::modeFromId(mode);
    if (!m)
        return {ErrorCode::Malformed, tr("%1: trigger.mode \"%2\" is not single, normal or auto").arg(source, mode)};
    run.settings.mode = *m;

    // Channels and samples: columns of equal length, time finite and non-decreasing.
    const QJsonValue channelsValue = root.value(QStringLiteral("channels"));
    if (!channelsValue.isArray() || channelsValue.toArray().isEmpty())
        return {ErrorCode::Malformed, tr("%1: channels must be a non-empty array").arg(source)};
    for (const QJsonValue &cv : channelsValue.toArray()) {
        QString id, unit;
        const QJsonObject c = cv.toObject();
        if (!cv.isObject() || !r.string(c, QStringLiteral("id"), &id, QStringLiteral("channels[]."))
            || !r.string(c, QStringLiteral("unit"), &unit, QStringLiteral("channels[].")))
            return why.isEmpty() ? Error{ErrorCode::Malformed, tr("%1: each channel must be an object").arg(source)}
                                 : bad();
        if (id.isEmpty() || id == QLatin1String("time") || run.capture.channels.contains(id))
            return {ErrorCode::Malformed, tr("%1: channel id \"%2\" is empty, \"time\" or repeated").arg(source, id)};
        run.capture.channels << id;
        run.units << unit;
    }
    for (auto it = samples.begin(); it != samples.end(); ++it)
        if (it.key() != QLatin1String("time") && !run.capture.channels.contains(it.key()))
            return {ErrorCode::Malformed, tr("%1: samples.%2 is not a listed channel").arg(source, it.key())};
    const QJsonValue timeValue = samples.value(QStringLiteral("time"));
    if (!timeValue.isArray())
        return {ErrorCode::Malformed, tr("%1: samples.time must be an array").arg(source)};
    const QJsonArray time = timeValue.toArray();
    if (time.size() > MaxSamples)
        return {ErrorCode::Malformed,
                tr("%1: samples.time holds %2 samples, more than the %3 a run file may hold")
                    .arg(source, QString::number(time.size()), QString::number(MaxSamples))};
    double previous = -INFINITY;
    int negatives = 0;
    for (int i = 0; i < time.size(); ++i) {
        const double t = time.at(i).toDouble(NAN);
        if (!time.at(i).isDouble() || !std::isfinite(t))
            return {ErrorCode::Malformed, tr("%1: samples.time[%2] must be a number").arg(source, QString::number(i))};
        if (t < previous)
            return {ErrorCode::Malformed, tr("%1: samples.time[%2] goes back in time").arg(source, QString::number(i))};
        previous = t;
        if (t < -1e-9)
            ++negatives;
        run.capture.time.append(t);
    }
    if (negatives != pre)
        return {ErrorCode::Malformed,
                tr("%1: trigger.preTriggerSamples is %2 but %3 samples are before the trigger")
                    .arg(source, QString::number(pre), QString::number(negatives))};
    run.capture.preTriggerSamples = negatives;
    for (const QString &id : std::as_const(run.capture.channels)) {
        const QJsonValue colValue = samples.value(id);
        if (!colValue.isArray() || colValue.toArray().size() != time.size())
            return {ErrorCode::Malformed,
                    tr("%1: samples.%2 must be an array of %3 values, like samples.time")
                        .arg(source, id, QString::number(time.size()))};
        QVector<double> col;
        col.reserve(time.size());
        const QJsonArray a = colValue.toArray();
        for (int i = 0; i < a.size(); ++i) {
            if (a.at(i).isNull())
                col.append(NAN);
            else if (a.at(i).isDouble() && std::isfinite(a.at(i).toDouble()))
                col.append(a.at(i).toDouble());
            else
                return {ErrorCode::Malformed,
                        tr("%1: samples.%2[%3] must be a number or null").arg(source, id, QString::number(i))};
        }
        run.capture.columns.append(col);
    }
    run.capture.interval = IntervalStats::of(run.capture.time);
    run.capture.gaps = CaptureGap::of(run.capture.time);

    // Metrics.
    QJsonObject metrics;
    if (!r.object(root, QStringLiteral("metrics"), &metrics, QString())
        || !r.string(root, QStringLiteral("metricsChannel"), &run.metricsChannel, QString()))
        return bad();
    if (!run.metricsChannel.isEmpty() && !run.capture.channels.contains(run.metricsChannel))
        return {ErrorCode::Malformed,
                tr("%1: metricsChannel \"%2\" is not a listed channel").arg(source, run.metricsChannel)};
    const QJsonValue notesValue = root.value(QStringLiteral("metricNotes"));
    QStringList metricNotes;
    for (const QJsonValue &n : notesValue.toArray()) {
        if (!n.isString())
            return {ErrorCode::Malformed, tr("%1: metricNotes must be strings").arg(source)};
        metricNotes << n.toString();
    }
    if (!notesValue.isUndefined() && !notesValue.isArray())
        return {ErrorCode::Malformed, tr("%1: metricNotes must be an array of strings").arg(source)};
    const QJsonValue res = root.value(QStringLiteral("resolution"));
    if (!res.isUndefined() && !res.isObject())
        return {ErrorCode::Malformed, tr("%1: resolution must be an object").arg(source)};
    QString metricError;
    if (!StepMetrics::fromJson(metrics, res.toObject(), metricNotes, &run.metrics, &metricError))
        return {ErrorCode::Malformed, QStringLiteral("%1: %2").arg(source, metricError)};

    // The tuning snapshot.
    const QJsonValue tuningValue = root.value(QStringLiteral("tuning"));
    if (!tuningValue.isArray())
        return {ErrorCode::Malformed, tr("%1: tuning must be an array").arg(source)};
    for (const QJsonValue &tv : tuningValue.toArray()) {
        TuningSnapshotEntry e;
        qint64 index = 0;
        const QJsonObject o = tv.toObject();
        if (!tv.isObject())
            return {ErrorCode::Malformed, tr("%1: each tuning entry must be an object").arg(source)};
        if (!r.integer(o, QStringLiteral("index"), &index, QStringLiteral("tuning[]."), 0, 65535)
            || !r.string(o, QStringLiteral("key"), &e.key, QStringLiteral("tuning[]."))
            || !r.string(o, QStringLiteral("role"), &e.role, QStringLiteral("tuning[]."))
            || !r.integer(o, QStringLiteral("value"), &e.value, QStringLiteral("tuning[]."), -(qint64(1) << 53),
                          qint64(1) << 53))
            return bad();
        if (!e.role.isEmpty() && !TuningEntry::knownRoles().contains(e.role))
            return {ErrorCode::Malformed, tr("%1: tuning role \"%2\" is unknown").arg(source, e.role)};
        e.index = int(index); // before the check below (it compared with -1: duplicates passed)
        for (const TuningSnapshotEntry &other : std::as_const(run.tuning))
            if (other.index == e.index || other.key.compare(e.key, Qt::CaseInsensitive) == 0)
                return {ErrorCode::Malformed, tr("%1: tuning lists %2 twice").arg(source, e.key)};
        run.tuning.append(e);
    }
    if (!r.string(root, QStringLiteral("notes"), &run.notes, QString(), true))
        return bad();
    const QJsonValue result = root.value(QStringLiteral("result"));
    if (!result.isUndefined()) {
        const QJsonObject o = result.toObject();
        if (!result.isObject() || !r.string(o, QStringLiteral("outcome"), &run.outcome, QStringLiteral("result."))
            || !r.string(o, QStringLiteral("abortCause"), &run.abortCause, QStringLiteral("result."), true)
            || !r.string(o, QStringLiteral("reason"), &run.abortReason, QStringLiteral("result."), true))
            return why.isEmpty() ? Error{ErrorCode::Malformed, tr("%1: result must be an object").arg(source)} : bad();
        if (run.outcome != QLatin1String("completed") && run.outcome != QLatin1String("aborted"))
            return {ErrorCode::Malformed,
                    tr("%1: result.outcome \"%2\" is not completed or aborted").arg(source, run.outcome)};
    }
    QJsonValue gaps = root.value(QStringLiteral("gaps"));
    if (!gaps.isUndefined() && !gaps.isArray())
        return {ErrorCode::Malformed, tr("%1: gaps must be an array").arg(source)};
    *out = run;
    return Error::none();
}

Error TuningRun::save(const QString &path) const
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {ErrorCode::FileError, tr("Cannot write %1: %2").arg(path, f.errorString())};
    f.write(toBytes());
    if (!f.commit())
        return {ErrorCode::FileError, tr("Cannot write %1: %2").arg(path, f.errorString())};
    return Error::none();
}

Error TuningRun::load(const QString &path, TuningRun *out)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {ErrorCode::FileError, tr("Cannot open %1: %2").arg(path, f.errorString())};
    if (f.size() > MaxFileSize)
        return {ErrorCode::Malformed, tr("%1 is larger than %2 MiB: not a run file").arg(path).arg(MaxFileSize >> 20)};
    TuningRun run;
    if (Error e = fromBytes(f.readAll(), QFileInfo(path).fileName(), &run))
        return e;
    run.label = QFileInfo(path).completeBaseName();
    *out = run;
    return Error::none();
}

} // namespace dd
