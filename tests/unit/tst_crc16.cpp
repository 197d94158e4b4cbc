#include <QtTest>

#include "core/protocol/modbus/crc16.h"

using namespace dd;

class TestCrc16 : public QObject
{
    Q_OBJECT
private slots:
    void knownVectors_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<QByteArray>("expected");
        // Classic Modbus read-holding-registers example: 01 03 00 00 00 0A -> C5 CD
        QTest::newRow("read 10 regs") << QByteArray::fromHex("01030000000a") << QByteArray::fromHex("01030000000ac5cd");
        // CRC-16/MODBUS check value over "123456789" is 0x4B37 -> 37 4B on the wire
        QTest::newRow("check string") << QByteArray("123456789")
                                      << (QByteArray("123456789") + QByteArray::fromHex("374b"));
    }
    void knownVectors()
    {
        QFETCH(QByteArray, frame);
        QFETCH(QByteArray, expected);
        QCOMPARE(withCrc16(frame).toHex(' '), expected.toHex(' '));
        QVERIFY(hasValidCrc16(expected));
    }
    void rejectsCorruption()
    {
        QByteArray f = withCrc16(QByteArray::fromHex("010300640014"));
        QVERIFY(hasValidCrc16(f));
        f[2] = static_cast<char>(f[2] ^ 0x01);
        QVERIFY(!hasValidCrc16(f));
        QVERIFY(!hasValidCrc16(QByteArray::fromHex("01")));
        QVERIFY(!hasValidCrc16(QByteArray()));
    }
};

QTEST_APPLESS_MAIN(TestCrc16)
#include "tst_crc16.moc"
