#include "i18n/Translations.h"

#include "core/Messages.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace awb::i18n {

namespace {

const QStringList &translatedCodes()
{
    static const QStringList codes{QStringLiteral("cs"), QStringLiteral("fr"),
                                   QStringLiteral("zh_CN")};
    return codes;
}

std::string translateCoreMessage(const char *context, const char *sourceText,
                                 const char *disambiguation, int n)
{
    return QCoreApplication::translate(context, sourceText, disambiguation, n).toStdString();
}

// "zh-Hans-CN", "zh_CN", "cs-CZ", "fr" ... -> one of translatedCodes() or "".
QString matchCode(const QString &name)
{
    const QLocale locale(name);
    if (locale.language() == QLocale::Czech)
        return QStringLiteral("cs");
    if (locale.language() == QLocale::French)
        return QStringLiteral("fr");
    // Simplified Chinese: mainland China and Singapore, or the script asked for explicitly.
    if (locale.language() == QLocale::Chinese
        && (locale.script() == QLocale::SimplifiedChineseScript
            || locale.territory() == QLocale::China || locale.territory() == QLocale::Singapore))
        return QStringLiteral("zh_CN");
    if (locale.language() == QLocale::English)
        return QStringLiteral("en");
    return {};
}

} // namespace

QList<Language> availableLanguages()
{
    return {{QStringLiteral("en"), QStringLiteral("English")},
            {QStringLiteral("cs"), QStringLiteral("Čeština")},
            {QStringLiteral("fr"), QStringLiteral("Français")},
            {QStringLiteral("zh_CN"), QStringLiteral("简体中文")}};
}

QString settingsKey() { return QStringLiteral("language"); }

// The GUI's settings (organization and application "attractor-workbench"), also from the CLI,
// whose application name differs.
QString savedLanguage()
{
    return QSettings(QCoreApplication::organizationName(), QStringLiteral("attractor-workbench"))
        .value(settingsKey())
        .toString();
}

void saveLanguage(const QString &code)
{
    QSettings(QCoreApplication::organizationName(), QStringLiteral("attractor-workbench"))
        .setValue(settingsKey(), code);
}

QString resolveLanguage(const QString &setting)
{
    if (setting == QLatin1String("en") || translatedCodes().contains(setting))
        return setting;
    if (!setting.isEmpty()) {
        const QString code = matchCode(setting);
        return code.isEmpty() ? QStringLiteral("en") : code;
    }
    // The system's preferred languages in order; the first we have wins (English counts).
    for (const QString &name : QLocale::system().uiLanguages()) {
        const QString code = matchCode(name);
        if (!code.isEmpty())
            return code;
    }
    return QStringLiteral("en");
}

QString effectiveLanguage()
{
    const QString forced = qEnvironmentVariable("AWB_LANGUAGE");
    if (!forced.isEmpty())
        return resolveLanguage(forced);
    return resolveLanguage(savedLanguage());
}

QString translationResource(const QString &code)
{
    return QStringLiteral(":/i18n/attractor-workbench_%1.qm").arg(code);
}

void installCoreTranslator() { setMessageTranslator(&translateCoreMessage); }

bool installTranslations(QCoreApplication &app, const QString &language)
{
    installCoreTranslator();
    if (language.isEmpty() || language == QLatin1String("en"))
        return true;
    // Parented to the application: they live as long as it does.
    auto *qt = new QTranslator(&app);
    if (qt->load(QStringLiteral("qtbase_") + language,
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    auto *ours = new QTranslator(&app);
    const bool loaded = ours->load(translationResource(language));
    if (loaded)
        QCoreApplication::installTranslator(ours);
    return loaded;
}

} // namespace awb::i18n
