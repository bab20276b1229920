#pragma once
// Translations: the language of the GUI and the CLI and the translators that carry it. Both
// executables call installTranslations() once after creating their application object: it
// picks the language (the AWB_LANGUAGE environment variable, else the "language" setting, else
// the system locale), loads Qt's own strings (qtbase_<lang>.qm from Qt's translations folder)
// and ours (:/i18n/attractor-workbench_<lang>.qm, embedded by translations/CMakeLists.txt),
// and hands the core a translator (setMessageTranslator) that calls
// QCoreApplication::translate. A changed setting takes effect at the next start.

#include <QList>
#include <QString>

class QCoreApplication;
class QTranslator;

namespace awb::i18n {

// A language the application offers: its code ("" follows the system, "en" is the source
// language) and its name in itself ("Čeština").
struct Language {
    QString code;
    QString nativeName;
};

// English, then the translations: en, cs, fr, zh_CN (not the "" of the system default).
QList<Language> availableLanguages();

// The QSettings key holding the chosen language code ("" or missing: follow the system).
QString settingsKey();

// The language code in the settings ("" when unset).
QString savedLanguage();
void saveLanguage(const QString &code);

// The translation to load for `setting` ("" = the system locale): one of the translated codes
// (cs, fr, zh_CN) or "en" when the locale has none.
QString resolveLanguage(const QString &setting);

// The language in effect for this process: AWB_LANGUAGE when set (tests use "en"), else the
// settings, resolved through resolveLanguage.
QString effectiveLanguage();

// Loads and installs the translators for `language` (resolved code; "en" installs none but the
// core hook). Returns false when a translation for a non-English language is missing. The
// translators live as long as the application.
bool installTranslations(QCoreApplication &app, const QString &language);
inline bool installTranslations(QCoreApplication &app)
{
    return installTranslations(app, effectiveLanguage());
}

// The resource path of our translation for a language code.
QString translationResource(const QString &code);

// Makes core messages (coreTranslate) go through QCoreApplication::translate.
void installCoreTranslator();

} // namespace awb::i18n
