// drivedesk-cli in Chinese: --lang and the locale pick the language of the help, the
// messages and the text tables; the exit codes and the --json output never change with it.
// Runs the real executable (simulated drives on a pseudo-terminal, no CAN).
#include "tests/support/clirun.h"

#include <QtTest>

using namespace dd::test;

namespace {

using Env = QHash<QString, QString>;

// A Chinese locale through the environment only (LANGUAGE would take precedence).
const Env ChineseLocale{{QStringLiteral("LC_ALL"), QStringLiteral("zh_CN.UTF-8")},
                        {QStringLiteral("LANGUAGE"), QString()}};

QStringList args(std::initializer_list<const char *> words)
{
    QStringList l;
    for (const char *w : words)
        l << QString::fromUtf8(w);
    return l;
}

QStringList zh(QStringList a)
{
    a.prepend(QStringLiteral("zh_CN"));
    a.prepend(QStringLiteral("--lang"));
    return a;
}

} // namespace

class TestCliLanguage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void helpWithLang();
    void helpFollowsLocale_data();
    void helpFollowsLocale();
    void commandHelp();
    void textTable();
    void errorsInChinese_data();
    void errorsInChinese();
    void jsonIsTheSameInEveryLanguage_data();
    void jsonIsTheSameInEveryLanguage();
    void unknownLanguage();
};

void TestCliLanguage::initTestCase()
{
    QVERIFY2(QFileInfo::exists(cliPath()), qPrintable(cliPath()));
}

void TestCliLanguage::helpWithLang()
{
    for (const QString &form : {QStringLiteral("--lang"), QStringLiteral("--lang=zh_CN")}) {
        QStringList a{form};
        if (form == QLatin1String("--lang"))
            a << QStringLiteral("zh_CN");
        a << QStringLiteral("--help");
        const CliRun r = runCli(a);
        QCOMPARE(r.exitCode, 0);
        const QString text = QString::fromUtf8(r.out);
        for (const char *word : {"用法：drivedesk-cli", "连接与驱动器", "波特率", "点动", "急停", "伺服使能", "退出码",
                                 "模拟器", "回零", "报警"})
            QVERIFY2(text.contains(QString::fromUtf8(word)), word);
        // Option names, command names and placeholders stay as they are.
        for (const char *word : {"--family servo-can|servo-modbus|shuoke", "jog SPEED [--duration S]",
                                 "set PARAM=VALUE", "--lang LANG", "--json", "ee set|rd|ba|rs|def"})
            QVERIFY2(text.contains(QLatin1String(word)), word);
        QVERIFY(!text.contains(QLatin1String("Usage:")));
        QVERIFY(!text.contains(QLatin1String("Exit codes")));
    }
}

void TestCliLanguage::helpFollowsLocale_data()
{
    QTest::addColumn<Env>("env");
    QTest::addColumn<QStringList>("extra");
    QTest::addColumn<bool>("chinese");

    QTest::newRow("LC_ALL") << ChineseLocale << QStringList() << true;
    QTest::newRow("LANG") << Env{{QStringLiteral("LC_ALL"), QString()},
                                 {QStringLiteral("LC_MESSAGES"), QString()},
                                 {QStringLiteral("LANGUAGE"), QString()},
                                 {QStringLiteral("LANG"), QStringLiteral("zh_CN.UTF-8")}}
                          << QStringList() << true;
    QTest::newRow("LANGUAGE") << Env{{QStringLiteral("LANGUAGE"), QStringLiteral("zh_CN")}} << QStringList() << true;
    QTest::newRow("C") << Env() << QStringList() << false;
    QTest::newRow("--lang en overrides") << ChineseLocale << args({"--lang", "en"}) << false;
    QTest::newRow("--lang system") << ChineseLocale << args({"--lang", "system"}) << true;
}

void TestCliLanguage::helpFollowsLocale()
{
    QFETCH(Env, env);
    QFETCH(QStringList, extra);
    QFETCH(bool, chinese);
    const CliRun r = runCli(extra + args({"--help"}), env);
    QCOMPARE(r.exitCode, 0);
    const QString text = QString::fromUtf8(r.out);
    QCOMPARE(text.contains(QString::fromUtf8("用法：drivedesk-cli")), chinese);
    QCOMPARE(text.contains(QString::fromUtf8("点动运行后停止")), chinese);
    QCOMPARE(text.contains(QLatin1String("Usage: drivedesk-cli")), !chinese);
}

void TestCliLanguage::commandHelp()
{
    const CliRun r = runCli(zh(args({"jog", "--help"})));
    QCOMPARE(r.exitCode, 0);
    const QString text = QString::fromUtf8(r.out);
    QVERIFY2(text.contains(QString::fromUtf8("以 SPEED 点动运行")), r.out);
    QVERIFY(text.contains(QString::fromUtf8("急停")));
    QVERIFY(text.contains(QLatin1String("jog SPEED [--duration S]")));
}

void TestCliLanguage::textTable()
{
    const CliRun r = runCli(zh(args({"--sim", "info"})));
    QCOMPARE(r.exitCode, 0);
    const QString text = QString::fromUtf8(r.out);
    // Headers translated and aligned by terminal columns (a Chinese character takes two).
    QVERIFY2(text.contains(QString::fromUtf8("系列        servo-modbus\n")), r.out);
    QVERIFY2(text.contains(QString::fromUtf8("支持的功能  read-parameters")), r.out);
    QVERIFY2(text.contains(QString::fromUtf8("状态        在线，未使能，停止\n")), r.out);
    // The simulator's note on stderr.
    QVERIFY2(QString::fromUtf8(r.err).contains(QString::fromUtf8("模拟 servo-modbus 驱动器")), r.err);
}

void TestCliLanguage::errorsInChinese_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("english"); // a part of stderr in English
    QTest::addColumn<QString>("chinese"); // the same part in Chinese

    QTest::newRow("out of range") << args({"--sim", "set", "PA12=999999"}) << 2 << "is outside the allowed range"
                                  << "超出允许范围";
    QTest::newRow("unknown command") << args({"--sim", "frobnicate"}) << 2 << "Unknown command \"frobnicate\""
                                     << "未知命令“frobnicate”";
    QTest::newRow("no link") << args({"get", "PA1"}) << 2 << "No link given"
                             << "未指定连接";
    QTest::newRow("bad number") << args({"--sim", "--address", "x", "info"}) << 2 << "is not a whole number"
                                << "不是整数";
    QTest::newRow("ee on shuoke") << args({"--sim", "--family", "shuoke", "ee", "set"}) << 2
                                  << "EEPROM operations exist only"
                                  << "只有 servo-modbus 驱动器支持 EEPROM 操作";
    QTest::newRow("missing value") << args({"--sim", "info", "--timeout"}) << 2 << "Option --timeout needs a value"
                                   << "选项 --timeout 需要一个值";
}

void TestCliLanguage::errorsInChinese()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, english);
    QFETCH(QString, chinese);

    const CliRun en = runCli(args);
    QCOMPARE(en.exitCode, exitCode);
    QVERIFY2(QString::fromUtf8(en.err).contains(english), en.err);

    for (const CliRun &r : {runCli(zh(args)), runCli(args, ChineseLocale)}) {
        QCOMPARE(r.exitCode, exitCode);
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(err.contains(chinese), r.err);
        QVERIFY2(!err.contains(english), r.err);
        QVERIFY(r.out.isEmpty());
    }
}

void TestCliLanguage::jsonIsTheSameInEveryLanguage_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");

    QTest::newRow("get") << args({"--sim", "get", "PA0", "PA1", "PA12"}) << 0;
    QTest::newRow("channels") << args({"--sim", "channels"}) << 0;
    QTest::newRow("shuoke channels") << args({"--sim", "--family", "shuoke", "channels"}) << 0;
    QTest::newRow("out of range") << args({"--sim", "set", "PA12=999999"}) << 2;
    QTest::newRow("usage error") << args({"--sim", "frobnicate"}) << 2;
}

void TestCliLanguage::jsonIsTheSameInEveryLanguage()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    args.prepend(QStringLiteral("--json"));

    const CliRun en = runCli(args);
    QCOMPARE(en.exitCode, exitCode);
    QVERIFY2(!en.json().isEmpty(), en.out);
    QCOMPARE(en.json().value(QStringLiteral("ok")).toBool(), exitCode == 0);

    for (const CliRun &r : {runCli(zh(args)), runCli(args, ChineseLocale)}) {
        QCOMPARE(r.exitCode, exitCode);
        QCOMPARE(r.out, en.out); // byte for byte: keys, values, names, units and messages
    }
}

void TestCliLanguage::unknownLanguage()
{
    const CliRun r = runCli(args({"--lang", "xx", "--sim", "info"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("Unknown language \"xx\" for --lang. Languages: en, zh_CN"), r.err);
    QVERIFY(r.out.isEmpty());

    // In the locale's language, like any usage error.
    const CliRun c = runCli(args({"--lang", "xx", "--sim", "info"}), ChineseLocale);
    QCOMPARE(c.exitCode, 2);
    QVERIFY2(QString::fromUtf8(c.err).contains(QString::fromUtf8("--lang 的语言“xx”未知")), c.err);

    const CliRun j = runCli(args({"--json", "--lang=xx", "info"}));
    QCOMPARE(j.exitCode, 2);
    const QJsonObject doc = j.json();
    QCOMPARE(doc.value(QStringLiteral("ok")).toBool(true), false);
    QCOMPARE(doc.value(QStringLiteral("exitCode")).toInt(), 2);
    QCOMPARE(doc.value(QStringLiteral("error")).toObject().value(QStringLiteral("code")).toString(),
             QStringLiteral("invalid-argument"));

    const CliRun none = runCli(args({"info", "--lang"}));
    QCOMPARE(none.exitCode, 2);
    QVERIFY2(none.err.contains("Option --lang needs a value"), none.err);
}

QTEST_GUILESS_MAIN(TestCliLanguage)
#include "tst_clilanguage.moc"
