#include <QtTest>

#include "core/protocol/modbus/crc16.h"
#include "sim/bus/uartresampler.h"

using namespace dd;

class TestUartResampler : public QObject
{
    Q_OBJECT
private slots:
    void sameRatePassesUnchanged()
    {
        QByteArray all;
        for (int i = 0; i < 256; ++i)
            all.append(static_cast<char>(i));
        QCOMPARE(UartResampler::resample(all, 9600, 9600), all);
        QCOMPARE(UartResampler::resample(QByteArray(), 9600, 19200), QByteArray());
    }

    void handComputedVectors_data()
    {
        QTest::addColumn<QByteArray>("sent");
        QTest::addColumn<int>("sentBaud");
        QTest::addColumn<int>("rxBaud");
        QTest::addColumn<QByteArray>("expected");
        // Receiver twice as fast: the start bit looks like start + data bit 0.
        QTest::newRow("ff 9600->19200") << QByteArray::fromHex("ff") << 9600 << 19200 << QByteArray::fromHex("fe");
        // All low through the receiver's stop-bit sample: framing error, read as 00.
        QTest::newRow("00 9600->19200") << QByteArray::fromHex("00") << 9600 << 19200 << QByteArray::fromHex("00");
        // Receiver twice as slow: a lone start bit is a glitch, nothing is received.
        QTest::newRow("ff 19200->9600") << QByteArray::fromHex("ff") << 19200 << 9600 << QByteArray();
        // Two characters merge into one: only the first stop bit shows up, as data bit 3.
        QTest::newRow("0000 19200->9600") << QByteArray::fromHex("0000") << 19200 << 9600 << QByteArray::fromHex("08");
    }
    void handComputedVectors()
    {
        QFETCH(QByteArray, sent);
        QFETCH(int, sentBaud);
        QFETCH(int, rxBaud);
        QFETCH(QByteArray, expected);
        QCOMPARE(UartResampler::resample(sent, sentBaud, rxBaud).toHex(' '), expected.toHex(' '));
    }

    void wrongRateNeverYieldsTheFrame_data()
    {
        QTest::addColumn<int>("sentBaud");
        QTest::addColumn<int>("rxBaud");
        const int rates[] = {2400, 4800, 9600, 19200, 38400, 57600, 115200};
        for (int s : rates)
            for (int r : rates)
                if (s != r)
                    QTest::addRow("%d->%d", s, r) << s << r;
    }
    void wrongRateNeverYieldsTheFrame()
    {
        QFETCH(int, sentBaud);
        QFETCH(int, rxBaud);
        const QByteArray frames[] = {
            withCrc16(QByteArray::fromHex("010300000002")),
            withCrc16(QByteArray::fromHex("0a10006400010200ff")),
            withCrc16(QByteArray::fromHex("012000")),
        };
        for (const QByteArray &f : frames) {
            const QByteArray heard = UartResampler::resample(f, sentBaud, rxBaud);
            QVERIFY(heard != f);
            QVERIFY(!hasValidCrc16(heard));
            // deterministic
            QCOMPARE(UartResampler::resample(f, sentBaud, rxBaud), heard);
        }
    }
};

QTEST_APPLESS_MAIN(TestUartResampler)
#include "tst_uartresampler.moc"
