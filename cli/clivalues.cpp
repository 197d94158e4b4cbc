#include "cli/clivalues.h"

#include <QStringList>
#include <cmath>

namespace dd {

std::optional<qint64> CliValues::integer(const QString &text, qint64 min, qint64 max, const QString &what,
                                         QString *error)
{
    QString t = text.trimmed();
    bool negative = false;
    if (t.startsWith(QLatin1Char('+')) || t.startsWith(QLatin1Char('-'))) {
        negative = t.startsWith(QLatin1Char('-'));
        t = t.mid(1);
    }
    bool ok = false;
    qint64 v = 0;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) && t.size() > 2)
        v = t.mid(2).toLongLong(&ok, 16);
    else if (!t.isEmpty() && t.at(0).isDigit())
        v = t.toLongLong(&ok, 10);
    if (!ok) {
        *error = tr("%1: \"%2\" is not a whole number.").arg(what, text);
        return std::nullopt;
    }
    if (negative)
        v = -v;
    if (v < min || v > max) {
        *error = tr("%1: %2 is out of range (allowed %3 to %4).").arg(what).arg(v).arg(min).arg(max);
        return std::nullopt;
    }
    return v;
}

std::optional<double> CliValues::real(const QString &text, double min, double max, const QString &what, QString *error)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        *error = tr("%1: \"%2\" is not a number.").arg(what, text);
        return std::nullopt;
    }
    if (v < min || v > max) {
        *error = tr("%1: %2 is out of range (allowed %3 to %4).").arg(what).arg(v).arg(min).arg(max);
        return std::nullopt;
    }
    return v;
}

std::optional<QList<qint64>> CliValues::integerList(const QString &text, qint64 min, qint64 max, const QString &what,
                                                    QString *error)
{
    QList<qint64> out;
    const QStringList items = text.split(QLatin1Char(','));
    for (const QString &item : items) {
        if (item.trimmed().isEmpty()) {
            *error = tr("%1: \"%2\" has an empty item; write a comma-separated list such as 9600,19200.")
                         .arg(what, text);
            return std::nullopt;
        }
        const auto v = integer(item, min, max, what, error);
        if (!v)
            return std::nullopt;
        out << *v;
    }
    return out;
}

std::optional<bool> CliValues::onOff(const QString &text, const QString &what, QString *error)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("on") || t == QLatin1String("1") || t == QLatin1String("true") || t == QLatin1String("yes"))
        return true;
    if (t == QLatin1String("off") || t == QLatin1String("0") || t == QLatin1String("false") || t == QLatin1String("no"))
        return false;
    *error = tr("%1: expected on or off, not \"%2\".").arg(what, text);
    return std::nullopt;
}

std::optional<CliValues::PreTrigger> CliValues::preTrigger(const QString &text, double maxSeconds, QString *error)
{
    const QString t = text.trimmed();
    PreTrigger p;
    QString number;
    if (t.endsWith(QLatin1Char('%'))) {
        p.percent = true;
        number = t.chopped(1).trimmed();
    } else if (t.endsWith(QLatin1Char('s'))) {
        number = t.chopped(1).trimmed();
    } else {
        *error = tr("--pre needs its unit: a percentage of the record (e.g. --pre 25%) or seconds before the "
                    "trigger (e.g. --pre 0.1s), not \"%1\".")
                     .arg(text);
        return std::nullopt;
    }
    bool ok = false;
    const double v = number.toDouble(&ok);
    const double max = p.percent ? 99.9 : maxSeconds;
    if (!ok || !std::isfinite(v) || v < 0.0 || v > max) {
        *error = p.percent ? tr("--pre: \"%1\" must be a percentage from 0%% to %2%%.").arg(text).arg(max)
                           : tr("--pre: \"%1\" must be seconds from 0s to %2s.").arg(text).arg(max);
        error->replace(QStringLiteral("%%"), QStringLiteral("%"));
        return std::nullopt;
    }
    p.value = v;
    return p;
}

QJsonValue CliValues::json(const std::optional<qint64> &v)
{
    return v ? QJsonValue(double(*v)) : QJsonValue();
}

QString CliValues::text(const std::optional<qint64> &v)
{
    return v ? QString::number(*v) : QStringLiteral("-");
}

} // namespace dd
