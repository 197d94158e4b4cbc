#include <QtTest>

#include "core/params/alarmdictionary.h"
#include "tests/support/testdata.h"

using namespace dd;

Q_DECLARE_METATYPE(dd::Family)

namespace {

using dd::test::dataDir;

const QLocale zh(QLocale::Chinese, QLocale::China);
const QLocale en(QLocale::English, QLocale::UnitedStates);

QByteArray table(const QByteArray &alarms, const QByteArray &extra = QByteArray())
{
    return "{\"format\": \"drivedesk-alarms\", \"formatVersion\": 1, \"family\": \"servo-modbus\", " + extra
        + "\"alarms\": [" + alarms + "]}";
}

} // namespace

class TestAlarmDictionary : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void bundled_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<int>("count");
        QTest::newRow("servo-can") << Family::ServoCan << 1;
        QTest::newRow("servo-modbus") << Family::ServoModbus << 1;
        QTest::newRow("shuoke") << Family::Shuoke << 0;
    }
    void bundled()
    {
        QFETCH(Family, family);
        QFETCH(int, count);
        AlarmDictionary d;
        const Error e = d.loadBundled(family);
        QVERIFY2(!e, qPrintable(e.message));
        QVERIFY(d.isLoaded());
        QCOMPARE(d.family(), family);
        QCOMPARE(d.size(), count);
        QCOMPARE(AlarmDictionary::bundled(family).size(), count);
        // Unnamed codes fall back to "Alarm N".
        QCOMPARE(d.text(12, en), QStringLiteral("Alarm 12"));
        QCOMPARE(d.text(12, zh), QStringLiteral("报警 12"));
        QCOMPARE(d.text(-3, en), QStringLiteral("Alarm -3"));
        QCOMPARE(d.remedy(12, en), QString());
    }

    void noAlarm()
    {
        const AlarmDictionary &can = AlarmDictionary::bundled(Family::ServoCan);
        QVERIFY(can.contains(0));
        QCOMPARE(can.text(0, en), QStringLiteral("No alarm"));
        QCOMPARE(can.text(0, zh), QStringLiteral("无报警"));
        QCOMPARE(can.codes(), QList<qint64>{0});
    }

    void userTable()
    {
        AlarmDictionary d;
        const Error e = d.loadFromFile(dataDir() + "/alarms/good/servo-can-named.json", Family::ServoCan);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(d.text(12, en), QStringLiteral("Overcurrent"));
        QCOMPARE(d.text(12, zh), QStringLiteral("过流"));
        QCOMPARE(d.remedy(12, zh), QStringLiteral("检查电机接线。"));
        QCOMPARE(d.remedy(12, QLocale(QLocale::German)), QStringLiteral("Check the motor wiring."));
        QCOMPARE(d.text(13, en), QStringLiteral("Alarm 13"));
        QCOMPARE(d.alarm(12)->code, 12);
        QVERIFY(!d.alarm(13));
    }

    void customFallback()
    {
        AlarmDictionary d;
        const Error e = d.loadFromJson(table("", "\"fallback\": {\"en\": \"Err-%1\", \"zh\": \"故障 Err-%1\"}, "),
                                       "t.json");
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(d.text(7, en), QStringLiteral("Err-7"));
        QCOMPARE(d.text(7, zh), QStringLiteral("故障 Err-7"));
        // Without a fallback in the file, the built-in one.
        QVERIFY(!d.loadFromJson(table("{\"code\": 1, \"text\": {\"en\": \"One\", \"zh\": \"一\"}}"), "t.json"));
        QCOMPARE(d.text(2, en), QStringLiteral("Alarm 2"));
        QCOMPARE(d.text(2, zh), QStringLiteral("报警 2"));
    }

    void badTables_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("code");
        QTest::addColumn<QString>("fragment");
        const QByteArray one = "{\"code\": 1, \"text\": {\"en\": \"One\", \"zh\": \"一\"}}";
        QTest::newRow("truncated") << table(one).left(40) << "malformed"
                                   << "not valid JSON";
        QTest::newRow("format") << QByteArray(
            "{\"format\": \"x\", \"formatVersion\": 1, \"family\": \"shuoke\", \"alarms\": []}")
                                << "malformed"
                                << "not a DriveDesk alarm table";
        QTest::newRow("version") << QByteArray(table("").replace("\"formatVersion\": 1", "\"formatVersion\": 3"))
                                 << "not-supported"
                                 << "version 3";
        QTest::newRow("family") << QByteArray(table("").replace("servo-modbus", "servo-zz")) << "not-supported"
                                << "servo-zz";
        QTest::newRow("duplicate") << table(one + "," + one) << "malformed"
                                   << "code 1 is listed twice";
        QTest::newRow("code string") << table("{\"code\": \"1\", \"text\": {\"en\": \"a\", \"zh\": \"b\"}}")
                                     << "malformed"
                                     << "\"code\"";
        QTest::newRow("code huge") << table("{\"code\": 99999999999, \"text\": {\"en\": \"a\", \"zh\": \"b\"}}")
                                   << "malformed"
                                   << "outside the allowed range";
        QTest::newRow("code beyond 2^53")
            << table("{\"code\": 18014398509481985, \"text\": {\"en\": \"a\", \"zh\": \"b\"}}") << "malformed"
            << "too large";
        QTest::newRow("no zh") << table("{\"code\": 1, \"text\": {\"en\": \"a\"}}") << "malformed"
                               << "\"zh\"";
        QTest::newRow("unknown field") << table("{\"code\": 1, \"level\": 2, \"text\": {\"en\": \"a\", \"zh\": \"b\"}}")
                                       << "malformed"
                                       << "unknown field \"level\"";
        QTest::newRow("entry not object") << table("1") << "malformed"
                                          << "alarms[0]";
        QTest::newRow("fallback placeholder")
            << table("", "\"fallback\": {\"en\": \"Alarm\", \"zh\": \"报警 %1\"}, ") << "malformed"
            << "fallback.en";
        QTest::newRow("alarms missing") << QByteArray(
            "{\"format\": \"drivedesk-alarms\", \"formatVersion\": 1, \"family\": \"shuoke\"}")
                                        << "malformed"
                                        << "\"alarms\" is missing";
    }
    void badTables()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, code);
        QFETCH(QString, fragment);
        AlarmDictionary d;
        QVERIFY(!d.loadBundled(Family::ServoCan));
        const Error e = d.loadFromJson(json, "bad.json");
        QCOMPARE(errorCodeName(e.code), code);
        QVERIFY2(e.message.contains(fragment), qPrintable(e.message));
        QCOMPARE(d.text(0, en), QStringLiteral("No alarm")); // unchanged
    }

    void wrongFamily()
    {
        AlarmDictionary d;
        const Error e = d.loadFromJson(table(""), "t.json", Family::Shuoke);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(!d.isLoaded());
    }

    void corpus()
    {
        const QDir bad(dataDir() + "/alarms/bad");
        const QStringList files = bad.entryList({"*.json"}, QDir::Files);
        QVERIFY2(files.size() >= 3, qPrintable(bad.path()));
        for (const QString &name : files) {
            AlarmDictionary d;
            QCOMPARE(errorCodeName(d.loadFromFile(bad.filePath(name)).code), name.section("--", 0, 0));
        }
    }

    void userFileOverridesBundled()
    {
        const QString path = AlarmDictionary::userFilePath(Family::ServoCan);
        QVERIFY(path.endsWith("/alarms/servo-can.json"));
        QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
        auto cleanup = qScopeGuard([&] { QFile::remove(path); });
        QVERIFY(QFile::copy(dataDir() + "/alarms/good/servo-can-named.json", path));
        AlarmDictionary d;
        QVERIFY(!d.loadForFamily(Family::ServoCan));
        QCOMPARE(d.text(12, en), QStringLiteral("Overcurrent"));
        QFile::remove(path);
        QVERIFY(!d.loadForFamily(Family::ServoCan));
        QCOMPARE(d.text(12, en), QStringLiteral("Alarm 12"));
    }
};

QTEST_GUILESS_MAIN(TestAlarmDictionary)
#include "tst_alarmdictionary.moc"
