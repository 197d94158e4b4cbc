// drivedesk-cli without a drive: help, usage errors (exit 2, nothing sent), an unopenable
// port (exit 3). Runs the real executable.
#include "tests/support/clirun.h"

#include "core/common/coreresources.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace dd::test;

class TestCliUsage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void help();
    void commandHelp();
    void version();
    void usageErrors_data();
    void usageErrors();
    void usageErrorAsJson();
    void badBackupFiles_data();
    void badBackupFiles();
    void unopenablePort_data();
    void unopenablePort();
};

void TestCliUsage::initTestCase()
{
    dd::ensureCoreResources();
    QVERIFY2(QFileInfo::exists(cliPath()), qPrintable(cliPath()));
}

void TestCliUsage::help()
{
    const CliRun r = runCli({QStringLiteral("--help")});
    QVERIFY(r.finished);
    QCOMPARE(r.exitCode, 0);
    const QString text = QString::fromUtf8(r.out);
    for (const char *word : {"scan",
                             "info",
                             "get PARAM",
                             "set PARAM=VALUE",
                             "backup -o FILE",
                             "diff FILE",
                             "restore FILE",
                             "ee set|rd|ba|rs|def",
                             "monitor CHANNEL",
                             "jog SPEED",
                             "move (--by N | --to N)",
                             "stop [--emergency]",
                             "enable on|off",
                             "clear-alarm",
                             "home [--positive]",
                             "channels",
                             "--sim",
                             "--trace",
                             "--json",
                             "Exit codes",
                             "--family servo-can|servo-modbus|shuoke"})
        QVERIFY2(text.contains(QLatin1String(word)), word);
}

void TestCliUsage::commandHelp()
{
    const CliRun r = runCli({QStringLiteral("restore"), QStringLiteral("--help")});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("--dry-run"));
    QVERIFY(!r.out.contains("Commands:"));
}

void TestCliUsage::version()
{
    const CliRun r = runCli({QStringLiteral("--version")});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.startsWith("drivedesk-cli "));
}

void TestCliUsage::usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message"); // a part of what stderr must say

    const QStringList port{QStringLiteral("--port"), QStringLiteral("/dev/null")};
    auto a = [&](std::initializer_list<const char *> words, bool withPort = true) {
        QStringList l = withPort ? port : QStringList();
        for (const char *w : words)
            l << QString::fromUtf8(w);
        return l;
    };
    QTest::newRow("no command") << a({}) << "No command";
    QTest::newRow("unknown command") << a({"frobnicate"}) << "Unknown command \"frobnicate\"";
    QTest::newRow("unknown option") << a({"--bogus", "info"}) << "Unknown option --bogus";
    QTest::newRow("command option before command") << a({"--dry-run", "info"}) << "Unknown option --dry-run";
    QTest::newRow("option of another command") << a({"info", "--emergency"}) << "Unknown option --emergency";
    QTest::newRow("missing value") << a({"info", "--baud"}) << "--baud needs a value";
    QTest::newRow("flag with value") << a({"stop", "--emergency=1"}) << "takes no value";
    QTest::newRow("bad baud") << a({"--baud", "fast", "info"}) << "not a whole number";
    QTest::newRow("zero baud") << a({"--baud", "0", "info"}) << "out of range";
    QTest::newRow("octal-looking junk") << a({"--baud", "96OO", "info"}) << "not a whole number";
    QTest::newRow("bad family") << a({"--family", "stepper", "info"}) << "Unknown family";
    QTest::newRow("address too big") << a({"--address", "300", "info"}) << "out of range";
    QTest::newRow("servo-can address") << QStringList{"--can",     "virtualcan:can0", "--family",
                                                      "servo-can", "--address",       "100",
                                                      "info"}
                                       << "out of range";
    QTest::newRow("bad framing") << a({"--framing", "morse", "info"}) << "Unknown framing";
    QTest::newRow("negative timeout") << a({"--timeout", "-5", "info"}) << "out of range";
    QTest::newRow("too many retries") << a({"--retries", "99", "info"}) << "out of range";
    QTest::newRow("no link") << a({"info"}, false) << "No link given";
    QTest::newRow("port and can") << a({"--can", "socketcan:can0", "info"}) << "not both";
    QTest::newRow("can without plugin") << a({"--can", "can0", "info"}, false) << "PLUGIN:INTERFACE";
    QTest::newRow("servo-can on a port") << a({"--family", "servo-can", "info"}) << "--can";
    QTest::newRow("servo-modbus on can") << QStringList{"--family", "servo-modbus", "--can", "virtualcan:can0", "info"}
                                         << "--port";
    QTest::newRow("shuoke can framing on a port")
        << a({"--family", "shuoke", "--framing", "can", "info"}) << "--framing can";
    QTest::newRow("info extra") << a({"info", "now"}) << "unexpected argument";
    QTest::newRow("get nothing") << a({"get"}) << "\"get\" needs";
    QTest::newRow("enable maybe") << a({"enable", "maybe"}) << "on or off";
    QTest::newRow("enable nothing") << a({"enable"}) << "\"enable\" needs";
    QTest::newRow("ee unknown") << a({"ee", "format"}) << "unknown operation";
    QTest::newRow("ee on shuoke") << a({"--family", "shuoke", "ee", "set"}) << "only on servo-modbus";
    QTest::newRow("jog nothing") << a({"jog"}) << "\"jog\" needs";
    QTest::newRow("jog not a number") << a({"jog", "fast"}) << "not a whole number";
    QTest::newRow("jog too fast") << a({"jog", "99999999999"}) << "out of range";
    QTest::newRow("jog zero duration") << a({"jog", "10", "--duration", "0"}) << "out of range";
    QTest::newRow("move neither") << a({"move"}) << "exactly one of";
    QTest::newRow("move both") << a({"move", "--by", "1", "--to", "2"}) << "exactly one of";
    QTest::newRow("move bad") << a({"move", "--by", "1.5"}) << "not a whole number";
    QTest::newRow("move zero speed") << a({"move", "--by", "10", "--speed", "0"}) << "out of range";
    QTest::newRow("monitor nothing") << a({"monitor"}) << "\"monitor\" needs";
    QTest::newRow("monitor empty channel") << a({"monitor", "speed,,torque"}) << "empty channel";
    QTest::newRow("monitor zero rate") << a({"monitor", "speed", "--rate", "0"}) << "out of range";
    QTest::newRow("monitor bad duration") << a({"monitor", "speed", "--duration", "soon"}) << "not a number";
    QTest::newRow("monitor unwritable csv")
        << a({"monitor", "speed", "-o", "/nonexistent-dir/x.csv"}) << "Cannot write";
    QTest::newRow("scan inverted range") << a({"scan", "--from", "10", "--to", "5"}) << "above --to";
    QTest::newRow("scan empty baud") << a({"scan", "--bauds", "9600,,19200"}) << "empty item";
    QTest::newRow("scan bauds on can") << QStringList{"--can", "virtualcan:can0", "scan", "--bauds", "9600"}
                                       << "--bauds is for serial";
    QTest::newRow("get unknown parameter") << a({"get", "PA99"}) << "Unknown parameter";
    QTest::newRow("set without =") << a({"set", "PA12"}) << "PARAM=VALUE";
    QTest::newRow("set not a number") << a({"set", "PA12=fast"}) << "not a whole number";
    QTest::newRow("set out of range") << a({"set", "PA12=99999999"}) << "outside the allowed range";
    QTest::newRow("set one of two out of range")
        << a({"set", "PA12=5", "PA13=-99999999"}) << "outside the allowed range";
    QTest::newRow("set read-only") << a({"set", "PA2=1"}) << "read-only";
    QTest::newRow("set twice") << a({"set", "PA12=1", "12=2"}) << "given twice";
    QTest::newRow("servo-can out of range")
        << QStringList{"--can", "virtualcan:can0", "set", "P12=40000"} << "outside the allowed range";
    QTest::newRow("backup without file") << a({"backup"}) << "backup -o FILE";
    QTest::newRow("backup into missing folder") << a({"backup", "-o", "/nonexistent-dir/b.json"}) << "does not exist";
    QTest::newRow("diff without file") << a({"diff"}) << "\"diff\" needs";
    QTest::newRow("diff missing file") << a({"diff", "/nonexistent-dir/b.json"}) << "/nonexistent-dir/b.json";
    QTest::newRow("restore missing file") << a({"restore", "/nonexistent-dir/b.json"}) << "/nonexistent-dir/b.json";
    QTest::newRow("missing dictionary") << a({"--dictionary", "/nonexistent-dir/d.json", "get", "PA1"})
                                        << "/nonexistent-dir/d.json";
    QTest::newRow("option without =") << a({"--option", "shuoke.checksum", "info"}) << "FAMILY.KEY=VALUE";
    QTest::newRow("option without family") << a({"--option", "checksum=sum", "info"}) << "FAMILY.KEY=VALUE";
    QTest::newRow("sim drives malformed") << QStringList{"--sim-drives", "1@2@3", "info"} << "--sim-drives";
}

void TestCliUsage::usageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    args.prepend(QStringLiteral("--trace"));
    const CliRun r = runCli(args);
    QVERIFY(r.finished);
    QVERIFY2(r.exitCode == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.text())));
    QVERIFY2(r.err.contains(message.toUtf8()), r.err.constData());
    QCOMPARE(r.txFrames(), 0);
    QVERIFY(r.out.isEmpty());
}

void TestCliUsage::usageErrorAsJson()
{
    const CliRun r = runCli({QStringLiteral("--json"), QStringLiteral("--port"), QStringLiteral("/dev/null"),
                             QStringLiteral("set"), QStringLiteral("PA1")});
    QCOMPARE(r.exitCode, 2);
    const QJsonObject doc = r.json();
    QCOMPARE(doc.value(QLatin1String("ok")).toBool(true), false);
    QCOMPARE(doc.value(QLatin1String("exitCode")).toInt(), 2);
    QCOMPARE(doc.value(QLatin1String("command")).toString(), QStringLiteral("set"));
    QVERIFY(!doc.value(QLatin1String("error")).toObject().value(QLatin1String("message")).toString().isEmpty());
}

void TestCliUsage::badBackupFiles_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QStringList>("args"); // after the file name
    QTest::addColumn<QString>("message");

    // A valid servo-modbus backup, then damaged in different ways.
    dd::BackupFile file;
    file.setFamily(dd::Family::ServoModbus);
    file.setAddress(1);
    file.setFirmware(QStringLiteral("7051"));
    dd::ParameterSet values;
    values.set(12, 300);
    values.set(13, 40);
    file.setValues(values);
    QByteArray good;
    QVERIFY(!file.toJson(dd::ParameterDictionary::bundled(dd::Family::ServoModbus), &good));
    QVERIFY(good.contains("\"value\": 300"));

    // One value changed, the checksum left as it was.
    QByteArray badChecksum = good;
    badChecksum.replace("\"value\": 300", "\"value\": 301");
    QVERIFY(badChecksum != good);
    QTest::newRow("not json") << QByteArray("{ this is not json") << QStringList{} << "b.json is not valid JSON";
    QTest::newRow("empty") << QByteArray() << QStringList{} << "(is the file empty or truncated?)";
    QTest::newRow("checksum") << badChecksum << QStringList{} << "the checksum does not match the values";
    QTest::newRow("truncated") << good.left(good.size() / 2) << QStringList{} << "(is the file empty or truncated?)";

    dd::BackupFile other = file;
    other.setFamily(dd::Family::ServoCan);
    QByteArray otherFamily;
    QVERIFY(!other.toJson(dd::ParameterDictionary::bundled(dd::Family::ServoCan), &otherFamily));
    QTest::newRow("other family") << otherFamily << QStringList{} << "servo-can";
    QTest::newRow("only unknown") << good << QStringList{"--only", "PA77"} << "Unknown parameter";
    QTest::newRow("only not in file") << good << QStringList{"--only", "PA14"} << "no value";
}

void TestCliUsage::badBackupFiles()
{
    QFETCH(QByteArray, content);
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("b.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(content);
    f.close();
    for (const char *command : {"diff", "restore"}) {
        if (!args.isEmpty() && qstrcmp(command, "diff") == 0)
            continue;
        const QStringList all = QStringList{"--trace", "--port", "/dev/null", QString::fromLatin1(command), path}
            + args;
        const CliRun r = runCli(all);
        QVERIFY2(r.exitCode == 2,
                 qPrintable(QStringLiteral("%1: exit %2: %3").arg(command).arg(r.exitCode).arg(r.text())));
        QVERIFY(!message.isEmpty());
        QVERIFY2(r.err.contains(message.toUtf8()), r.err.constData());
        QCOMPARE(r.txFrames(), 0);
    }
}

void TestCliUsage::unopenablePort_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("servo-modbus") << QStringList{"--family", "servo-modbus", "--port", "/dev/nonexistent-tty"};
    QTest::newRow("shuoke rtu") << QStringList{"--family", "shuoke", "--port", "/dev/nonexistent-tty"};
    QTest::newRow("servo-can") << QStringList{"--family", "servo-can", "--can", "nosuchplugin:can0"};
    QTest::newRow("shuoke can") << QStringList{"--family", "shuoke", "--can", "nosuchplugin:can0"};
}

void TestCliUsage::unopenablePort()
{
    QFETCH(QStringList, args);
    const CliRun r = runCli(args << QStringLiteral("info"));
    QVERIFY2(r.exitCode == 3, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.text())));
    QVERIFY(!r.err.trimmed().isEmpty());
}

QTEST_GUILESS_MAIN(TestCliUsage)
#include "tst_cliusage.moc"
