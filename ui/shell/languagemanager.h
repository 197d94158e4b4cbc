#pragma once

#include <QObject>
#include <QTranslator>

namespace dd {

// The user-interface language: follows the system locale unless the user picks one in the
// Language menu (or --lang). apply() swaps the installed translators — Qt's own
// (qtbase_zh_CN from QLibraryInfo::TranslationsPath: standard dialogs and buttons) and
// DriveDesk's (:/i18n/drivedesk_zh_CN.qm, built from translations/*.ts) — which sends
// QEvent::LanguageChange to every widget; each widget sets its texts again in its
// changeEvent() (retranslate()), so the switch is live, without a restart.
class LanguageManager : public QObject
{
    Q_OBJECT
public:
    enum class Language { System, English, Chinese };

    explicit LanguageManager(QObject *parent = nullptr);
    ~LanguageManager() override;

    static QString languageId(Language language);                          // "system", "en", "zh_CN"
    static Language languageFromId(const QString &id, bool *ok = nullptr); // "zh", "zh_CN", "cn", "en", "system"
    // What "System" means here: Chinese when the first UI language of the locale is
    // Chinese, English otherwise.
    static Language systemLanguage();

    // Installs the translators for `language`; false when a translation could not be
    // loaded (English needs none and always succeeds).
    bool apply(Language language);
    Language language() const { return m_language; } // as chosen (may be System)
    Language effectiveLanguage() const { return m_effective; }
    bool qtTranslationLoaded() const { return m_qtLoaded; }
    bool appTranslationLoaded() const { return m_appLoaded; }

    // The "language" setting.
    static Language savedLanguage();
    void save() const;

signals:
    void languageChanged();

private:
    bool removeTranslators();

    QTranslator m_qt;
    QTranslator m_app;
    bool m_qtInstalled = false;
    bool m_appInstalled = false;
    bool m_qtLoaded = false;
    bool m_appLoaded = false;
    Language m_language = Language::System;
    Language m_effective = Language::English;
};

} // namespace dd
