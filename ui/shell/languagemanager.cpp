#include "ui/shell/languagemanager.h"

#include <QCoreApplication>
#include <QEvent>
#include <QLibraryInfo>
#include <QLocale>
#include <QLoggingCategory>
#include <QSettings>

Q_LOGGING_CATEGORY(lcLanguage, "drivedesk.ui.language")

namespace dd {

namespace {
const QString SettingKey = QStringLiteral("language");
}

LanguageManager::LanguageManager(QObject *parent)
    : QObject(parent)
{
}

LanguageManager::~LanguageManager()
{
    removeTranslators();
}

QString LanguageManager::languageId(Language language)
{
    switch (language) {
    case Language::System: return QStringLiteral("system");
    case Language::English: return QStringLiteral("en");
    case Language::Chinese: return QStringLiteral("zh_CN");
    }
    return QStringLiteral("system");
}

LanguageManager::Language LanguageManager::languageFromId(const QString &id, bool *ok)
{
    const QString t = id.trimmed().toLower().replace(QLatin1Char('-'), QLatin1Char('_'));
    if (ok)
        *ok = true;
    if (t == QLatin1String("en") || t.startsWith(QLatin1String("en_")) || t == QLatin1String("english"))
        return Language::English;
    if (t == QLatin1String("zh") || t.startsWith(QLatin1String("zh_")) || t == QLatin1String("cn")
        || t == QLatin1String("chinese") || t == QStringLiteral("中文"))
        return Language::Chinese;
    if (ok)
        *ok = t == QLatin1String("system") || t.isEmpty();
    return Language::System;
}

LanguageManager::Language LanguageManager::systemLanguage()
{
    const QStringList ui = QLocale::system().uiLanguages();
    const QString first = ui.isEmpty() ? QLocale::system().name() : ui.first();
    return first.startsWith(QLatin1String("zh")) ? Language::Chinese : Language::English;
}

bool LanguageManager::removeTranslators()
{
    const bool any = m_qtInstalled || m_appInstalled;
    if (m_qtInstalled)
        QCoreApplication::removeTranslator(&m_qt);
    if (m_appInstalled)
        QCoreApplication::removeTranslator(&m_app);
    m_qtInstalled = m_appInstalled = false;
    return any;
}

bool LanguageManager::apply(Language language)
{
    m_language = language;
    m_effective = language == Language::System ? systemLanguage() : language;
    const bool removed = removeTranslators();
    m_qtLoaded = m_appLoaded = false;
    bool ok = true;
    if (m_effective == Language::Chinese) {
        QLocale::setDefault(QLocale(QLocale::Chinese, QLocale::China));
        const QString qtDir = QLibraryInfo::path(QLibraryInfo::TranslationsPath);
        m_qtLoaded = m_qt.load(QStringLiteral("qtbase_zh_CN"), qtDir);
        if (m_qtLoaded)
            m_qtInstalled = QCoreApplication::installTranslator(&m_qt);
        else
            qCWarning(lcLanguage) << "Qt's Chinese translation (qtbase_zh_CN.qm) is not in" << qtDir
                                  << "- install qt6-translations-l10n";
        m_appLoaded = m_app.load(QStringLiteral(":/i18n/drivedesk_zh_CN.qm"));
        if (m_appLoaded)
            m_appInstalled = QCoreApplication::installTranslator(&m_app);
        else
            qCWarning(lcLanguage) << "DriveDesk's Chinese translation is missing from the resources";
        ok = m_appLoaded;
    } else {
        QLocale::setDefault(language == Language::System ? QLocale::system()
                                                         : QLocale(QLocale::English, QLocale::UnitedStates));
        // Removing translators sent LanguageChange; installing none sends nothing: tell the
        // widgets ourselves (texts built from the locale, e.g. numbers, change too).
        if (!removed && QCoreApplication::instance()) {
            QEvent event(QEvent::LanguageChange);
            QCoreApplication::sendEvent(QCoreApplication::instance(), &event);
        }
    }
    emit languageChanged();
    return ok;
}

LanguageManager::Language LanguageManager::savedLanguage()
{
    QSettings s;
    return languageFromId(s.value(SettingKey, QStringLiteral("system")).toString());
}

void LanguageManager::save() const
{
    QSettings s;
    s.setValue(SettingKey, languageId(m_language));
}

} // namespace dd
