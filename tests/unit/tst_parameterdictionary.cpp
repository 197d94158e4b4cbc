#include <QtTest>

#include "core/params/parameterdictionary.h"
#include "tests/support/jsonmutation.h"
#include "tests/support/testdata.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTranslator>
#include <functional>

using namespace dd;

Q_DECLARE_METATYPE(dd::Family)
Q_DECLARE_METATYPE(dd::ErrorCode)

namespace {

using dd::test::dataDir;

QJsonObject entry(int index, const QString &key, qint64 min = -100, qint64 max = 100)
{
    return QJsonObject{
        {"index", index},
        {"key", key},
        {"name",
         QJsonObject{{"en", QStringLiteral("Parameter %1").arg(index)}, {"zh", QStringLiteral("参数 %1").arg(index)}}},
        {"description", QJsonObject{{"en", "Test."}, {"zh", "测试。"}}},
        {"unit", ""},
        {"min", min},
        {"max", max},
        {"access", "rw"}};
}

QJsonObject smallDictionary()
{
    return QJsonObject{{"format", "drivedesk-dictionary"},
                       {"formatVersion", 1},
                       {"family", "servo-can"},
                       {"valueType", "int16"},
                       {"parameters", QJsonArray{entry(0, "P0"), entry(1, "P1"), entry(2, "P2")}}};
}

QByteArray toBytes(const QJsonObject &o)
{
    return QJsonDocument(o).toJson();
}

using Mutation = test::JsonMutation;

// Applies f to parameters[i].
const auto onEntry = test::onParameterEntry;

// Replaces the text of a JSON number: QJsonObject cannot hold numbers beyond a double.
QByteArray withRawNumber(const QJsonObject &root, const QByteArray &placeholder, const QByteArray &number)
{
    QByteArray bytes = toBytes(root);
    bytes.replace("\"" + placeholder + "\"", number);
    return bytes;
}

class MarkingTranslator : public QTranslator
{
public:
    QString translate(const char *context, const char *sourceText, const char *, int) const override
    {
        if (QByteArray(context) == "dd::ParameterDictionary"
            && QByteArray(sourceText).contains("outside the allowed range"))
            return QStringLiteral("[zh] %1: %2 超出允许范围 %3 ~ %4");
        return {};
    }
    bool isEmpty() const override { return false; }
};

} // namespace

class TestParameterDictionary : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void bundledCounts_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<int>("count");
        QTest::newRow("servo-can") << Family::ServoCan << 220;
        QTest::newRow("servo-modbus") << Family::ServoModbus << 60;
        QTest::newRow("shuoke") << Family::Shuoke << 18;
    }
    void bundledCounts()
    {
        QFETCH(Family, family);
        QFETCH(int, count);
        ParameterDictionary d;
        const Error e = d.loadBundled(family);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(d.size(), count);
        QCOMPARE(d.family(), family);
        QCOMPARE(ParameterDictionary::bundled(family).size(), count);
        for (const ParameterInfo &p : d.parameters()) {
            const QByteArray what = p.key.toUtf8();
            QVERIFY2(!p.name.english().isEmpty() && !p.name.chinese().isEmpty(), what);
            QVERIFY2(!p.description.english().isEmpty() && !p.description.chinese().isEmpty(), what);
            // The Chinese texts are Chinese (hold CJK ideographs).
            QVERIFY2(p.name.chinese().contains(QRegularExpression(QStringLiteral("[\\x{4e00}-\\x{9fff}]"))), what);
            QVERIFY2(p.min <= p.max, what);
            QVERIFY2(!p.defaultValue || p.inRange(*p.defaultValue), what);
        }
    }

    void servoCanContents()
    {
        const ParameterDictionary &d = ParameterDictionary::bundled(Family::ServoCan);
        QCOMPARE(d.indices().first(), 0);
        QCOMPARE(d.indices().last(), 219);
        QCOMPARE(d.byIndex(4)->name.english(), QStringLiteral("Control mode"));
        QCOMPARE(d.byIndex(4)->name.chinese(), QStringLiteral("控制方式"));
        QVERIFY(d.byIndex(4)->description.english().contains("8 = internal run control"));
        QCOMPARE(d.byIndex(74)->name.chinese(), QStringLiteral("通讯方式"));
        QVERIFY(d.byIndex(74)->communication);
        QCOMPARE(d.byIndex(75)->min, 0);
        QCOMPARE(d.byIndex(75)->max, 99);
        QVERIFY(d.byIndex(75)->communication);
        const ParameterInfo *generic = d.byIndex(100);
        QCOMPARE(generic->key, QStringLiteral("P100"));
        QCOMPARE(generic->min, -32768);
        QCOMPARE(generic->max, 32767);
        QCOMPARE(generic->type, ValueType::Int16);
        QCOMPARE(generic->access, Access::ReadWrite);
        QVERIFY(!generic->communication);
    }

    void servoModbusContents()
    {
        const ParameterDictionary &d = ParameterDictionary::bundled(Family::ServoModbus);
        for (int n = 0; n < 60; ++n) {
            QCOMPARE(d.byIndex(n)->key, QStringLiteral("PA%1").arg(n));
            QCOMPARE(d.byIndex(n)->registerAddress, 0x64 + n);
        }
        QCOMPARE(d.byIndex(2)->access, Access::ReadOnly);
        QCOMPARE(d.byIndex(2)->name.chinese(), QStringLiteral("软件版本"));
        QCOMPARE(d.byIndex(51)->min, 0);
        QCOMPARE(d.byIndex(51)->max, 255);
        QVERIFY(d.byIndex(51)->description.english().contains("broadcast"));
        QCOMPARE(d.byIndex(59)->registerAddress, 0x9F);
    }

    void shuokeContents()
    {
        const ParameterDictionary &d = ParameterDictionary::bundled(Family::Shuoke);
        const QList<int> expected = {0x24, 0x25, 0x27, 0x29, 0x2B, 0x2D, 0x2F, 0x48, 0x49,
                                     0x4A, 0x4B, 0x5C, 0x5D, 0x5E, 0x5F, 0x61, 0x65, 0x66};
        QCOMPARE(d.indices(), expected);
        struct Readable
        {
            int set;
            int get;
            const char *key;
            qint64 min;
            qint64 max;
            const char *zh;
        };
        const Readable readable[] = {
            {0x24, 0x23, "baud-code", 1, 8, "串口波特率代号"},
            {0x25, 0x26, "start-speed", 0, 100000, "起始速度"},
            {0x27, 0x28, "max-speed", 0, 100000, "最大速度"},
            {0x29, 0x2A, "stop-speed", 0, 100000, "停止速度"},
            {0x2B, 0x2C, "acceleration", 0, 100000, "加速度"},
            {0x2D, 0x2E, "deceleration", 0, 100000, "减速度"},
            {0x2F, 0x30, "homing-speed", 0, 100000, "归零速度"},
            {0x5F, 0x60, "gear-numerator", 1, 65535, "电子齿轮分子"},
            {0x61, 0x62, "gear-denominator", 1, 65535, "电子齿轮分母"},
        };
        for (const Readable &r : readable) {
            const ParameterInfo *p = d.byIndex(r.set);
            QVERIFY2(p, r.key);
            QCOMPARE(p->key, QLatin1String(r.key));
            QCOMPARE(p->readCommand, r.get);
            QCOMPARE(p->access, Access::ReadWrite);
            QCOMPARE(p->min, r.min);
            QCOMPARE(p->max, r.max);
            QCOMPARE(p->name.chinese(), QString::fromUtf8(r.zh));
        }
        QVERIFY(!d.byIndex(0x2F)->models.contains("M4505"));
        QVERIFY(d.byIndex(0x2F)->models.contains("M6505"));
        for (int wo : {0x5C, 0x5D, 0x5E, 0x65, 0x66, 0x4A, 0x4B, 0x48, 0x49}) {
            const ParameterInfo *p = d.byIndex(wo);
            QVERIFY(p);
            QCOMPARE(p->access, Access::WriteOnly);
            QCOMPARE(p->readCommand, -1);
            QVERIFY(!p->isReadable());
        }
        for (int binary : {0x5C, 0x5D, 0x5E, 0x4A, 0x48, 0x49}) {
            QCOMPARE(d.byIndex(binary)->min, 0);
            QCOMPARE(d.byIndex(binary)->max, 1);
        }
        QCOMPARE(d.byIndex(0x65)->defaultValue, std::optional<qint64>(200));
        QCOMPARE(d.byIndex(0x66)->defaultValue, std::optional<qint64>(5000));
        QCOMPARE(d.byIndex(0x4B)->min, 1);
        QCOMPARE(d.byIndex(0x4B)->max, 18);
        QCOMPARE(d.byIndex(0x4B)->defaultValue, std::optional<qint64>(12));
        QCOMPARE(d.byIndex(0x25)->unit, QStringLiteral("pulse/s"));
    }

    void lookup_data()
    {
        QTest::addColumn<Family>("family");
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("index");
        const Family m = Family::ServoModbus, c = Family::ServoCan, s = Family::Shuoke;
        QTest::newRow("number") << m << "12" << 12;
        QTest::newRow("PA key") << m << "PA12" << 12;
        QTest::newRow("pa lower") << m << "pa12" << 12;
        QTest::newRow("P prefix") << m << "P12" << 12;
        QTest::newRow("spaces") << m << "  PA12 " << 12;
        QTest::newRow("PA space") << m << "PA 12" << 12;
        QTest::newRow("english name") << m << "Drive address" << 51;
        QTest::newRow("name any case") << m << "dRIVE ADDRESS" << 51;
        QTest::newRow("chinese name") << m << "驱动器地址" << 51;
        QTest::newRow("hex") << m << "0x33" << 51;
        QTest::newRow("beyond") << m << "PA60" << -1;
        QTest::newRow("beyond number") << m << "60" << -1;
        QTest::newRow("unknown") << m << "speed" << -1;
        QTest::newRow("empty") << m << "" << -1;
        QTest::newRow("negative") << m << "-1" << -1;
        QTest::newRow("can P4") << c << "P4" << 4;
        QTest::newRow("can 219") << c << "p219" << 219;
        QTest::newRow("can 220") << c << "220" << -1;
        QTest::newRow("can name") << c << "control mode" << 4;
        QTest::newRow("can zh") << c << "站号" << 75;
        QTest::newRow("can generic name") << c << "Parameter 17" << 17;
        QTest::newRow("shuoke key") << s << "start-speed" << 0x25;
        QTest::newRow("shuoke key case") << s << "START-SPEED" << 0x25;
        QTest::newRow("shuoke zh") << s << "起始速度" << 0x25;
        QTest::newRow("shuoke set code") << s << "0x25" << 0x25;
        QTest::newRow("shuoke decimal") << s << "37" << 0x25;
        QTest::newRow("shuoke gear") << s << "电子齿轮分子" << 0x5F;
        QTest::newRow("shuoke get code is not an index") << s << "0x26" << -1;
    }
    void lookup()
    {
        QFETCH(Family, family);
        QFETCH(QString, text);
        QFETCH(int, index);
        const ParameterDictionary &d = ParameterDictionary::bundled(family);
        const ParameterInfo *p = d.find(text);
        QCOMPARE(p ? p->index : -1, index);
        int resolved = -7;
        const Error e = d.resolve(text, &resolved);
        QCOMPARE(e.isError(), index < 0);
        if (index >= 0)
            QCOMPARE(resolved, index);
        else
            QVERIFY(e.message.contains(text.trimmed()));
    }

    void lookupByKeyAndName()
    {
        const ParameterDictionary &d = ParameterDictionary::bundled(Family::ServoModbus);
        QCOMPARE(d.byKey("pa51")->index, 51);
        QVERIFY(!d.byKey("51"));
        QCOMPARE(d.byName("DRIVE address")->index, 51);
        QVERIFY(!d.byName("PA51"));
        QVERIFY(!d.byIndex(-1));
    }

    void ambiguousNameFindsNothing()
    {
        QJsonObject root = smallDictionary();
        onEntry(2, [](QJsonObject &e) { e["name"] = QJsonObject{{"en", "Parameter 1"}, {"zh", "重复"}}; })(root);
        ParameterDictionary d;
        QVERIFY(!d.loadFromJson(toBytes(root), "dup-names.json"));
        QVERIFY(!d.byName("Parameter 1"));
        QCOMPARE(d.byName("重复")->index, 2);
    }

    void resolveList()
    {
        const ParameterDictionary &d = ParameterDictionary::bundled(Family::ServoCan);
        QList<int> out;
        QVERIFY(!d.resolveList({"P4,P75", " p4 ", "74"}, &out));
        QCOMPARE(out, (QList<int>{4, 75, 74}));
        const Error e = d.resolveList({"P4,nonsense"}, &out);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(e.message.contains("nonsense"));
        QCOMPARE(out, (QList<int>{4, 75, 74})); // unchanged on failure
    }

    void validateValue()
    {
        const ParameterDictionary &can = ParameterDictionary::bundled(Family::ServoCan);
        QVERIFY(!can.validateValue(75, 0));
        QVERIFY(!can.validateValue(75, 99));
        Error e = can.validateValue(75, 100);
        QCOMPARE(e.code, ErrorCode::OutOfRange);
        QVERIFY2(e.message.contains("P75") && e.message.contains("100") && e.message.contains("0 to 99"),
                 qPrintable(e.message));
        e = can.validateValue(75, -1);
        QCOMPARE(e.code, ErrorCode::OutOfRange);
        QVERIFY(!can.validateValue(10, -32768));
        QCOMPARE(can.validateValue(10, 32768).code, ErrorCode::OutOfRange);
        e = can.validateValue(220, 0);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(e.message.contains("220"));

        const ParameterDictionary &shuoke = ParameterDictionary::bundled(Family::Shuoke);
        e = shuoke.validateValue(0x25, 100001);
        QCOMPARE(e.code, ErrorCode::OutOfRange);
        QVERIFY2(e.message.contains("0 to 100000 pulse/s"), qPrintable(e.message));
        QCOMPARE(shuoke.validateValue(0x5F, 0).code, ErrorCode::OutOfRange);

        const ParameterDictionary &modbus = ParameterDictionary::bundled(Family::ServoModbus);
        QVERIFY(!modbus.validateValue(2, 7051));
        e = modbus.validateWrite(2, 7051);
        QCOMPARE(e.code, ErrorCode::NotSupported);
        QVERIFY(e.message.contains("read-only"));
        QVERIFY(!modbus.validateWrite(51, 3));
        QCOMPARE(modbus.validateWrite(51, 256).code, ErrorCode::OutOfRange);
        QVERIFY(!shuoke.validateWrite(0x5C, 1)); // write-only is writable
    }

    void validationMessageIsTranslated()
    {
        MarkingTranslator translator;
        QVERIFY(QCoreApplication::installTranslator(&translator));
        const Error e = ParameterDictionary::bundled(Family::ServoCan).validateValue(75, 120);
        QCoreApplication::removeTranslator(&translator);
        QCOMPARE(e.code, ErrorCode::OutOfRange);
        QVERIFY2(e.message.startsWith("[zh] P75 ") && e.message.endsWith("120 超出允许范围 0 ~ 99"),
                 qPrintable(e.message));
    }

    void displayNameFollowsLocale()
    {
        const ParameterDictionary &d = ParameterDictionary::bundled(Family::Shuoke);
        QCOMPARE(d.displayName(0x27, QLocale(QLocale::Chinese, QLocale::China)), QStringLiteral("最大速度"));
        QCOMPARE(d.displayName(0x27, QLocale(QLocale::Chinese, QLocale::Taiwan)), QStringLiteral("最大速度"));
        QCOMPARE(d.displayName(0x27, QLocale(QLocale::English, QLocale::UnitedStates)),
                 QStringLiteral("Maximum speed"));
        QCOMPARE(d.displayName(0x27, QLocale(QLocale::German, QLocale::Germany)), QStringLiteral("Maximum speed"));
        QCOMPARE(d.displayName(0x27, QLocale::c()), QStringLiteral("Maximum speed"));
        QCOMPARE(d.displayName(1), QStringLiteral("P1")); // not in the dictionary
        QCOMPARE(d.label(0x25, QLocale(QLocale::Chinese)), QStringLiteral("start-speed 起始速度"));
        QCOMPARE(d.byIndex(0x25)->displayName(QLocale(QLocale::English)), QStringLiteral("Start speed"));
    }

    void otherLanguagesAndComments()
    {
        QJsonObject root = smallDictionary();
        root["_comment"] = "comments are fields starting with an underscore";
        onEntry(0, [](QJsonObject &e) {
            e["name"] = QJsonObject{{"en", "Gain"}, {"zh", "增益"}, {"de", "Verstärkung"}, {"zh_TW", "增益(繁)"}};
            e["_note"] = "ignored";
        })(root);
        ParameterDictionary d;
        const Error e = d.loadFromJson(toBytes(root), "langs.json");
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(d.displayName(0, QLocale(QLocale::German)), QStringLiteral("Verstärkung"));
        QCOMPARE(d.displayName(0, QLocale(QLocale::Chinese, QLocale::Taiwan)), QStringLiteral("增益(繁)"));
        QCOMPARE(d.displayName(0, QLocale(QLocale::Chinese, QLocale::China)), QStringLiteral("增益"));
        QCOMPARE(d.find("verstärkung")->index, 0);
    }

    void badDictionary_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<ErrorCode>("code");
        QTest::addColumn<QStringList>("fragments");
        const QJsonObject base = smallDictionary();
        auto mutated = [&](const Mutation &m) {
            QJsonObject o = base;
            m(o);
            return toBytes(o);
        };
        const QByteArray good = toBytes(base);
        const ErrorCode M = ErrorCode::Malformed;
        QTest::newRow("truncated") << good.left(good.size() / 2) << M << QStringList{"not valid JSON", "truncated"};
        QTest::newRow("empty") << QByteArray() << M << QStringList{"not valid JSON"};
        QTest::newRow("array") << QByteArray("[]") << M << QStringList{"top level"};
        QTest::newRow("format") << mutated([](QJsonObject &o) { o["format"] = "drivedesk-backup"; }) << M
                                << QStringList{"not a DriveDesk parameter dictionary"};
        QTest::newRow("version") << mutated([](QJsonObject &o) { o["formatVersion"] = 2; }) << ErrorCode::NotSupported
                                 << QStringList{"version 2"};
        QTest::newRow("family") << mutated([](QJsonObject &o) { o["family"] = "servo-x"; }) << ErrorCode::NotSupported
                                << QStringList{"servo-x", "servo-can, servo-modbus, shuoke"};
        QTest::newRow("no params") << mutated([](QJsonObject &o) { o["parameters"] = QJsonArray(); }) << M
                                   << QStringList{"no parameters"};
        QTest::newRow("params not array") << mutated([](QJsonObject &o) { o["parameters"] = 3; }) << M
                                          << QStringList{"\"parameters\"", "array", "number"};
        QTest::newRow("unknown root field")
            << mutated([](QJsonObject &o) { o["extra"] = 1; }) << M << QStringList{"unknown field \"extra\""};
        QTest::newRow("value type") << mutated([](QJsonObject &o) { o["valueType"] = "float"; }) << M
                                    << QStringList{"valueType", "float"};
        QTest::newRow("entry not object") << mutated([](QJsonObject &o) {
            QJsonArray a = o["parameters"].toArray();
            a[1] = 5;
            o["parameters"] = a;
        }) << M << QStringList{"parameters[1]", "object"};
        QTest::newRow("missing max") << mutated(onEntry(1, [](QJsonObject &e) { e.remove("max"); })) << M
                                     << QStringList{"parameters[1] (P1)", "\"max\"", "missing"};
        QTest::newRow("missing key") << mutated(onEntry(1, [](QJsonObject &e) { e.remove("key"); })) << M
                                     << QStringList{"parameters[1]", "\"key\"", "missing"};
        QTest::newRow("min string") << mutated(onEntry(0, [](QJsonObject &e) { e["min"] = "0"; })) << M
                                    << QStringList{"(P0)", "\"min\"", "integer", "string"};
        QTest::newRow("fraction") << mutated(onEntry(0, [](QJsonObject &e) { e["max"] = 1.5; })) << M
                                  << QStringList{"\"max\"", "whole number"};
        QTest::newRow("huge double") << mutated(onEntry(0, [](QJsonObject &e) { e["max"] = 1e30; })) << M
                                     << QStringList{"\"max\"", "too large"};
        {
            QJsonObject o = base;
            onEntry(0, [](QJsonObject &e) { e["max"] = "HUGE"; })(o);
            QTest::newRow("beyond 2^53") << withRawNumber(o, "HUGE", "9007199254740993") << M
                                         << QStringList{"\"max\"", "too large"};
            QTest::newRow("beyond int64") << withRawNumber(o, "HUGE", "123456789012345678901234567890") << M
                                          << QStringList{"\"max\"", "too large"};
            QTest::newRow("overflowing exponent")
                << withRawNumber(o, "HUGE", "1e400") << M << QStringList{"not valid JSON"};
        }
        QTest::newRow("name not object") << mutated(onEntry(0, [](QJsonObject &e) { e["name"] = "Gain"; })) << M
                                         << QStringList{"\"name\"", "object"};
        QTest::newRow("name without zh") << mutated(onEntry(0, [](QJsonObject &e) {
            e["name"] = QJsonObject{{"en", "Gain"}};
        })) << M << QStringList{"\"name\"", "\"zh\""};
        QTest::newRow("description empty en") << mutated(onEntry(0, [](QJsonObject &e) {
            e["description"] = QJsonObject{{"en", " "}, {"zh", "说明"}};
        })) << M << QStringList{"\"description\"", "\"en\""};
        QTest::newRow("bad language code") << mutated(onEntry(0, [](QJsonObject &e) {
            e["name"] = QJsonObject{{"en", "a"}, {"zh", "b"}, {"English", "c"}};
        })) << M << QStringList{"English", "language code"};
        QTest::newRow("min > max") << mutated(onEntry(2, [](QJsonObject &e) {
            e["min"] = 10;
            e["max"] = 5;
        })) << M << QStringList{"(P2)", "min 10 is greater than max 5"};
        QTest::newRow("default outside") << mutated(onEntry(1, [](QJsonObject &e) { e["default"] = 101; })) << M
                                         << QStringList{"(P1)", "default 101", "-100 to 100"};
        QTest::newRow("beyond type") << mutated(onEntry(1, [](QJsonObject &e) { e["max"] = 40000; })) << M
                                     << QStringList{"(P1)", "does not fit the type int16"};
        QTest::newRow("entry type") << mutated(onEntry(1, [](QJsonObject &e) { e["type"] = "int64"; })) << M
                                    << QStringList{"(P1)", "int64"};
        QTest::newRow("access") << mutated(onEntry(1, [](QJsonObject &e) { e["access"] = "rx"; })) << M
                                << QStringList{"(P1)", "\"access\"", "rx"};
        QTest::newRow("unknown entry field") << mutated(onEntry(1, [](QJsonObject &e) { e["scale"] = 10; })) << M
                                             << QStringList{"(P1)", "unknown field \"scale\""};
        QTest::newRow("index negative") << mutated(onEntry(1, [](QJsonObject &e) { e["index"] = -1; })) << M
                                        << QStringList{"\"index\"", "outside the allowed range 0 to 65535"};
        QTest::newRow("index too big") << mutated(onEntry(1, [](QJsonObject &e) {
            e["index"] = 70000;
            e["key"] = "X";
        })) << M << QStringList{"\"index\"", "0 to 65535"};
        QTest::newRow("duplicate index") << mutated(onEntry(2, [](QJsonObject &e) {
            e["index"] = 1;
            e["key"] = "other";
        })) << M << QStringList{"(other)", "index 1 is already used by P1"};
        QTest::newRow("duplicate key") << mutated([](QJsonObject &o) {
            QJsonArray a = o["parameters"].toArray();
            a.append(entry(3, "p1x"));
            a.append(entry(4, "P1X"));
            o["parameters"] = a;
        }) << M << QStringList{"(P1X)", "already used"};
        QTest::newRow("key names other index") << mutated(onEntry(1, [](QJsonObject &e) { e["key"] = "PA7"; })) << M
                                               << QStringList{"PA7", "parameter 7", "index is 1"};
        QTest::newRow("key with space") << mutated(onEntry(1, [](QJsonObject &e) { e["key"] = "max speed"; })) << M
                                        << QStringList{"max speed", "start with a letter"};
        QTest::newRow("key numeric") << mutated(onEntry(1, [](QJsonObject &e) { e["key"] = "1"; })) << M
                                     << QStringList{"start with a letter"};
        QTest::newRow("write-only with readCommand") << mutated(onEntry(1, [](QJsonObject &e) {
            e["access"] = "wo";
            e["readCommand"] = 0x26;
        })) << M << QStringList{"(P1)", "write-only", "readCommand"};
        QTest::newRow("readCommand range") << mutated(onEntry(1, [](QJsonObject &e) { e["readCommand"] = 256; })) << M
                                           << QStringList{"\"readCommand\"", "0 to 255"};
        QTest::newRow("shuoke needs readCommand") << mutated([](QJsonObject &o) {
            o["family"] = "shuoke";
            o["valueType"] = "uint32";
            onEntry(0, [](QJsonObject &e) { e["min"] = 0; })(o);
            onEntry(1, [](QJsonObject &e) { e["min"] = 0; })(o);
            onEntry(2, [](QJsonObject &e) { e["min"] = 0; })(o);
        }) << M << QStringList{"(P0)", "readCommand"};
        QTest::newRow("modbus needs register")
            << mutated([](QJsonObject &o) { o["family"] = "servo-modbus"; }) << M << QStringList{"(P0)", "register"};
        QTest::newRow("duplicate register") << mutated([](QJsonObject &o) {
            onEntry(0, [](QJsonObject &e) { e["register"] = 100; })(o);
            onEntry(1, [](QJsonObject &e) { e["register"] = 100; })(o);
        }) << M << QStringList{"(P1)", "register 100 is already used by P0"};
        QTest::newRow("models not strings") << mutated(onEntry(1, [](QJsonObject &e) { e["models"] = QJsonArray{1}; }))
                                            << M << QStringList{"(P1)", "models[0]"};
        QTest::newRow("communication not bool") << mutated(onEntry(1, [](QJsonObject &e) { e["communication"] = 1; }))
                                                << M << QStringList{"\"communication\"", "true or false"};
    }
    void badDictionary()
    {
        QFETCH(QByteArray, json);
        QFETCH(ErrorCode, code);
        QFETCH(QStringList, fragments);
        ParameterDictionary d;
        QVERIFY(!d.loadFromJson(toBytes(smallDictionary()), "first.json"));
        const Error e = d.loadFromJson(json, "bad.json");
        QCOMPARE(errorCodeName(e.code), errorCodeName(code));
        QVERIFY2(e.message.startsWith("bad.json"), qPrintable(e.message));
        for (const QString &f : fragments)
            QVERIFY2(e.message.contains(f), qPrintable(QStringLiteral("'%1' not in: %2").arg(f, e.message)));
        // A failed load leaves the previous contents.
        QCOMPARE(d.size(), 3);
        QCOMPARE(d.sourceName(), QStringLiteral("first.json"));
    }

    void wrongFamily()
    {
        ParameterDictionary d;
        Error e = d.loadFromJson(toBytes(smallDictionary()), "can.json", Family::Shuoke);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(e.message.contains("servo-can") && e.message.contains("shuoke"));
        QVERIFY(d.isEmpty());
        QVERIFY(!d.loadFromJson(toBytes(smallDictionary()), "can.json", Family::ServoCan));
    }

    void corpus()
    {
        const QDir bad(dataDir() + "/dictionaries/bad");
        const QStringList files = bad.entryList({"*.json"}, QDir::Files);
        QVERIFY2(files.size() >= 10, qPrintable(bad.path()));
        for (const QString &name : files) {
            ParameterDictionary d;
            const Error e = d.loadFromFile(bad.filePath(name));
            QCOMPARE(errorCodeName(e.code), name.section("--", 0, 0));
            QVERIFY(d.isEmpty());
        }
        const QDir good(dataDir() + "/dictionaries/good");
        for (const QString &name : good.entryList({"*.json"}, QDir::Files)) {
            ParameterDictionary d;
            const Error e = d.loadFromFile(good.filePath(name));
            QVERIFY2(!e, qPrintable(e.message));
        }
    }

    void fileErrors()
    {
        QTemporaryDir dir;
        ParameterDictionary d;
        Error e = d.loadFromFile(dir.filePath("missing.json"));
        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY(e.message.contains("missing.json"));

        QFile big(dir.filePath("big.json"));
        QVERIFY(big.open(QIODevice::WriteOnly));
        big.write(QByteArray(ParameterDictionary::MaxFileSize + 1, ' '));
        big.close();
        e = d.loadFromFile(big.fileName());
        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY(e.message.contains("larger than"));
    }

    void userDictionaryReplacesBundled()
    {
        const QString path = ParameterDictionary::userFilePath(Family::ServoCan);
        QVERIFY(path.endsWith("/dictionaries/servo-can.json"));
        QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
        auto cleanup = qScopeGuard([&] { QFile::remove(path); });

        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(toBytes(smallDictionary()));
        f.close();
        ParameterDictionary d;
        QVERIFY(!d.loadForFamily(Family::ServoCan));
        QCOMPARE(d.size(), 3);

        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("{ broken");
        f.close();
        const Error e = d.loadForFamily(Family::ServoCan);
        QCOMPARE(e.code, ErrorCode::Malformed); // reported...
        QCOMPARE(d.size(), 220);                // ...and the bundled one is used

        QFile::remove(path);
        QVERIFY(!d.loadForFamily(Family::ServoCan));
        QCOMPARE(d.size(), 220);
    }
};

QTEST_GUILESS_MAIN(TestParameterDictionary)
#include "tst_parameterdictionary.moc"
