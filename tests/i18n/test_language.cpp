// The choice of language (src/i18n, issue 15): resolving a setting or the locale to a
// translation, AWB_LANGUAGE for the tests, the embedded .qm files and Qt's own translations,
// and the Edit > Language menu that saves the choice for the next start.

#include "gui/WindowTestSupport.h"

#include "core/Messages.h"
#include "i18n/Translations.h"

#include <QActionGroup>
#include <QFile>
#include <QLibraryInfo>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

class TestLanguage : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void resolve_data();
    void resolve();
    void testsRunInEnglish();
    void resourcesAndQtTranslations_data();
    void resourcesAndQtTranslations();
    void coreWithoutTranslation();
    void menu();

private:
    QTemporaryDir m_dir;
};

void TestLanguage::initTestCase()
{
    test::useTestSettings("test_language");
    i18n::saveLanguage(QString());
    QVERIFY(m_dir.isValid());
}

void TestLanguage::resolve_data()
{
    QTest::addColumn<QString>("setting");
    QTest::addColumn<QString>("expected");
    QTest::newRow("en") << "en" << "en";
    QTest::newRow("cs") << "cs" << "cs";
    QTest::newRow("fr") << "fr" << "fr";
    QTest::newRow("zh_CN") << "zh_CN" << "zh_CN";
    QTest::newRow("cs_CZ") << "cs_CZ" << "cs";
    QTest::newRow("fr-CA") << "fr-CA" << "fr";
    QTest::newRow("zh-Hans") << "zh-Hans" << "zh_CN";
    QTest::newRow("zh_TW: no translation") << "zh_TW" << "en";
    QTest::newRow("de: no translation") << "de" << "en";
}

void TestLanguage::resolve()
{
    QFETCH(QString, setting);
    QFETCH(QString, expected);
    QCOMPARE(i18n::resolveLanguage(setting), expected);
}

void TestLanguage::testsRunInEnglish()
{
    // tests/CMakeLists.txt sets AWB_LANGUAGE=en for every test: the suite's messages are the
    // English sources whatever the machine's locale.
    QCOMPARE(qEnvironmentVariable("AWB_LANGUAGE"), QStringLiteral("en"));
    QCOMPARE(i18n::effectiveLanguage(), QStringLiteral("en"));
}

void TestLanguage::resourcesAndQtTranslations_data()
{
    QTest::addColumn<QString>("code");
    for (const QString &code : {QStringLiteral("cs"), QStringLiteral("fr"),
                                QStringLiteral("zh_CN")})
        QTest::newRow(qPrintable(code)) << code;
}

void TestLanguage::resourcesAndQtTranslations()
{
    QFETCH(QString, code);
    QVERIFY2(QFile::exists(i18n::translationResource(code)),
             qPrintable(i18n::translationResource(code)));
    // Qt's own dialogs and buttons (Debian package qt6-translations-l10n, scripts/setup.sh).
    QTranslator qt;
    QVERIFY2(qt.load(QStringLiteral("qtbase_") + code,
                     QLibraryInfo::path(QLibraryInfo::TranslationsPath)),
             "qtbase translations missing: install qt6-translations-l10n");
    QVERIFY(!qt.isEmpty());
}

void TestLanguage::coreWithoutTranslation()
{
    // Without a translation the hook returns the source, and %n becomes the count.
    i18n::installCoreTranslator();
    QCOMPARE(coreTranslate("awb::ifs", "the IFS has no maps"), std::string("the IFS has no maps"));
    setMessageTranslator(nullptr);
    QCOMPARE(coreTranslate("awb::test", "%n maps", nullptr, 3), std::string("3 maps"));
    QCOMPARE(formatMessage("map %1 of %2, 100%", 2, "three"), std::string("map 2 of three, 100%"));
}

void TestLanguage::menu()
{
    RecordingMessages messages;
    MainWindow window(&messages, m_dir.path() + QStringLiteral("/recovery"));
    auto *menu = window.findChild<QMenu *>(QStringLiteral("menuLanguage"));
    QVERIFY(menu);
    QCOMPARE(menu->title(), QStringLiteral("&Language"));
    // Under Edit, next to the preferences.
    auto *edit = qobject_cast<QMenu *>(menu->parent());
    QVERIFY(edit);
    QCOMPARE(edit->title(), QStringLiteral("&Edit"));

    QStringList texts;
    QList<QAction *> choices;
    for (QAction *a : menu->actions()) {
        if (a->isSeparator())
            continue;
        texts << a->text();
        choices << a;
        QVERIFY(a->isCheckable());
        QVERIFY(a->actionGroup() && a->actionGroup()->isExclusive());
    }
    QCOMPARE(texts, (QStringList{QStringLiteral("System Default"), QStringLiteral("English"),
                                 QStringLiteral("Čeština"), QStringLiteral("Français"),
                                 QStringLiteral("简体中文")}));
    // Nothing saved: the system's language.
    QVERIFY(choices[0]->isChecked());

    choices[3]->trigger();
    QVERIFY(choices[3]->isChecked() && !choices[0]->isChecked());
    QCOMPARE(i18n::savedLanguage(), QStringLiteral("fr"));
    QCOMPARE(messages.infos.size(), 1);
    QVERIFY2(messages.infos.first().contains(
                 QStringLiteral("The language changes when Attractor Workbench is started again.")),
             qPrintable(messages.infos.first()));
    // The environment still wins for this process (and the tests).
    QCOMPARE(i18n::effectiveLanguage(), QStringLiteral("en"));

    // A new window shows the saved choice; System Default forgets it.
    {
        RecordingMessages again;
        MainWindow second(&again, m_dir.path() + QStringLiteral("/recovery2"));
        auto *m = second.findChild<QMenu *>(QStringLiteral("menuLanguage"));
        QVERIFY(m);
        auto *fr = second.findChild<QAction *>(QStringLiteral("actionLanguage_fr"));
        QVERIFY(fr && fr->isChecked());
        auto *system = second.findChild<QAction *>(QStringLiteral("actionLanguage_system"));
        QVERIFY(system);
        system->trigger();
        QCOMPARE(i18n::savedLanguage(), QString());
        QCOMPARE(again.infos.size(), 1);
    }
}

AWB_TEST_MAIN(TestLanguage)
#include "test_language.moc"
