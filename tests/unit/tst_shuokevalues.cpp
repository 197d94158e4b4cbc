#include <QtTest>

#include "core/protocol/shuoke/shuokevalues.h"
#include "tests/support/hex.h"

#include <limits>

using namespace dd::shuoke;

namespace {
using dd::test::hex;
constexpr ByteOrder LE = ByteOrder::LittleEndian;
constexpr ByteOrder BE = ByteOrder::BigEndian;
} // namespace

class TestShuokeValues : public QObject
{
    Q_OBJECT
private slots:
    void int32()
    {
        // Seed, PLC chapter: "02 00 00 00" carries 2 -> low byte first.
        QCOMPARE(encodeUInt32(2).toHex(' '), QByteArray("02 00 00 00"));
        QCOMPARE(encodeUInt32(1000).toHex(' '), QByteArray("e8 03 00 00"));
        QCOMPARE(encodeUInt32(1000, BE).toHex(' '), QByteArray("00 00 03 e8"));
        QCOMPARE(encodeInt32(-1000).toHex(' '), QByteArray("18 fc ff ff"));
        QCOMPARE(encodeInt32(-1000, BE).toHex(' '), QByteArray("ff ff fc 18"));
        QCOMPARE(encodeUInt32(0x12345678).toHex(' '), QByteArray("78 56 34 12"));
        QCOMPARE(*decodeUInt32(hex("78563412")), quint32(0x12345678));
        QCOMPARE(*decodeUInt32(hex("12345678"), BE), quint32(0x12345678));
        QCOMPARE(*decodeInt32(hex("18fcffff")), qint32(-1000));
        QCOMPARE(*decodeInt32(hex("fffffc18"), BE), qint32(-1000));
        QCOMPARE(*decodeInt32(encodeInt32(std::numeric_limits<qint32>::min())), std::numeric_limits<qint32>::min());
        QCOMPARE(*decodeUInt32(encodeUInt32(0xFFFFFFFFu, BE), BE), 0xFFFFFFFFu);
        QVERIFY(!decodeUInt32(hex("010203")));
        QVERIFY(!decodeInt32(hex("0102030405")));
        QVERIFY(!decodeInt32(QByteArray()));
    }

    void uint16()
    {
        QCOMPARE(encodeUInt16(0x1234).toHex(' '), QByteArray("34 12"));
        QCOMPARE(encodeUInt16(0x1234, BE).toHex(' '), QByteArray("12 34"));
        QCOMPARE(*decodeUInt16(hex("3412")), quint16(0x1234));
        QCOMPARE(*decodeUInt16(hex("1234"), BE), quint16(0x1234));
        QVERIFY(!decodeUInt16(hex("12")));
    }

    void direction24_data()
    {
        QTest::addColumn<int>("value");
        QTest::addColumn<int>("order");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("+200000 LE") << 200000 << int(LE) << hex("01400d03");
        QTest::newRow("+200000 BE") << 200000 << int(BE) << hex("01030d40");
        QTest::newRow("-1000 LE") << -1000 << int(LE) << hex("00e80300");
        QTest::newRow("-1000 BE") << -1000 << int(BE)
                                  << hex("0000"
                                         "03e8");
        QTest::newRow("0 is positive") << 0 << int(LE) << hex("01000000");
        QTest::newRow("max") << 0xFFFFFF << int(LE) << hex("01ffffff");
        QTest::newRow("min") << -0xFFFFFF << int(BE) << hex("00ffffff");
    }
    void direction24()
    {
        QFETCH(int, value);
        QFETCH(int, order);
        QFETCH(QByteArray, bytes);
        const auto o = static_cast<ByteOrder>(order);
        QCOMPARE(encodeDirection24(value, o)->toHex(' '), bytes.toHex(' '));
        QCOMPARE(*decodeDirection24(bytes, o), value);
    }
    void direction24Invalid()
    {
        QVERIFY(!encodeDirection24(0x1000000));
        QVERIFY(!encodeDirection24(-0x1000000));
        QVERIFY(!decodeDirection24(hex("02000000")));
        QVERIFY(!decodeDirection24(hex("ff000000")));
        QVERIFY(!decodeDirection24(hex("010000")));
    }

    void ranges()
    {
        QVERIFY(isSpeedInRange(0));
        QVERIFY(isSpeedInRange(100000));
        QVERIFY(!isSpeedInRange(100001));
        QVERIFY(!isSpeedInRange(-1));
        QVERIFY(isSignedSpeedInRange(-100000));
        QVERIFY(!isSignedSpeedInRange(-100001));
        QVERIFY(!isGearDenominatorInRange(0));
        QVERIFY(isGearNumeratorInRange(0));
        QVERIFY(isGearNumeratorInRange(65535));
        QVERIFY(!isGearNumeratorInRange(65536));
        QVERIFY(isPulseCountInRange(std::numeric_limits<qint32>::max()));
        QVERIFY(!isPulseCountInRange(std::numeric_limits<qint32>::min()));
    }

    void validate_data()
    {
        QTest::addColumn<int>("command");
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<int>("order");
        QTest::addColumn<bool>("valid");
        auto row = [](const char *name, int cmd, const QByteArray &d, bool ok, ByteOrder o = LE) {
            QTest::newRow(name) << cmd << d << int(o) << ok;
        };
        row("unknown command", 0x50, QByteArray(), false);
        row("wrong length", 0x25, hex("e80300"), false);
        row("query with data", 0x36, hex("00"), false);
        row("query", 0x36, QByteArray(), true);
        row("address 2", 0x22, hex("02"), true);
        row("address 0", 0x22, hex("00"), false);
        row("address 247", 0x22, hex("f7"), true);
        row("address 248", 0x22, hex("f8"), false);
        row("baud 8", 0x24, hex("08"), true);
        row("baud 9 reserved", 0x24, hex("09"), false);
        row("baud 0", 0x24, hex("00"), false);
        row("start speed 100000", 0x25, encodeUInt32(100000), true);
        row("start speed 100001", 0x25, encodeUInt32(100001), false);
        row("max speed BE 100000", 0x27, encodeUInt32(100000, BE), true, BE);
        row("max speed BE read as LE", 0x27, encodeUInt32(100000, BE), false, LE);
        row("accel 0", 0x2B, encodeUInt32(0), true);
        row("decel huge", 0x2D, encodeUInt32(0x80000000u), false);
        row("speed step F", 0x44, encodeUInt32(100001), false);
        row("change speed", 0x35, encodeUInt32(5000), true);
        row("jog -100000", 0x33, encodeInt32(-100000), true);
        row("jog -100001", 0x33, encodeInt32(-100001), false);
        row("jog dir24 100000", 0x34, *encodeDirection24(-100000), true);
        row("jog dir24 100001", 0x34, *encodeDirection24(100001), false);
        row("jog dir24 bad direction", 0x34, hex("02e80300"), false);
        row("move dir24", 0x32, *encodeDirection24(0xFFFFFF), true);
        row("move dir24 bad direction", 0x32, hex("05000000"), false);
        row("move int32", 0x31, encodeInt32(-2000000000), true);
        row("move int32 min", 0x31, encodeInt32(std::numeric_limits<qint32>::min()), false);
        row("home 1", 0x3E, hex("01"), true);
        row("home 2", 0x3E, hex("02"), false);
        row("homing variant 0x4E", 0x4E, hex("00"), true);
        row("homing variant 0x4F bad", 0x4F, hex("03"), false);
        row("s-curve 0x4E", 0x4E, encodeInt32(-5), true);
        row("s-curve 0x4F", 0x4F, *encodeDirection24(5), true);
        row("s-curve 0x4F bad direction", 0x4F, hex("07050000"), false);
        row("fixed replies 1", 0x49, hex("01"), true);
        row("crc skip 2", 0x48, hex("02"), false);
        row("encoder dir 1", 0x5C, hex("01"), true);
        row("encoder dir 2", 0x5C, hex("02"), false);
        row("can bitrate 18", 0x4B, hex("12"), true);
        row("can bitrate 19", 0x4B, hex("13"), false);
        row("can bitrate 0", 0x4B, hex("00"), false);
        row("io subst index 15", 0x40, hex("0f0102"), true);
        row("io subst index 16", 0x40, hex("100102"), false);
        row("io read index 0", 0x41, hex("00"), false);
        row("gear num 65535", 0x5F, encodeUInt32(65535), true);
        row("gear num 65536", 0x5F, encodeUInt32(65536), false);
        row("gear den 0", 0x61, encodeUInt32(0), false);
        row("gear den 1", 0x61, encodeUInt32(1), true);
        row("clear closed-loop position", 0x59, QByteArray(), true);
        row("set closed-loop position", 0x59, encodeInt32(-7), true);
        row("plc base", 0x3F, encodeUInt16(0x100), true);
        row("ab tolerance", 0x65, encodeUInt32(200), true);
    }
    void validate()
    {
        QFETCH(int, command);
        QFETCH(QByteArray, data);
        QFETCH(int, order);
        QFETCH(bool, valid);
        const QString why = validateRequestData(static_cast<quint8>(command), data, static_cast<ByteOrder>(order));
        QVERIFY2(why.isEmpty() == valid, qPrintable(why));
    }

    void status()
    {
        const auto s = decodeMotionStatus(hex("0100010001"));
        QVERIFY(s);
        QVERIFY(s->running);
        QVERIFY(!s->leftLimit);
        QVERIFY(s->origin);
        QVERIFY(!s->rightLimit);
        QVERIFY(s->enableInput);
        QCOMPARE(encodeMotionStatus(*s).toHex(' '), QByteArray("01 00 01 00 01"));
        MotionStatus limits;
        limits.leftLimit = limits.rightLimit = true;
        QCOMPARE(encodeMotionStatus(limits).toHex(' '), QByteArray("00 01 00 01 00"));
        QVERIFY(*decodeMotionStatus(encodeMotionStatus(limits)) == limits);
        QVERIFY(decodeMotionStatus(hex("0100010001000000"))); // PLC: 8 bytes, first 5 count
        QVERIFY(!decodeMotionStatus(hex("01000100")));
    }

    void inputBits()
    {
        QCOMPARE(*decodeInputBits(hex("0100000001")), quint8(0x11));
        QCOMPARE(*decodeInputBits(hex("0001010100")), quint8(0x0E));
        QCOMPARE(*decodeInputBits(hex("ff00000000")), quint8(0x01));
        QVERIFY(!decodeInputBits(hex("01000000")));
    }
};

QTEST_APPLESS_MAIN(TestShuokeValues)
#include "tst_shuokevalues.moc"
