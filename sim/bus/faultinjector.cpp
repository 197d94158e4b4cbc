#include "sim/bus/faultinjector.h"

#include <QStringList>

#include <algorithm>

namespace dd {

namespace {
double clampRate(double r)
{
    return std::clamp(r, 0.0, 1.0);
}

std::optional<double> parseRate(QString text)
{
    bool percent = false;
    text = text.trimmed();
    if (text.endsWith(QLatin1Char('%'))) {
        percent = true;
        text.chop(1);
    }
    bool ok = false;
    double v = text.toDouble(&ok);
    if (!ok)
        return std::nullopt;
    if (percent)
        v /= 100.0;
    if (v < 0.0 || v > 1.0)
        return std::nullopt;
    return v;
}

std::optional<int> parseNonNegativeInt(const QString &text)
{
    bool ok = false;
    const int v = text.trimmed().toInt(&ok);
    if (!ok || v < 0)
        return std::nullopt;
    return v;
}
} // namespace

// --- FaultSettings ------------------------------------------------------------------------

std::optional<FaultSettings> FaultSettings::parse(const QString &spec, QString *error)
{
    FaultSettings s;
    const auto fail = [error](const QString &message) -> std::optional<FaultSettings> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QStringList items = spec.split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &rawItem : items) {
        const QString item = rawItem.trimmed();
        if (item.isEmpty())
            continue;
        const qsizetype eq = item.indexOf(QLatin1Char('='));
        const QString key = (eq < 0 ? item : item.left(eq)).trimmed().toLower();
        const QString value = eq < 0 ? QString() : item.mid(eq + 1).trimmed();
        if (key == QLatin1String("silent")) {
            if (eq < 0 || value == QLatin1String("1") || value.compare(QLatin1String("true"), Qt::CaseInsensitive) == 0)
                s.silent = true;
            else if (value == QLatin1String("0") || value.compare(QLatin1String("false"), Qt::CaseInsensitive) == 0)
                s.silent = false;
            else
                return fail(QStringLiteral("fault option 'silent': expected 0 or 1, got '%1'").arg(value));
            continue;
        }
        if (eq < 0)
            return fail(QStringLiteral("fault option '%1' needs a value (key=value)").arg(item));
        if (key == QLatin1String("drop") || key == QLatin1String("corrupt")) {
            const auto rate = parseRate(value);
            if (!rate)
                return fail(
                    QStringLiteral("fault option '%1': expected a rate 0..1 or 0..100%, got '%2'").arg(key, value));
            (key == QLatin1String("drop") ? s.dropRate : s.corruptRate) = *rate;
        } else if (key == QLatin1String("latency") || key == QLatin1String("jitter")) {
            const auto ms = parseNonNegativeInt(value);
            if (!ms)
                return fail(QStringLiteral("fault option '%1': expected milliseconds >= 0, got '%2'").arg(key, value));
            (key == QLatin1String("latency") ? s.extraLatencyMs : s.latencyJitterMs) = *ms;
        } else if (key == QLatin1String("seed")) {
            bool ok = false;
            const uint seed = value.toUInt(&ok);
            if (!ok)
                return fail(QStringLiteral("fault option 'seed': expected an unsigned integer, got '%1'").arg(value));
            s.seed = seed;
        } else {
            return fail(
                QStringLiteral("unknown fault option '%1' (known: drop, corrupt, latency, jitter, silent, seed)")
                    .arg(key));
        }
    }
    return s;
}

QString FaultSettings::toString() const
{
    return QStringLiteral("drop=%1,corrupt=%2,latency=%3,jitter=%4,silent=%5,seed=%6")
        .arg(QString::number(dropRate, 'g', 17), QString::number(corruptRate, 'g', 17))
        .arg(extraLatencyMs)
        .arg(latencyJitterMs)
        .arg(silent ? 1 : 0)
        .arg(seed);
}

bool FaultSettings::operator==(const FaultSettings &o) const
{
    return dropRate == o.dropRate && corruptRate == o.corruptRate && extraLatencyMs == o.extraLatencyMs
        && latencyJitterMs == o.latencyJitterMs && silent == o.silent && seed == o.seed;
}

// --- FaultInjector ------------------------------------------------------------------------

FaultInjector::FaultInjector()
    : FaultInjector(FaultSettings{})
{
}

FaultInjector::FaultInjector(const FaultSettings &settings)
{
    setSettings(settings);
}

void FaultInjector::setSettings(const FaultSettings &settings)
{
    m_settings = settings;
    m_settings.dropRate = clampRate(m_settings.dropRate);
    m_settings.corruptRate = clampRate(m_settings.corruptRate);
    m_settings.extraLatencyMs = std::max(0, m_settings.extraLatencyMs);
    m_settings.latencyJitterMs = std::max(0, m_settings.latencyJitterMs);
    m_rng.seed(m_settings.seed);
    m_lastCorrupted = false;
}

void FaultInjector::reseed(quint32 seed)
{
    m_settings.seed = seed;
    m_rng.seed(seed);
}

void FaultInjector::setDropRate(double rate)
{
    m_settings.dropRate = clampRate(rate);
}
void FaultInjector::setCorruptRate(double rate)
{
    m_settings.corruptRate = clampRate(rate);
}

void FaultInjector::setExtraLatency(int fixedMs, int jitterMs)
{
    m_settings.extraLatencyMs = std::max(0, fixedMs);
    m_settings.latencyJitterMs = std::max(0, jitterMs);
}

double FaultInjector::uniform()
{
    return static_cast<double>(m_rng()) * (1.0 / 4294967296.0);
}

quint32 FaultInjector::below(quint32 n)
{
    // Multiply-shift: maps a 32-bit draw onto 0..n-1 (bias below 2^-32 · n, irrelevant here).
    return static_cast<quint32>((static_cast<quint64>(m_rng()) * n) >> 32);
}

bool FaultInjector::dropNow()
{
    const double u = uniform();
    return u < m_settings.dropRate;
}

QByteArray FaultInjector::corrupt(QByteArray bytes)
{
    const double u = uniform();
    const quint32 byteDraw = static_cast<quint32>(m_rng());
    const quint32 bitDraw = static_cast<quint32>(m_rng());
    m_lastCorrupted = false;
    if (bytes.isEmpty() || u >= m_settings.corruptRate)
        return bytes;
    const auto index = static_cast<qsizetype>((static_cast<quint64>(byteDraw) * static_cast<quint64>(bytes.size()))
                                              >> 32);
    const int bit = static_cast<int>((static_cast<quint64>(bitDraw) * 8u) >> 32);
    bytes[index] = static_cast<char>(static_cast<quint8>(bytes[index]) ^ (1u << bit));
    m_lastCorrupted = true;
    return bytes;
}

int FaultInjector::extraLatencyMs()
{
    const quint32 jitter = below(static_cast<quint32>(m_settings.latencyJitterMs) + 1u);
    return m_settings.extraLatencyMs + static_cast<int>(jitter);
}

} // namespace dd
