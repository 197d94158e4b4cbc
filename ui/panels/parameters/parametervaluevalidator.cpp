#include "ui/panels/parameters/parametervaluevalidator.h"

#include "core/params/parameterdictionary.h"

namespace dd {

ParameterValueValidator::ParameterValueValidator(const ParameterDictionary *dictionary, int parameterIndex,
                                                 QObject *parent)
    : QValidator(parent)
    , m_dictionary(dictionary)
    , m_index(parameterIndex)
{
}

QValidator::State ParameterValueValidator::validate(QString &input, int &pos) const
{
    Q_UNUSED(pos);
    return reason(input).isEmpty() ? Acceptable : Intermediate;
}

QString ParameterValueValidator::reason(const QString &text) const
{
    if (!m_dictionary)
        return tr("No parameter dictionary is loaded for this drive.");
    qint64 value = 0;
    return check(*m_dictionary, m_index, text, &value).message;
}

bool ParameterValueValidator::parseValue(const QString &text, qint64 *value)
{
    QString t = text.trimmed();
    bool negative = false;
    if (t.startsWith(QLatin1Char('+')) || t.startsWith(QLatin1Char('-'))) {
        negative = t.startsWith(QLatin1Char('-'));
        t.remove(0, 1);
    }
    int base = 10;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        base = 16;
        t.remove(0, 2);
    }
    if (t.isEmpty())
        return false;
    for (const QChar c : std::as_const(t)) {
        const char16_t u = c.unicode();
        const bool decimal = u >= u'0' && u <= u'9';
        const bool hex = decimal || (u >= u'a' && u <= u'f') || (u >= u'A' && u <= u'F');
        if (!(base == 16 ? hex : decimal))
            return false;
    }
    bool ok = false;
    const qint64 magnitude = t.toLongLong(&ok, base);
    if (!ok)
        return false;
    *value = negative ? -magnitude : magnitude;
    return true;
}

Error ParameterValueValidator::check(const ParameterDictionary &dictionary, int index, const QString &text,
                                     qint64 *value)
{
    qint64 v = 0;
    if (text.trimmed().isEmpty())
        return {ErrorCode::InvalidArgument, tr("Enter a value.")};
    if (!parseValue(text, &v))
        return {ErrorCode::InvalidArgument,
                tr("“%1” is not a whole number (write it in decimal, or in hexadecimal as 0x…).").arg(text.trimmed())};
    if (Error e = dictionary.validateWrite(index, v))
        return e;
    *value = v;
    return {};
}

} // namespace dd
