// The simulated servo-modbus drive on its own: requests in, reply bytes out (no bus, no pty).

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/modbus/modbusrtu.h"
#include "sim/servomodbus/simservomodbusdrive.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QtTest>

using namespace dd;

namespace {

QByteArray adu(const char *hexWithoutCrc)
{
    return withCrc16(QByteArray::fromHex(hexWithoutCrc));
}

SimServoModbusDrive::Config modbusConfig(int address = 1, quint16 firmware = 7051)
{
    SimServoModbusDrive::Config c;
    c.address = address;
    c.baud = 19200;
    c.firmware = firmware;
    return c;
}

} // namespace

class TestSimServoModbusDrive : public QObject
{
    Q_OBJECT

    qint64 m_now = 0;
    QList<QByteArray> send(SimServoModbusDrive &d, const QByteArray &bytes, qint64 gapUs = 100000)
    {
        m_now += gapUs;
        return d.onBusBytes(bytes, m_now);
    }

private slots:
    void init() { m_now = 0; }

    void readsParameters()
    {
        SimServoModbusDrive d(modbusConfig(1));
        const auto r = send(d, adu("010300640003"));
        QCOMPARE(r.size(), 1);
        QCOMPARE(r[0], adu("010306013b00651b8b")); // PA0 315, PA1 101, PA2 7051
    }

    void ignoresOtherAddresses()
    {
        SimServoModbusDrive d(modbusConfig(3));
        QVERIFY(send(d, adu("010300640001")).isEmpty());
        QCOMPARE(send(d, adu("030300640001")).size(), 1);
        QCOMPARE(d.requestsAnswered(), quint64(1));
    }

    // The seed's error reply: 驱动器在对接收的数据进行校验后，若检测出错误 … 若读操作校验出错，则
    // 出错码为读操作功能码+0x80; address byte fixed 0x01, type 0x04. A request to this drive
    // whose CRC fails is answered so (it used to get no reply); one for another address or the
    // broadcast is not. Bytes by hand (read PA5 = register 0x0069 of drive 5: CRC 55 92).
    void damagedRequestGetsTheSeedsErrorReply()
    {
        SimServoModbusDrive d(modbusConfig(5));
        const QList<QByteArray> none;
        QCOMPARE(send(d, QByteArray::fromHex("05 03 00 69 00 01 55 93")),
                 QList<QByteArray>{QByteArray::fromHex("01 83 04 40 F3")});
        QCOMPARE(send(d, QByteArray::fromHex("05 03 00 69 00 01 54 92")),
                 QList<QByteArray>{QByteArray::fromHex("01 83 04 40 F3")});
        QCOMPARE(send(d, QByteArray::fromHex("06 03 00 69 00 01 55 A0")), none); // drive 6's
        QCOMPARE(send(d, QByteArray::fromHex("00 03 00 69 00 01 55 C6")), none); // broadcast
        // Write PA0 = 10 (05 10 00 64 00 01 02 00 0A, CRC 1C B3), damaged: the write's code.
        QCOMPARE(send(d, QByteArray::fromHex("05 10 00 64 00 01 02 00 0A 1C B2")),
                 QList<QByteArray>{QByteArray::fromHex("01 90 04 4D C3")});
        QVERIFY(d.parameter(0) != 10);
        QCOMPARE(d.checksumErrors(), quint64(3));
        // The damaged request in two pieces (no silence between) is judged once it is whole.
        m_now += 100000;
        QCOMPARE(d.onBusBytes(QByteArray::fromHex("05 03 00"), m_now), none);
        m_now += 3000; // 5 more characters at 19200 baud
        QCOMPARE(d.onBusBytes(QByteArray::fromHex("69 00 01 55 93"), m_now),
                 QList<QByteArray>{QByteArray::fromHex("01 83 04 40 F3")});
        // The same request undamaged is answered as usual.
        QCOMPARE(send(d, QByteArray::fromHex("05 03 00 69 00 01 55 92")).size(), 1);
        // Line noise on the way (the test hook) damages the next request to this drive only.
        d.damageIncomingRequests(1);
        QCOMPARE(send(d, QByteArray::fromHex("06 03 00 69 00 01 55 A1")), none);
        QCOMPARE(send(d, QByteArray::fromHex("05 03 00 69 00 01 55 92")),
                 QList<QByteArray>{QByteArray::fromHex("01 83 04 40 F3")});
        QCOMPARE(send(d, QByteArray::fromHex("05 03 00 69 00 01 55 92")).size(), 1);
        QCOMPARE(send(d, QByteArray::fromHex("05 03 00 69 00 01 55 92")).first().left(3),
                 QByteArray::fromHex("05 03 02"));
    }

    void exceptionsCarryAddressOneAndCodeFour()
    {
        SimServoModbusDrive d(modbusConfig(7));
        QCOMPARE(send(d, adu("070300640015")), QList<QByteArray>{adu("018304")});       // 21 registers
        QCOMPARE(send(d, adu("070300180001")), QList<QByteArray>{adu("018304")});       // past DP-rES
        QCOMPARE(send(d, adu("070300100010")), QList<QByteArray>{adu("018304")});       // DP into the gap
        QCOMPARE(send(d, adu("071000000001020005")), QList<QByteArray>{adu("019004")}); // write to DP
        QCOMPARE(send(d, adu("070600640001")), QList<QByteArray>{adu("018604")});       // 0x06 to a PA
        d.setExceptionAddressFixed(false);
        QCOMPARE(send(d, adu("070300640015")), QList<QByteArray>{adu("078304")});
        QCOMPARE(d.exceptionsSent(), quint64(6));
    }

    void writesAndReadOnlyFirmware()
    {
        SimServoModbusDrive d(modbusConfig(1));
        QCOMPARE(send(d, adu("0110006500020404d2fffb")), QList<QByteArray>{adu("011000650002")});
        QCOMPARE(d.parameter(1), quint16(1234));
        QCOMPARE(d.parameter(2), quint16(7051)); // PA2 ignores writes
    }

    void broadcastActsWithoutReply()
    {
        SimServoModbusDrive d(modbusConfig(4));
        QVERIFY(send(d, adu("00100070000102002a")).isEmpty());
        QCOMPARE(d.parameter(12), quint16(42));
        QVERIFY(send(d, adu("000300640001")).isEmpty());
        QCOMPARE(d.broadcastsHandled(), quint64(2));
    }

    void legacyEeReportsProgress()
    {
        SimServoModbusDrive::Config c = modbusConfig(1, 7041);
        c.eeBusyUs = 300000;
        SimServoModbusDrive d(c);
        d.setParameter(30, 77);
        QCOMPARE(send(d, adu("010600000001"), 1000), QList<QByteArray>{adu("010600000000")}); // started
        QVERIFY(d.eeRunning());
        QCOMPARE(send(d, adu("010600000001"), 100000), QList<QByteArray>{adu("010600000000")}); // running
        QCOMPARE(d.eepromParameter(30), quint16(130));
        QCOMPARE(send(d, adu("010600000001"), 250000), QList<QByteArray>{adu("010600000001")}); // done
        QCOMPARE(d.eepromParameter(30), quint16(77));
        QVERIFY(!d.eeRunning());
        // The new format is not understood by this firmware.
        QCOMPARE(send(d, adu("0110003a0001020001")), QList<QByteArray>{adu("019004")});
        // An op code outside 1..5.
        QCOMPARE(send(d, adu("010600000009")), QList<QByteArray>{adu("018604")});
    }

    void newEeFormatAndEveryOperation()
    {
        SimServoModbusDrive d(modbusConfig(1, 7051));
        QCOMPARE(send(d, adu("010600000001")), QList<QByteArray>{adu("018604")}); // legacy refused
        d.setParameter(20, 5);
        QCOMPARE(send(d, adu("0110003a0001020003")), QList<QByteArray>{adu("0110003a0001")}); // EE-bA
        QCOMPARE(d.backupParameter(20), quint16(5));
        d.setParameter(20, 6);
        send(d, adu("0110003a0001020001")); // EE-Set
        QCOMPARE(d.eepromParameter(20), quint16(6));
        d.setParameter(20, 7);
        send(d, adu("0110003a0001020002")); // EE-rd
        QCOMPARE(d.parameter(20), quint16(6));
        send(d, adu("0110003a0001020004")); // EE-rS
        QCOMPARE(d.parameter(20), quint16(5));
        send(d, adu("0110003a0001020005")); // EE-dEF
        QCOMPARE(d.parameter(20), quint16(120));
        QCOMPARE(d.eepromParameter(20), quint16(120));
        QCOMPARE(d.parameter(2), quint16(7051));
        QCOMPARE(d.eeOperationsCompleted(), 5);
    }

    void addressChangeTakesEffectAfterSaveAndPowerCycle()
    {
        SimServoModbusDrive d(modbusConfig(1));
        send(d, adu("011000970001020009")); // PA51 = 9
        QCOMPARE(d.address(), 1);
        send(d, adu("0110003a0001020001")); // EE-Set
        d.powerCycle();
        QCOMPARE(d.address(), 9);
        QCOMPARE(send(d, adu("090300970001")), QList<QByteArray>{adu("0903020009")});
    }

    void framesSplitOrJoinedAndResyncAfterSilence()
    {
        SimServoModbusDrive d(modbusConfig(1));
        const QByteArray req = adu("010300640001");
        QVERIFY(send(d, req.left(3)).isEmpty());
        QCOMPARE(send(d, req.mid(3), 500).size(), 1); // the rest, right after
        QCOMPARE(send(d, req + req).size(), 2);       // two in one chunk
        QVERIFY(send(d, req.left(5)).isEmpty());
        // A long silence: the half frame is dropped, the next whole one is answered.
        QCOMPARE(send(d, req, 100000).size(), 1);
    }

    void monitorFollowsTheMotor()
    {
        SimServoModbusDrive d(modbusConfig(1));
        d.motor().enable();
        d.motor().setPosition(-70000);
        d.setAlarm(0);
        d.advanceTo(1000);
        // DP-PoS / DP-PoS.: binary words of -70000 = 0xFFFEEE90.
        QCOMPARE(d.monitorRegister(0x01), quint16(0xEE90));
        QCOMPARE(d.monitorRegister(0x02), quint16(0xFFFE));
        d.setAlarm(12);
        QCOMPARE(d.monitorRegister(0x13), quint16(12));
        const auto r = send(d, adu("010300130001"));
        QCOMPARE(r, QList<QByteArray>{adu("010302000c")});
    }

    void demoRunsOnlyWithThePowerStageOn()
    {
        // The demo profile runs only while SON is on; off, the shaft coasts to rest and the
        // monitor says so (DP-SPd 0, DP-oUt "servo ready" clear), also after the alarm.
        SimServoModbusDrive::Config c = modbusConfig(1);
        c.demoMotion = true;
        SimServoModbusDrive d(c);
        d.advanceTo(1000000); // 1 s into the forward phase
        QVERIFY(qint16(d.monitorRegister(0x00)) > 500);
        QCOMPARE(d.monitorRegister(0x10) & 0x01, 0x01);
        d.setServoOnInput(false);
        d.advanceTo(2900000);
        QCOMPARE(d.monitorRegister(0x00), quint16(0));
        QCOMPARE(d.monitorRegister(0x10) & 0x01, 0);
        QVERIFY(!d.motor().isMoving());
        d.setServoOnInput(true);
        d.advanceTo(9000000); // forward again
        QVERIFY(qint16(d.monitorRegister(0x00)) > 500);
        d.setAlarm(7);
        d.advanceTo(10000000);
        QCOMPARE(d.monitorRegister(0x00), quint16(0));
        QCOMPARE(d.monitorRegister(0x10) & 0x01, 0);
    }

    void stateRoundTrip()
    {
        SimServoModbusDrive a(modbusConfig(6));
        a.setParameter(33, 3333);
        send(a, adu("0610003a0001020001")); // EE-Set
        a.setParameter(33, 4444);
        a.setAlarm(5);
        const QJsonObject state = a.saveState();
        const QByteArray json = QJsonDocument(state).toJson();

        SimServoModbusDrive b(modbusConfig(1));
        QString error;
        QVERIFY2(b.loadState(QJsonDocument::fromJson(json).object(), &error), qPrintable(error));
        QCOMPARE(b.address(), 6);
        QCOMPARE(b.parameter(33), quint16(4444));
        QCOMPARE(b.eepromParameter(33), quint16(3333));
        QCOMPARE(b.alarm(), 5);
        QJsonObject broken = state;
        broken.insert(QStringLiteral("eeprom"), QJsonArray{1, 2, 3});
        QVERIFY(!b.loadState(broken, &error));
        QVERIFY(error.contains(QLatin1String("eeprom")));
    }
};

QTEST_GUILESS_MAIN(TestSimServoModbusDrive)
#include "tst_simservomodbusdrive.moc"
