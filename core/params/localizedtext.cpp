#include "core/params/localizedtext.h"

namespace dd {

LocalizedText::LocalizedText(const QString &english, const QString &chinese)
{
    set(QStringLiteral("en"), english);
    set(QStringLiteral("zh"), chinese);
}

void LocalizedText::set(const QString &language, const QString &text)
{
    m_texts.insert(language, text);
}

QString LocalizedText::text(const QString &language) const
{
    return m_texts.value(language);
}

QString LocalizedText::text(const QLocale &locale) const
{
    const QString full = locale.name(); // "zh_CN", "en_US", "C"
    auto it = m_texts.constFind(full);
    if (it != m_texts.cend() && !it->isEmpty())
        return *it;
    const QString language = full.section(QLatin1Char('_'), 0, 0);
    it = m_texts.constFind(language);
    if (it != m_texts.cend() && !it->isEmpty())
        return *it;
    return english();
}

} // namespace dd
