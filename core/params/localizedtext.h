#pragma once

#include <QLocale>
#include <QMap>
#include <QString>
#include <QStringList>

namespace dd {

// A text in several languages, keyed by language code ("en", "zh", or "zh_CN").
// English is the fallback of every lookup.
class LocalizedText
{
public:
    LocalizedText() = default;
    LocalizedText(const QString &english, const QString &chinese);

    void set(const QString &language, const QString &text);
    // The text for `locale`: its full name (e.g. "zh_CN"), then its language ("zh"),
    // then English.
    QString text(const QLocale &locale) const;
    QString text(const QString &language) const; // exact code, empty when absent
    QString english() const { return text(QStringLiteral("en")); }
    QString chinese() const { return text(QStringLiteral("zh")); }
    QStringList languages() const { return m_texts.keys(); }
    QStringList allTexts() const { return m_texts.values(); }
    bool isEmpty() const { return m_texts.isEmpty(); }

    friend bool operator==(const LocalizedText &a, const LocalizedText &b) { return a.m_texts == b.m_texts; }
    friend bool operator!=(const LocalizedText &a, const LocalizedText &b) { return !(a == b); }

private:
    QMap<QString, QString> m_texts;
};

} // namespace dd
