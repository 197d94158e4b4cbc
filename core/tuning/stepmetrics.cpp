#include "core/tuning/stepmetrics.h"

#include <QJsonValue>
#include <algorithm>
#include <cmath>

namespace dd {

namespace {
constexpr double Nan = std::numeric_limits<double>::quiet_NaN();

// The time a straight line through two samples reaches `level`.
double crossing(double t0, double v0, double t1, double v1, double level)
{
    if (v1 == v0)
        return t1;
    return t0 + (level - v0) / (v1 - v0) * (t1 - t0);
}

// The longest interval between consecutive samples from..to (indices into t), the ones a
// metric measured over that stretch rests on: a stall elsewhere in the record does not
// make it less certain.
double longestInterval(const QVector<double> &t, int from, int to)
{
    double worst = 0.0;
    for (int i = std::max(from, 1); i <= to && i < t.size(); ++i)
        worst = std::max(worst, t.at(i) - t.at(i - 1));
    return worst;
}

QString ms(double seconds)
{
    return QString::number(seconds * 1000.0, 'g', 3);
}

Metric peakOf(const CaptureData &c, const QString &channel, double resolutionShare)
{
    Metric m;
    const int col = c.columnOf(channel);
    if (col < 0) {
        m.reason = StepMetrics::tr("channel %1 was not captured").arg(channel);
        return m;
    }
    double peak = Nan;
    for (double v : c.columns.at(col))
        if (std::isfinite(v) && !(std::abs(v) <= std::abs(peak)))
            peak = v;
    if (!std::isfinite(peak)) {
        m.reason = StepMetrics::tr("channel %1 has no values").arg(channel);
        return m;
    }
    m.value = std::abs(peak);
    m.resolution = resolutionShare;
    return m;
}
} // namespace

const QStringList &StepMetrics::keys()
{
    static const QStringList k = {
        QStringLiteral("riseTime"),           QStringLiteral("overshoot"),        QStringLiteral("settlingTime2"),
        QStringLiteral("settlingTime5"),      QStringLiteral("steadyStateError"), QStringLiteral("steadyStateRipple"),
        QStringLiteral("peakFollowingError"), QStringLiteral("peakTorque"),       QStringLiteral("peakCurrent"),
        QStringLiteral("sampleInterval"),
    };
    return k;
}

const Metric &StepMetrics::byKey(const QString &key) const
{
    return const_cast<StepMetrics *>(this)->byKey(key);
}

Metric &StepMetrics::byKey(const QString &key)
{
    Metric *all[] = {&riseTime,          &overshoot,          &settlingTime2, &settlingTime5, &steadyStateError,
                     &steadyStateRipple, &peakFollowingError, &peakTorque,    &peakCurrent,   &sampleInterval};
    const int i = int(keys().indexOf(key));
    return *all[i >= 0 ? i : 0];
}

StepMetrics StepMetrics::compute(const CaptureData &c, const Input &in)
{
    StepMetrics m;
    const double dt = c.interval.count > 0 ? c.interval.mean : Nan;
    if (std::isfinite(dt)) {
        m.sampleInterval.value = dt;
        m.sampleInterval.resolution = 0.0;
    } else {
        m.sampleInterval.reason = tr("fewer than two samples");
    }
    m.peakFollowingError = peakOf(c, in.followingErrorChannel, 0.0);
    m.peakTorque = peakOf(c, in.torqueChannel, 0.0);
    m.peakCurrent = peakOf(c, in.currentChannel, 0.0);

    const int col = c.columnOf(in.channel);
    Metric *stepMetrics[] = {&m.riseTime,      &m.overshoot,        &m.settlingTime2,
                             &m.settlingTime5, &m.steadyStateError, &m.steadyStateRipple};
    auto failAll = [&](const QString &why) {
        for (Metric *x : stepMetrics) {
            x->value.reset();
            x->reason = why;
        }
        return m;
    };
    if (col < 0)
        return failAll(tr("the response channel %1 was not captured").arg(in.channel));
    if (!std::isfinite(dt))
        return failAll(tr("fewer than two samples"));

    // The step window: samples from the trigger to stepEnd.
    const QVector<double> &y = c.columns.at(col);
    const double end = std::isfinite(in.stepEnd) ? in.stepEnd : c.time.last();
    QVector<double> t, v;
    double before = 0.0;
    int beforeCount = 0;
    for (int i = 0; i < c.time.size(); ++i) {
        if (!std::isfinite(y.at(i)))
            continue;
        if (c.time.at(i) < 0.0) {
            before += y.at(i);
            ++beforeCount;
        } else if (c.time.at(i) <= end + 1e-9) {
            t.append(c.time.at(i));
            v.append(y.at(i));
        }
    }
    if (t.size() < 4)
        return failAll(tr("fewer than four samples in the step"));
    const double y0 = beforeCount > 0 ? before / beforeCount : v.first();

    // The steady state: the last fifth of the step window.
    const double tailFrom = t.first() + 0.8 * (t.last() - t.first());
    double tailSum = 0.0, tailMin = Nan, tailMax = Nan;
    int tailCount = 0;
    for (int i = 0; i < t.size(); ++i) {
        if (t.at(i) < tailFrom)
            continue;
        tailSum += v.at(i);
        tailMin = std::isfinite(tailMin) ? std::min(tailMin, v.at(i)) : v.at(i);
        tailMax = std::isfinite(tailMax) ? std::max(tailMax, v.at(i)) : v.at(i);
        ++tailCount;
    }
    const double steady = tailSum / std::max(tailCount, 1);
    const double target = std::isfinite(in.target) ? in.target : steady;
    const double step = target - y0;
    if (std::abs(step) < 1e-12)
        return failAll(tr("no step: the target equals the starting value"));
    const double dir = step > 0 ? 1.0 : -1.0;

    m.steadyStateError.value = target - steady;
    m.steadyStateError.resolution = 0.0;
    m.steadyStateRipple.value = tailMax - tailMin;
    m.steadyStateRipple.resolution = 0.0;

    // Rise time: 10 % to 90 % of the step, crossings interpolated between samples.
    double t10 = Nan, t90 = Nan;
    int n10 = -1, n90 = -1;
    for (int i = 1; i < t.size(); ++i) {
        const double a = (v.at(i - 1) - y0) * dir / std::abs(step), b = (v.at(i) - y0) * dir / std::abs(step);
        if (!std::isfinite(t10) && a < 0.1 && b >= 0.1) {
            t10 = crossing(t.at(i - 1), a, t.at(i), b, 0.1);
            n10 = i;
        }
        if (!std::isfinite(t90) && a < 0.9 && b >= 0.9) {
            t90 = crossing(t.at(i - 1), a, t.at(i), b, 0.9);
            n90 = i;
            break;
        }
    }
    if (!std::isfinite(t10) || !std::isfinite(t90)) {
        m.riseTime.reason = tr("the response never reached 90 % of the step");
        m.overshoot.reason = m.riseTime.reason;
    } else if (const double around = longestInterval(t, n10, n90); n90 - n10 < 1 || t90 - t10 < 2.0 * around) {
        // Fewer than two intervals between the 10 % and 90 % crossings: the interpolation
        // says more than the samples do, and a peak between samples would be missed.
        m.riseTime.reason = tr("the rise is shorter than two sample intervals (%1 ms): not resolvable at this "
                               "sample rate")
                                .arg(ms(around));
        m.overshoot.reason = m.riseTime.reason;
    } else {
        m.riseTime.value = t90 - t10;
        m.riseTime.resolution = dt;
        double peak = 0.0;
        for (int i = 0; i < t.size(); ++i)
            peak = std::max(peak, (v.at(i) - y0) * dir);
        m.overshoot.value = std::max(0.0, 100.0 * (peak - std::abs(step)) / std::abs(step));
        // A peak between two samples is missed by at most the change over one interval.
        m.overshoot.resolution = 100.0 * (0.8 / (t90 - t10)) * dt * 0.5;
    }

    // Settling: from the step to the first sample after which every sample stays in the band.
    for (auto [metric, band] : {std::pair<Metric *, double>{&m.settlingTime2, 0.02}, {&m.settlingTime5, 0.05}}) {
        int lastOutside = -1;
        for (int i = 0; i < t.size(); ++i)
            if (std::abs(v.at(i) - target) > band * std::abs(step))
                lastOutside = i;
        if (lastOutside == t.size() - 1) {
            metric->reason = tr("the response did not settle within ±%1 % in the record").arg(band * 100.0);
        } else if (lastOutside < 0) {
            metric->value = 0.0;
            metric->resolution = dt;
        } else {
            metric->value = t.at(lastOutside + 1);
            metric->resolution = dt;
            if (lastOutside + 1 < 2)
                metric->reason.clear();
        }
        const double around = longestInterval(t, 1, std::max(lastOutside + 1, 1));
        if (metric->value && *metric->value < 2.0 * around) {
            metric->value.reset();
            metric->reason = tr("settles within two sample intervals (%1 ms): not resolvable at this sample rate")
                                 .arg(ms(around));
        }
    }
    return m;
}

QJsonObject StepMetrics::valuesJson() const
{
    QJsonObject o;
    for (const QString &k : keys()) {
        const Metric &x = byKey(k);
        o.insert(k, x.value ? QJsonValue(*x.value) : QJsonValue(QJsonValue::Null));
    }
    return o;
}

QJsonObject StepMetrics::resolutionsJson() const
{
    QJsonObject o;
    for (const QString &k : keys())
        if (byKey(k).value)
            o.insert(k, byKey(k).resolution);
    return o;
}

QStringList StepMetrics::notes() const
{
    QStringList out;
    for (const QString &k : keys())
        if (!byKey(k).value && !byKey(k).reason.isEmpty())
            out << QStringLiteral("%1: %2").arg(k, byKey(k).reason);
    return out;
}

bool StepMetrics::fromJson(const QJsonObject &values, const QJsonObject &resolutions, const QStringList &notes,
                           StepMetrics *out, QString *error)
{
    StepMetrics m;
    for (const QString &k : keys()) {
        if (!values.contains(k)) {
            *error = tr("metrics.%1 is missing").arg(k);
            return false;
        }
        const QJsonValue v = values.value(k);
        Metric &x = m.byKey(k);
        if (v.isDouble() && std::isfinite(v.toDouble())) {
            x.value = v.toDouble();
            const QJsonValue r = resolutions.value(k);
            if (!r.isUndefined() && (!r.isDouble() || r.toDouble() < 0.0)) {
                *error = tr("resolution.%1 must be a number ≥ 0").arg(k);
                return false;
            }
            x.resolution = r.toDouble(0.0);
        } else if (v.isNull()) {
            const QString prefix = k + QStringLiteral(": ");
            for (const QString &n : notes)
                if (n.startsWith(prefix))
                    x.reason = n.mid(prefix.size());
        } else {
            *error = tr("metrics.%1 must be a number or null").arg(k);
            return false;
        }
    }
    for (auto it = values.begin(); it != values.end(); ++it) {
        if (!keys().contains(it.key())) {
            *error = tr("metrics.%1 is not a known metric").arg(it.key());
            return false;
        }
    }
    *out = m;
    return true;
}

} // namespace dd
