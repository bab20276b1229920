// The translations (translations/*.ts, issue 15): each language's .qm is embedded and loads,
// no message is left unfinished, every translation keeps its source's placeholders, and the
// main window and the core speak the language. Fails until the translators' work is merged.

#include "TestPaths.h"
#include "i18n/TsFile.h"
#include "gui/WindowTestSupport.h"

#include "core/Messages.h"
#include "i18n/Translations.h"

#include <QMenuBar>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

namespace {

QString tsPath(const QString &code)
{
    return (awb::test::sourceDir() + QStringLiteral("/translations/attractor-workbench_%1.ts")).arg(code);
}

// %1..%9 (also as %L1) and %n, sorted: a translation may reorder them, not drop or add any.
QStringList placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%L?([1-9]|n)"));
    QStringList out;
    for (auto it = re.globalMatch(text); it.hasNext();)
        out << QLatin1Char('%') + it.next().captured(1);
    out.sort();
    return out;
}

QString listed(const QStringList &lines)
{
    const int shown = 40;
    QString text = lines.mid(0, shown).join(QLatin1Char('\n'));
    if (lines.size() > shown)
        text += QStringLiteral("\n... and %1 more").arg(lines.size() - shown);
    return text;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void languages_data();
    void qmLoads_data() { languages_data(); }
    void qmLoads();
    void noUnfinishedMessages_data() { languages_data(); }
    void noUnfinishedMessages();
    void placeholdersMatch_data() { languages_data(); }
    void placeholdersMatch();
    void windowAndCoreTranslated_data() { languages_data(); }
    void windowAndCoreTranslated();
    void cleanup();

private:
    QTemporaryDir m_dir;
};

void TestTranslations::initTestCase()
{
    test::useTestSettings("test_translations");
    QVERIFY(m_dir.isValid());
}

void TestTranslations::languages_data()
{
    QTest::addColumn<QString>("code");
    for (const QString &code : {QStringLiteral("cs"), QStringLiteral("fr"),
                                QStringLiteral("zh_CN")})
        QTest::newRow(qPrintable(code)) << code;
}

void TestTranslations::cleanup() { setMessageTranslator(nullptr); }

void TestTranslations::qmLoads()
{
    QFETCH(QString, code);
    QTranslator translator;
    QVERIFY2(translator.load(i18n::translationResource(code)),
             qPrintable(i18n::translationResource(code)));
    QCOMPARE(translator.language(), QLocale(code).name());
}

void TestTranslations::noUnfinishedMessages()
{
    QFETCH(QString, code);
    QString error;
    const auto messages = test::readTs(tsPath(code), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(messages.size() > 1000);
    QStringList unfinished;
    for (const test::TsMessage &m : messages)
        if (m.unfinished)
            unfinished << m.context + QStringLiteral(": ") + m.source.left(100);
    QVERIFY2(unfinished.isEmpty(),
             qPrintable(QStringLiteral("%1 of %2 messages unfinished in %3:\n%4")
                            .arg(unfinished.size())
                            .arg(messages.size())
                            .arg(tsPath(code), listed(unfinished))));
}

void TestTranslations::placeholdersMatch()
{
    QFETCH(QString, code);
    const auto messages = test::readTs(tsPath(code));
    QVERIFY(!messages.isEmpty());
    QStringList wrong;
    for (const test::TsMessage &m : messages) {
        if (m.unfinished)
            continue;
        QStringList expected = placeholders(m.source);
        for (const QString &t : m.translations) {
            QStringList got = placeholders(t);
            // A plural form may spell the count out ("one file") instead of using %n.
            if (m.numerus) {
                got.removeAll(QStringLiteral("%n"));
                expected.removeAll(QStringLiteral("%n"));
            }
            if (got != expected)
                wrong << QStringLiteral("%1: \"%2\" has %3, its translation \"%4\" has %5")
                             .arg(m.context, m.source.left(80), expected.join(QLatin1Char(' ')),
                                  t.left(80), got.join(QLatin1Char(' ')));
        }
    }
    QVERIFY2(wrong.isEmpty(), qPrintable(listed(wrong)));
}

void TestTranslations::windowAndCoreTranslated()
{
    QFETCH(QString, code);
    const auto messages = test::readTs(tsPath(code));
    QTranslator translator;
    QVERIFY(translator.load(i18n::translationResource(code)));
    QVERIFY(QCoreApplication::installTranslator(&translator));
    i18n::installCoreTranslator();

    // The File menu: the first of the menu bar.
    const QString english = QStringLiteral("&File");
    const QString expected = test::tsTranslation(messages, QStringLiteral("awb::MainWindow"),
                                                 english);
    QString title;
    {
        RecordingMessages recorded;
        MainWindow window(&recorded, m_dir.path() + QStringLiteral("/recovery"));
        const auto menus = window.menuBar()->actions();
        QVERIFY(!menus.isEmpty());
        title = menus.first()->text();
    }
    // A core message, through coreTranslate and QCoreApplication::translate.
    const char *coreSource = "the IFS has no maps";
    const QString coreExpected = test::tsTranslation(messages, QStringLiteral("awb::ifs"),
                                                     QString::fromUtf8(coreSource));
    const QString core = QString::fromStdString(coreTranslate("awb::ifs", coreSource));
    QCoreApplication::removeTranslator(&translator);

    QVERIFY2(!expected.isEmpty(), "\"&File\" has no translation in the .ts file");
    QCOMPARE(title, expected);
    QVERIFY(title != english);
    QVERIFY2(!coreExpected.isEmpty(), "the core message has no translation in the .ts file");
    QCOMPARE(core, coreExpected);
    QVERIFY(core != QString::fromUtf8(coreSource));
}

AWB_TEST_MAIN(TestTranslations)
#include "test_translations.moc"
