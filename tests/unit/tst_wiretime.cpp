#include <QtTest>

#include "core/link/wiretime.h"

using namespace dd;

class TestWireTime : public QObject
{
    Q_OBJECT
private slots:
    void serialCharTime()
    {
        QCOMPARE(WireTime::serialCharUs(9600), 1e6 * 10 / 9600);
        QVERIFY(qFuzzyCompare(WireTime::serialCharUs(9600), 1041.6666666666667));
        QCOMPARE(WireTime::serialCharUs(115200), 1e6 * 10 / 115200);
        // 8E1 / 8N2: 11 bits a character
        QVERIFY(qFuzzyCompare(WireTime::serialCharUs(9600, 11), 1145.8333333333333));
        QCOMPARE(WireTime::serialCharUs(0), 0.0);
        QCOMPARE(WireTime::serialCharUs(-9600), 0.0);
    }

    void serialBytesTime()
    {
        // An 8-byte Modbus request at 9600 8N1: 80 bits = 8333.3 µs
        QVERIFY(qFuzzyCompare(WireTime::serialBytesUs(8, 9600), 8333.333333333334));
        QVERIFY(qFuzzyCompare(WireTime::serialBytesUs(8, 115200), 694.4444444444445));
        QVERIFY(qFuzzyCompare(WireTime::serialBytesUs(256, 19200), 256 * 10 * 1e6 / 19200));
        QCOMPARE(WireTime::serialBytesUs(0, 9600), 0.0);
        QCOMPARE(WireTime::serialBytesUs(-3, 9600), 0.0);
    }

    void modbusSilence()
    {
        // 3.5 characters up to 19200 baud ...
        QVERIFY(qFuzzyCompare(WireTime::modbusSilenceUs(9600), 3.5 * 1e6 * 10 / 9600));
        QVERIFY(qFuzzyCompare(WireTime::modbusSilenceUs(19200), 3.5 * 1e6 * 10 / 19200)); // 1822.9
        // ... a fixed 1750 µs above it
        QCOMPARE(WireTime::modbusSilenceUs(38400), 1750.0);
        QCOMPARE(WireTime::modbusSilenceUs(115200), 1750.0);
        QCOMPARE(WireTime::modbusSilenceUs(115200, 11), 1750.0);
        // before a request to the drive that has just answered: 3.5 characters at every baud
        QVERIFY(qFuzzyCompare(WireTime::modbusSameDriveSilenceUs(115200), 3.5 * 1e6 * 10 / 115200)); // 303.8
        QVERIFY(qFuzzyCompare(WireTime::modbusSameDriveSilenceUs(9600), WireTime::modbusSilenceUs(9600)));
        QVERIFY(qFuzzyCompare(WireTime::modbusInterCharUs(9600), 1.5 * 1e6 * 10 / 9600));
        QCOMPARE(WireTime::modbusInterCharUs(57600), 750.0);
    }

    void canFrameBits_data()
    {
        QTest::addColumn<int>("dlc");
        QTest::addColumn<bool>("extended");
        QTest::addColumn<int>("nominal");
        QTest::addColumn<int>("worstCase");
        // nominal = 47 + 8n (2.0A) / 67 + 8n (2.0B), incl. 3-bit intermission;
        // stuffing adds floor((34 + 8n - 1) / 4) resp. floor((54 + 8n - 1) / 4)
        QTest::newRow("2.0A dlc 0") << 0 << false << 47 << 55;
        QTest::newRow("2.0A dlc 1") << 1 << false << 55 << 65;
        QTest::newRow("2.0A dlc 8") << 8 << false << 111 << 135;
        QTest::newRow("2.0B dlc 0") << 0 << true << 67 << 80;
        QTest::newRow("2.0B dlc 8") << 8 << true << 131 << 160;
        QTest::newRow("dlc clamped high") << 12 << false << 111 << 135;
        QTest::newRow("dlc clamped low") << -1 << false << 47 << 55;
    }
    void canFrameBits()
    {
        QFETCH(int, dlc);
        QFETCH(bool, extended);
        QFETCH(int, nominal);
        QFETCH(int, worstCase);
        QCOMPARE(WireTime::canFrameBits(dlc, extended, CanStuffing::None), nominal);
        QCOMPARE(WireTime::canFrameBits(dlc, extended, CanStuffing::WorstCase), worstCase);
        QCOMPARE(WireTime::canFrameBits(dlc, extended), worstCase); // the default
    }

    void canFrameTime()
    {
        QCOMPARE(WireTime::canFrameUs(8, false, 1000000), 135.0);
        QCOMPARE(WireTime::canFrameUs(8, false, 1000000, CanStuffing::None), 111.0);
        QCOMPARE(WireTime::canFrameUs(8, false, 100000), 1350.0);
        QCOMPARE(WireTime::canFrameUs(8, true, 250000), 640.0);
        QCOMPARE(WireTime::canFrameUs(8, false, 0), 0.0);
    }
};

QTEST_APPLESS_MAIN(TestWireTime)
#include "tst_wiretime.moc"
