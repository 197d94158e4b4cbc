// FrameDescriber: what the frame monitor says a frame means, per family and framing.
#include "core/protocol/familytraits.h"
#include "core/protocol/framedescriber.h"
#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/shuoke/shuokecan.h"
#include "core/protocol/shuoke/shuokeplc.h"
#include "core/protocol/shuoke/shuokevalues.h"
#include "tests/support/hex.h"

#include <QTest>

using namespace dd;
using Origin = FrameDescriber::Origin;

namespace {
CanFrameData can(quint32 id, const char *hex)
{
    CanFrameData f;
    f.id = id;
    f.data = QByteArray::fromHex(hex);
    return f;
}
using dd::test::hex;
} // namespace

class TestFrameDescriber : public QObject
{
    Q_OBJECT

private slots:
    void servoCanSeedExamples_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<QString>("expected");
        // The seed's examples, station 0 (ID 0x064).
        QTest::newRow("keep-alive") << hex("00 08 00 00 00 00 00 FF") << QStringLiteral("#0 keep-alive");
        QTest::newRow("enable") << hex("00 25 01 00 00 00 00 FF") << QStringLiteral("#0 servo on");
        QTest::newRow("speed") << hex("00200064000000FF") << QStringLiteral("#0 run at 100 r/min");
        QTest::newRow("pos speed") << hex("002300C8000000FF") << QStringLiteral("#0 positioning speed 200 r/min");
        QTest::newRow("relative") << hex("002100E8030000FF") << QStringLiteral("#0 move by 1000");
        QTest::newRow("absolute") << hex("002200E8030000FF") << QStringLiteral("#0 move to 1000");
        QTest::newRow("stop") << hex("00260000000000FF") << QStringLiteral("#0 stop");
        QTest::newRow("stop+disable") << hex("00280000000000FF") << QStringLiteral("#0 stop and disable");
        QTest::newRow("clear alarm") << hex("00810000000000FF") << QStringLiteral("#0 clear alarm");
        QTest::newRow("write P12") << hex("0015010C005901FF") << QStringLiteral("#0 write P12 = 345");
        QTest::newRow("negative speed") << hex("00200038FFFFFFFF") << QStringLiteral("#0 run at -200 r/min");
    }

    void servoCanSeedExamples()
    {
        QFETCH(QByteArray, data);
        QFETCH(QString, expected);
        const auto d_ = createFrameDescriber(Family::ServoCan);
        FrameDescriber &d = *d_;
        CanFrameData f;
        f.id = 0x64;
        f.data = data;
        QCOMPARE(d.describeCan(Origin::Host, f), expected);
    }

    void servoCanDriveFrames()
    {
        const auto d_ = createFrameDescriber(Family::ServoCan);
        FrameDescriber &d = *d_;
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "011088D2040000FF")),
                 QStringLiteral("#1 heartbeat: idle, position 1234"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "01100018FCFFFFFF")),
                 QStringLiteral("#1 heartbeat: running, position -1000"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "01050C00000000FF")), QStringLiteral("#1 alarm 12"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "01050000000000FF")), QStringLiteral("#1 no alarm"));
        // Reads: the request names what is read, the reply its value with unit and scale.
        QCOMPARE(d.describeCan(Origin::Host, can(0x65, "0112FA0C000000FF")), QStringLiteral("#1 read P12"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "0112FA0C005901FF")), QStringLiteral("#1 P12 = 345"));
        QCOMPARE(d.describeCan(Origin::Host, can(0x65, "0112FC00000000FF")), QStringLiteral("#1 read Speed"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "0112FC64000000FF")), QStringLiteral("#1 Speed = 100 r/min"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "0112A496000000FF")),
                 QStringLiteral("#1 Output current = 1.50 A"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x65, "0112A80B000000FF")), QStringLiteral("#1 Input IO = 0xB"));
    }

    void servoCanMalformed()
    {
        const auto d_ = createFrameDescriber(Family::ServoCan);
        FrameDescriber &d = *d_;
        const QString bad = d.describeCan(Origin::Drive, can(0x200, "01 10 88 00 00 00 00 FF"));
        QVERIFY2(bad.startsWith(QLatin1String("? (")), qPrintable(bad));
        QVERIFY2(d.describeCan(Origin::Drive, can(0x65, "01 EE 00 00 00 00 00 FF")).startsWith(QLatin1String("? (")),
                 "unknown command");
        // A serial frame on a CAN family, a CAN frame on a serial family: unknown.
        QCOMPARE(d.describeSerial(Origin::Host, hex("010300640014041A")), QStringLiteral("?"));
        const auto m_ = createFrameDescriber(Family::ServoModbus);
        FrameDescriber &m = *m_;
        QCOMPARE(m.describeCan(Origin::Host, can(0x65, "0112FA0C000000FF")), QStringLiteral("?"));
    }

    void modbusReadAndReply()
    {
        const auto d_ = createFrameDescriber(Family::ServoModbus);
        FrameDescriber &d = *d_;
        QCOMPARE(d.describeSerial(Origin::Host, hex("010300640014041A")), QStringLiteral("#1 read PA0–PA19"));
        QList<quint16> values{7051, 0, 5, 0xFFFF};
        for (int i = 4; i < 20; ++i)
            values << quint16(i);
        QCOMPARE(d.describeSerial(Origin::Drive, modbusrtu::encodeReadHoldingReply(1, values)),
                 QStringLiteral("#1 PA0 = 7051, PA1 = 0, PA2 = 5, PA3 = -1, … (20 values)"));
        // Two registers, byte-exact.
        QCOMPARE(d.describeSerial(Origin::Host, modbusrtu::encodeReadHoldingRequest(1, 0x64, 2)),
                 QStringLiteral("#1 read PA0–PA1"));
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 03 04 1B 8B FF FF 8D 4D")),
                 QStringLiteral("#1 PA0 = 7051, PA1 = -1"));
        // The DP monitor by mnemonic.
        QCOMPARE(d.describeSerial(Origin::Host, modbusrtu::encodeReadHoldingRequest(1, 0x0000, 3)),
                 QStringLiteral("#1 read DP-SPd–DP-PoS."));
        QCOMPARE(d.describeSerial(Origin::Drive, modbusrtu::encodeReadHoldingReply(1, {100, 2, 0})),
                 QStringLiteral("#1 DP-SPd = 100, DP-PoS = 2, DP-PoS. = 0"));
        QCOMPARE(d.describeSerial(Origin::Host, modbusrtu::encodeReadHoldingRequest(1, 0x0013, 1)),
                 QStringLiteral("#1 read DP-Err"));
        // Exception (the drive fixes its address byte to 1).
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 83 04 40 F3")),
                 QStringLiteral("#1 exception 4: server device failure"));
    }

    void modbusWritesAndEe()
    {
        const auto d_ = createFrameDescriber(Family::ServoModbus);
        FrameDescriber &d = *d_;
        QCOMPARE(d.describeSerial(Origin::Host, modbusrtu::encodeWriteMultipleRequest(1, 0x69, {10, 0xFFFE, 3})),
                 QStringLiteral("#1 write PA5–PA7 = 10, -2, 3"));
        QCOMPARE(d.describeSerial(Origin::Drive, modbusrtu::encodeWriteMultipleReply(1, 0x69, 3)),
                 QStringLiteral("#1 written PA5–PA7"));
        QCOMPARE(d.describeSerial(Origin::Host, modbusrtu::encodeWriteMultipleRequest(1, 0x64, {1, 2, 3, 4, 5})),
                 QStringLiteral("#1 write PA0–PA4 = 1, 2, 3, 4, …"));
        // EE, new format (0x10 at 0x3A) and legacy (0x06 at 0, progress in the reply).
        QCOMPARE(d.describeSerial(Origin::Host, hex("01 10 00 3A 00 01 02 00 01 62 CA")),
                 QStringLiteral("#1 EE operation EE-Set"));
        QCOMPARE(d.describeSerial(Origin::Drive, modbusrtu::encodeWriteMultipleReply(1, 0x3A, 1)),
                 QStringLiteral("#1 EE operation accepted"));
        QCOMPARE(d.describeSerial(Origin::Host, modbusrtu::encodeWriteSingleRequest(1, 0, 5)),
                 QStringLiteral("#1 EE operation EE-dEF"));
        QCOMPARE(d.describeSerial(Origin::Drive, modbusrtu::encodeWriteSingleReply(1, 0, 0)),
                 QStringLiteral("#1 EE operation running"));
        QCOMPARE(d.describeSerial(Origin::Drive, modbusrtu::encodeWriteSingleReply(1, 0, 5)),
                 QStringLiteral("#1 EE operation EE-dEF done"));
        // Broadcast (address change of every drive on the bus).
        QCOMPARE(d.describeSerial(Origin::Host, hex("00 10 00 97 00 01 02 00 03 F7 26")),
                 QStringLiteral("all (broadcast): write PA51 = 3"));
    }

    void modbusRepliesNeedTheirRequest()
    {
        const auto d_ = createFrameDescriber(Family::ServoModbus);
        FrameDescriber &d = *d_;
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 03 04 1B 8B FF FF 8D 4D")),
                 QStringLiteral("? (reply without a request)"));
        // A reply that does not fit the request before it (4 registers asked, 2 given).
        d.describeSerial(Origin::Host, modbusrtu::encodeReadHoldingRequest(1, 0x64, 4));
        QVERIFY(d.describeSerial(Origin::Drive, hex("01 03 04 1B 8B FF FF 8D 4D")).startsWith(QLatin1String("? (")));
        // A damaged request: bad CRC; the next reply is not attributed to an older request.
        QVERIFY(d.describeSerial(Origin::Host, hex("01 03 00 64 00 14 04 1B")).startsWith(QLatin1String("? (")));
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 03 04 1B 8B FF FF 8D 4D")),
                 QStringLiteral("? (reply without a request)"));
        d.describeSerial(Origin::Host, modbusrtu::encodeReadHoldingRequest(1, 0x64, 2));
        d.reset();
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 03 04 1B 8B FF FF 8D 4D")),
                 QStringLiteral("? (reply without a request)"));
    }

    void shuokeRtu()
    {
        const auto d_ = createFrameDescriber(Family::Shuoke);
        FrameDescriber &d = *d_;
        QCOMPARE(d.describeSerial(Origin::Host, hex("01 33 04 E8 03 00 00 3A 63")),
                 QStringLiteral("#1 Run at constant speed (signed) 1000"));
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 33 00 34 F0")),
                 QStringLiteral("#1 Run at constant speed (signed): OK"));
        QCOMPARE(d.describeSerial(Origin::Host, hex("01 36 00 37 A0")), QStringLiteral("#1 Query speed"));
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 36 04 E8 03 00 00 3A 36")),
                 QStringLiteral("#1 Query speed → 1000"));
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 B3 01 04 F0 6C")),
                 QStringLiteral("#1 Run at constant speed (signed) failed: Value out of range"));
        QCOMPARE(d.describeSerial(Origin::Drive, hex("01 3B 05 01 00 01 00 01 A6 91")),
                 QStringLiteral("#1 Query status → running, origin, enable input"));
        QVERIFY(d.describeSerial(Origin::Drive, hex("01 3B 05 01 00 01 00 01 A6 92")).startsWith(QLatin1String("? (")));
    }

    void shuokeAsciiSeedExample()
    {
        // The seed's worked example: change address 1 -> 2.
        const auto d_ = createFrameDescriber(Family::Shuoke, QStringLiteral("ascii"));
        FrameDescriber &d = *d_;
        QCOMPARE(d.describeSerial(Origin::Host, QByteArray(":0122010226\r\n")), QStringLiteral("#1 Change address 2"));
        const auto twos_ = createFrameDescriber(
            Family::Shuoke, QStringLiteral("ascii"),
            {{QStringLiteral("shuoke.checksum"), QStringLiteral("twos-complement")}});
        FrameDescriber &twos = *twos_;
        QVERIFY(twos.describeSerial(Origin::Host, QByteArray(":0122010226\r\n")).startsWith(QLatin1String("? (")));
        QCOMPARE(twos.describeSerial(Origin::Host, QByteArray(":01220102DA\r\n")),
                 QStringLiteral("#1 Change address 2"));
    }

    void shuokeCanAndPlc()
    {
        const auto d_ = createFrameDescriber(Family::Shuoke, QStringLiteral("can"));
        FrameDescriber &d = *d_;
        QCOMPARE(d.describeCan(Origin::Host, can(0x01, "013E010100000000")), QStringLiteral("#1 Home positive first"));
        QCOMPARE(d.describeCan(Origin::Host, can(0x00, "003C000000000000")),
                 QStringLiteral("all (broadcast): Emergency stop"));
        QCOMPARE(d.describeCan(Origin::Drive, can(0x03, "033C000000000000")), QStringLiteral("#3 Emergency stop: OK"));

        const auto plc_ = createFrameDescriber(Family::Shuoke, QStringLiteral("plc"),
                                               {{QStringLiteral("shuoke.plcBase"), 0x100}});
        FrameDescriber &plc = *plc_;
        const shuoke::Frame request = shuoke::Frame::make(1, 0x36);
        shuoke::PlcOptions options;
        options.base = 0x100;
        const QByteArray adu = *shuoke::encodePlcRequest(request, options).value;
        QCOMPARE(adu.at(1), char(0x03)); // a Modbus read
        QCOMPARE(plc.describeSerial(Origin::Host, adu), QStringLiteral("#1 Query speed"));
        const QByteArray reply =
            *shuoke::encodePlcReply(shuoke::Frame::make(1, 0x36, shuoke::encodeInt32(-5)), request, options).value;
        QCOMPARE(plc.describeSerial(Origin::Drive, reply), QStringLiteral("#1 Query speed → -5"));
        QCOMPARE(plc.describeSerial(Origin::Drive, modbusrtu::encodeExceptionReply(1, 0x03, 2)),
                 QStringLiteral("#1 Query speed failed: illegal data address"));
    }

    void shuokeByteOrder()
    {
        const auto big_ = createFrameDescriber(Family::Shuoke, {},
                                               {{QStringLiteral("shuoke.byteOrder"), QStringLiteral("big")}});
        FrameDescriber &big = *big_;
        const auto little_ = createFrameDescriber(Family::Shuoke);
        FrameDescriber &little = *little_;
        const QByteArray frame = hex("01 33 04 E8 03 00 00 3A 63");
        QCOMPARE(little.describeSerial(Origin::Host, frame), QStringLiteral("#1 Run at constant speed (signed) 1000"));
        QCOMPARE(big.describeSerial(Origin::Host, frame),
                 QStringLiteral("#1 Run at constant speed (signed) %1").arg(qint32(0xE8030000)));
    }
};

QTEST_APPLESS_MAIN(TestFrameDescriber)
#include "tst_framedescriber.moc"
