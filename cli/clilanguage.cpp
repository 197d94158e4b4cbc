#include "cli/clilanguage.h"

#include <QLibraryInfo>
#include <QLocale>

namespace dd {

CliLanguage::CliLanguage() = default;

CliLanguage::~CliLanguage()
{
    remove();
}

QString CliLanguage::id(Language language)
{
    return language == Language::Chinese ? QStringLiteral("zh_CN") : QStringLiteral("en");
}

std::optional<CliLanguage::Language> CliLanguage::fromId(const QString &id)
{
    const QString t = id.trimmed().toLower().replace(QLatin1Char('-'), QLatin1Char('_'));
    if (t == QLatin1String("en") || t.startsWith(QLatin1String("en_")))
        return Language::English;
    if (t == QLatin1String("zh") || t.startsWith(QLatin1String("zh_")))
        return Language::Chinese;
    if (t == QLatin1String("system"))
        return systemLanguage();
    return std::nullopt;
}

CliLanguage::Language CliLanguage::systemLanguage()
{
    const QLocale system = QLocale::system();
    const QStringList ui = system.uiLanguages();
    const QString first = ui.isEmpty() ? system.name() : ui.first();
    return first.startsWith(QLatin1String("zh")) ? Language::Chinese : Language::English;
}

std::optional<QString> CliLanguage::requested(const QStringList &arguments)
{
    std::optional<QString> value;
    for (int i = 0; i < arguments.size(); ++i) {
        const QString &a = arguments.at(i);
        if (a == QLatin1String("--"))
            break;
        if (a == QLatin1String("--lang")) {
            if (i + 1 < arguments.size())
                value = arguments.at(++i);
        } else if (a.startsWith(QLatin1String("--lang="))) {
            value = a.mid(7);
        }
    }
    return value; // the last one wins, as for every option
}

void CliLanguage::remove()
{
    if (m_appInstalled)
        QCoreApplication::removeTranslator(&m_app);
    if (m_qtInstalled)
        QCoreApplication::removeTranslator(&m_qt);
    m_appInstalled = m_qtInstalled = false;
}

bool CliLanguage::apply(Language language)
{
    remove();
    if (language == Language::English) {
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        return true;
    }
    QLocale::setDefault(QLocale(QLocale::Chinese, QLocale::China));
    // Qt's own words (e.g. in errors of the serial port); optional.
    if (m_qt.load(QStringLiteral("qtbase_zh_CN"), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        m_qtInstalled = QCoreApplication::installTranslator(&m_qt);
    if (m_app.load(QStringLiteral(":/i18n/drivedesk_zh_CN.qm")))
        m_appInstalled = QCoreApplication::installTranslator(&m_app);
    return m_appInstalled;
}

} // namespace dd
