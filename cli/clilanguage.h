#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <QTranslator>
#include <optional>

namespace dd {

// The language of the CLI's words (messages, tables, --help): --lang, else the locale
// (LANGUAGE, LC_ALL, LC_MESSAGES, LANG, as QLocale reads them). English, or Chinese from
// the zh_CN translation embedded under :/i18n/. --json output is never translated (see
// Cli::run and docs/cli.md, "Language").
class CliLanguage
{
    Q_DECLARE_TR_FUNCTIONS(dd::Cli)
public:
    enum class Language { English, Chinese };

    CliLanguage();
    ~CliLanguage(); // removes the translators it installed
    CliLanguage(const CliLanguage &) = delete;
    CliLanguage &operator=(const CliLanguage &) = delete;

    static QString id(Language language); // "en", "zh_CN"
    // "en", "zh_CN" and their variants ("en_US", "zh", "zh-CN", ...) or "system" (the
    // locale's); nullopt for anything else.
    static std::optional<Language> fromId(const QString &id);
    // The locale's language: Chinese when its first UI language is Chinese, else English.
    static Language systemLanguage();
    // The value of --lang in `arguments` (without the program name), read the way
    // CliParser reads it (`--lang X` or `--lang=X`, before "--"); nullopt without one.
    static std::optional<QString> requested(const QStringList &arguments);

    // Installs the translators for `language` (replacing earlier ones) and makes it
    // QLocale's default, which picks the dictionaries' parameter and alarm names.
    // false when a translation is missing (the words then stay English).
    bool apply(Language language);

private:
    void remove();

    QTranslator m_app;
    QTranslator m_qt;
    bool m_appInstalled = false;
    bool m_qtInstalled = false;
};

} // namespace dd
