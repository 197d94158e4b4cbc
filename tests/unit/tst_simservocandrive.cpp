// SimServoCanDrive on its own (no bus, no clock): frames in, frames out, at chosen times.
#include <QtTest>

#include "core/protocol/servocan/servocan.h"
#include "sim/servocan/simservocandrive.h"

using namespace dd;
namespace sc = dd::servocan;

Q_DECLARE_METATYPE(dd::CanFrameData)

namespace {

constexpr qint64 kMs = 1000;

// Runs the drive from `from` to `to` (µs) the way SimCanBus does: advanceTo + tick every 5 ms.
QList<CanFrameData> run(SimServoCanDrive &d, qint64 from, qint64 to)
{
    QList<CanFrameData> out;
    for (qint64 t = from; t <= to; t += 5 * kMs) {
        d.advanceTo(t);
        out += d.tick(t);
    }
    return out;
}

QList<CanFrameData> feed(SimServoCanDrive &d, const CanFrameData &f, qint64 at)
{
    d.advanceTo(at);
    return d.onCanFrame(f, at);
}

int countCommand(const QList<CanFrameData> &frames, sc::Command c)
{
    int n = 0;
    for (const CanFrameData &f : frames)
        n += (f.data.size() == 8 && quint8(f.data.at(1)) == quint8(c)) ? 1 : 0;
    return n;
}

} // namespace

class TestSimServoCanDrive : public QObject
{
    Q_OBJECT

private slots:
    void defaults();
    void parameterReadAndWrite();
    void everyReadTypeIsAnswered();
    void framesForOthersAreIgnored();
    void reservedByteMustBe0xFF();
    void heartbeatEvery30ms();
    void noHeartbeatWithoutCanMode();
    void alarmFramesOnChangeAndEvery2s();
    void jogAndStop();
    void positioningNeedsSpeed();
    void stopAndDisable();
    void motionIgnoredOutsideCanMode();
    void watchdogStopsMotion();
    void keepAliveKeepsItRunning();
    void stateRoundTrip();
    void stateRejectsBadInput();
};

void TestSimServoCanDrive::defaults()
{
    const SimServoCanDrive::Parameters p = SimServoCanDrive::defaultParameters(5);
    QCOMPARE(p[4], qint16(8));
    QCOMPARE(p[74], qint16(1));
    QCOMPARE(p[75], qint16(5));
    QSet<qint16> distinct(p.begin(), p.end());
    QVERIFY(distinct.size() > 200); // a shifted backup shows
    QVERIFY(std::any_of(p.begin(), p.end(), [](qint16 v) { return v < 0; }));
    SimServoCanDrive d(5);
    QCOMPARE(d.station(), 5);
    QCOMPARE(d.describe(), QStringLiteral("servo-can station 5"));
}

void TestSimServoCanDrive::parameterReadAndWrite()
{
    SimServoCanDrive d(0);
    // The seed's station-0 ID 0x064.
    QCOMPARE(feed(d, sc::readParameter(0, 75), 0),
             QList<CanFrameData>({{0x64, QByteArray::fromHex("0012FA4B000000FF"), false}}));
    QVERIFY(feed(d, sc::writeParameter(0, 10, -300), 1 * kMs).isEmpty()); // writes are not answered
    QCOMPARE(feed(d, sc::readParameter(0, 10), 2 * kMs),
             QList<CanFrameData>({{0x64, QByteArray::fromHex("0012FA0A00D4FEFF"), false}}));
    // P75 outside 0..99 is refused; the station changes only after a restart.
    feed(d, sc::writeParameter(0, 75, 100), 3 * kMs);
    QCOMPARE(d.parameter(75), qint16(0));
    QCOMPARE(d.stats().writesRefused, 1u);
    feed(d, sc::writeParameter(0, 75, 9), 4 * kMs);
    QCOMPARE(d.parameter(75), qint16(9));
    QCOMPARE(d.station(), 0);
    QVERIFY(!feed(d, sc::readParameter(0, 1), 5 * kMs).isEmpty());
    d.restart();
    QCOMPARE(d.station(), 9);
    QVERIFY(feed(d, sc::readParameter(0, 1), 6 * kMs).isEmpty());
    QCOMPARE(feed(d, sc::readParameter(9, 1), 7 * kMs).size(), 1);
    // Write protection (fault injection).
    d.setWriteProtected(20, true);
    const qint16 before = d.parameter(20);
    feed(d, sc::writeParameter(9, 20, 1), 8 * kMs);
    QCOMPARE(d.parameter(20), before);
}

void TestSimServoCanDrive::everyReadTypeIsAnswered()
{
    SimServoCanDrive d(2);
    d.setInputs(0x15);
    for (sc::ReadType t : sc::allReadTypes()) {
        const QList<CanFrameData> out = feed(d, sc::read(2, t), 10 * kMs);
        QCOMPARE(out.size(), 1);
        const Decoded<sc::Message> m = sc::decode(out.first());
        QVERIFY(m.ok());
        QVERIFY(sc::isReplyTo(*m.value, 2, t, 0));
    }
    auto value = [&d](sc::ReadType t) { return sc::decode(feed(d, sc::read(2, t), 20 * kMs).first()).value->value; };
    QCOMPARE(value(sc::ReadType::InputIo), 0x15);
    QVERIFY(qAbs(value(sc::ReadType::BusVoltage) - 310) < 10);
    QVERIFY(qAbs(value(sc::ReadType::Temperature) - 25) < 5);
    QCOMPARE(value(sc::ReadType::AlarmCode), 0);
    QCOMPARE(value(sc::ReadType::OutputIo), 1 | 8); // ready, in position, not enabled
}

void TestSimServoCanDrive::framesForOthersAreIgnored()
{
    SimServoCanDrive d(2);
    QVERIFY(feed(d, sc::readParameter(3, 1), 0).isEmpty());                               // another station
    QVERIFY(feed(d, {0x66, QByteArray::fromHex("0212FA01"), false}, 0).isEmpty());        // DLC 4
    QVERIFY(feed(d, {0x66, QByteArray::fromHex("0212FA01000000FF"), true}, 0).isEmpty()); // extended
    QVERIFY(feed(d, sc::heartbeat(2, 0x88, 0), 0).isEmpty());                             // drive -> host
    QCOMPARE(d.stats().readsAnswered, 0u);
}

// DATE[7] "预留的通讯数据软件校验值，目前需固定的填入 0xff": a frame whose b7 is not 0xFF is
// not taken (it used to be read, written and run like any other).
void TestSimServoCanDrive::reservedByteMustBe0xFF()
{
    SimServoCanDrive d(0);
    QVERIFY(feed(d, {0x64, QByteArray::fromHex("0012FA4B00000000"), false}, 0).isEmpty());       // read P75, b7 = 0
    QVERIFY(feed(d, {0x64, QByteArray::fromHex("0015010A00D4FE00"), false}, 1 * kMs).isEmpty()); // P10 = -300
    QCOMPARE(feed(d, {0x64, QByteArray::fromHex("0012FA0A000000FF"), false}, 2 * kMs),
             QList<CanFrameData>({{0x64, QByteArray::fromHex("0012FA0A0095FDFF"), false}})); // P10 kept its -619
    // The seed's speed-mode example (+100) with b7 = 0x00: no motion.
    feed(d, {0x64, QByteArray::fromHex("0020006400000000"), false}, 3 * kMs);
    run(d, 3 * kMs, 200 * kMs);
    QVERIFY(!d.motor().isEnabled());
    QCOMPARE(d.motor().speed(), 0.0);
    QCOMPARE(d.stats().readsAnswered, 1u);
}

void TestSimServoCanDrive::heartbeatEvery30ms()
{
    SimServoCanDrive d(4);
    const QList<CanFrameData> out = run(d, 0, 300 * kMs);
    QCOMPARE(countCommand(out, sc::Command::Heartbeat), 11); // 0, 30, ..., 300 ms
    QCOMPARE(out.first(), sc::heartbeat(4, 0x88, 0));
}

void TestSimServoCanDrive::noHeartbeatWithoutCanMode()
{
    SimServoCanDrive d(4);
    d.setParameter(74, 0);
    QCOMPARE(countCommand(run(d, 0, 300 * kMs), sc::Command::Heartbeat), 0);
    // Reads still work, so a host can set P74 back.
    QCOMPARE(feed(d, sc::readParameter(4, 74), 310 * kMs).size(), 1);
}

void TestSimServoCanDrive::alarmFramesOnChangeAndEvery2s()
{
    SimServoCanDrive d(1);
    QCOMPARE(countCommand(run(d, 0, 100 * kMs), sc::Command::Alarm), 0);
    d.injectAlarm(0x123);
    QList<CanFrameData> out = run(d, 105 * kMs, 105 * kMs);
    QCOMPARE(out.first(), sc::alarm(1, 0x123)); // at once, before the heartbeat
    QCOMPARE(out.first().data, QByteArray::fromHex("01052301000000FF"));
    out = run(d, 110 * kMs, 4200 * kMs); // repeats at 2105 and 4105 ms
    QCOMPARE(countCommand(out, sc::Command::Alarm), 2);
    QCOMPARE(feed(d, sc::clearAlarm(1), 4210 * kMs).size(), 0);
    out = run(d, 4215 * kMs, 9000 * kMs);
    QCOMPARE(countCommand(out, sc::Command::Alarm), 1); // the change to 0, then silence
    QVERIFY(out.contains(sc::alarm(1, 0)));
}

void TestSimServoCanDrive::jogAndStop()
{
    SimServoCanDrive d(1);
    feed(d, sc::keepAlive(1), 0);
    feed(d, sc::runSpeed(1, 600), 1 * kMs); // enables
    QList<CanFrameData> out = run(d, 5 * kMs, 500 * kMs);
    QVERIFY(d.motor().isEnabled());
    QCOMPARE(qRound(d.motor().speedRpm()), 600);
    QCOMPARE(out.last().data.left(3), QByteArray::fromHex("011000")); // heartbeat: running
    QVERIFY(sc::decode(out.last()).value->value > 0);                 // position advancing
    auto value = [&d](sc::ReadType t, qint64 at) {
        return sc::decode(feed(d, sc::read(1, t), at).first()).value->value;
    };
    QCOMPARE(value(sc::ReadType::Speed, 500 * kMs), 600);
    QCOMPARE(value(sc::ReadType::SpeedCommand, 500 * kMs), 600);
    QVERIFY(value(sc::ReadType::OutputCurrent, 500 * kMs) != 0);
    feed(d, sc::stop(1), 510 * kMs);
    run(d, 515 * kMs, 1000 * kMs);
    QVERIFY(!d.motor().isMoving());
    QVERIFY(d.motor().isEnabled()); // 0x26 holds the shaft
    out = run(d, 1005 * kMs, 1040 * kMs);
    QCOMPARE(out.last().data.at(2), char(0x88));
}

void TestSimServoCanDrive::positioningNeedsSpeed()
{
    SimServoCanDrive d(1);
    feed(d, sc::moveRelative(1, 1000), 0);
    run(d, 5 * kMs, 300 * kMs);
    QVERIFY(d.motor().isEnabled());    // enabled ...
    QCOMPARE(d.motor().position(), 0); // ... but positioning speed 0: no motion (seed)
    feed(d, sc::positioningSpeed(1, 200), 305 * kMs);
    feed(d, sc::moveRelative(1, 1000), 306 * kMs);
    run(d, 310 * kMs, 2000 * kMs);
    QCOMPARE(d.motor().position(), 1000);
    feed(d, sc::moveAbsolute(1, -500), 2005 * kMs);
    run(d, 2010 * kMs, 4000 * kMs);
    QCOMPARE(d.motor().position(), -500);
    feed(d, sc::setPosition(1, 7), 4005 * kMs);
    QCOMPARE(sc::decode(feed(d, sc::read(1, sc::ReadType::Position), 4010 * kMs).first()).value->value, 7);
}

void TestSimServoCanDrive::stopAndDisable()
{
    SimServoCanDrive d(1);
    feed(d, sc::runSpeed(1, 1000), 0);
    run(d, 5 * kMs, 300 * kMs);
    feed(d, sc::stopAndDisable(1), 305 * kMs);
    QVERIFY(d.motor().isEnabled()); // decelerating first
    run(d, 310 * kMs, 1000 * kMs);
    QVERIFY(!d.motor().isMoving());
    QVERIFY(!d.motor().isEnabled());
    feed(d, sc::enable(1, true), 1005 * kMs);
    QVERIFY(d.motor().isEnabled());
    feed(d, sc::enable(1, false), 1010 * kMs);
    QVERIFY(!d.motor().isEnabled());
}

void TestSimServoCanDrive::motionIgnoredOutsideCanMode()
{
    SimServoCanDrive d(1);
    d.setParameter(4, 0);
    feed(d, sc::runSpeed(1, 100), 0);
    run(d, 5 * kMs, 200 * kMs);
    QVERIFY(!d.motor().isMoving());
    QVERIFY(!d.motor().isEnabled());
    QCOMPARE(d.stats().commandsIgnored, 1u);
}

void TestSimServoCanDrive::watchdogStopsMotion()
{
    SimServoCanDrive d(1);
    feed(d, sc::keepAlive(1), 0);
    feed(d, sc::runSpeed(1, 300), 1 * kMs);
    run(d, 5 * kMs, 1995 * kMs);
    QVERIFY(d.motor().isMoving());
    QVERIFY(d.isHostOnline());
    QCOMPARE(d.stats().watchdogTrips, 0u);
    run(d, 2000 * kMs, 2000 * kMs); // 2 s after the keep-alive
    QCOMPARE(d.stats().watchdogTrips, 1u);
    QVERIFY(!d.isHostOnline());
    run(d, 2005 * kMs, 2500 * kMs);
    QVERIFY(!d.motor().isMoving());
    QVERIFY(d.motor().isEnabled()); // holds the shaft
    // A host without keep-alive: a motion command arms the watchdog for 2 s.
    feed(d, sc::runSpeed(1, 300), 3000 * kMs);
    run(d, 3005 * kMs, 4990 * kMs);
    QVERIFY(d.motor().isMoving());
    run(d, 4995 * kMs, 5500 * kMs);
    QVERIFY(!d.motor().isMoving());
    QCOMPARE(d.stats().watchdogTrips, 2u);
}

void TestSimServoCanDrive::keepAliveKeepsItRunning()
{
    SimServoCanDrive d(1);
    feed(d, sc::runSpeed(1, 300), 0);
    for (qint64 t = 0; t <= 6000 * kMs; t += 100 * kMs) {
        feed(d, sc::keepAlive(1), t);
        run(d, t + 5 * kMs, t + 95 * kMs);
    }
    QVERIFY(d.motor().isMoving());
    QCOMPARE(d.stats().watchdogTrips, 0u);
    QCOMPARE(d.stats().keepAlives, 61u);
}

void TestSimServoCanDrive::stateRoundTrip()
{
    SimServoCanDrive a(6);
    a.setParameter(0, -32768);
    a.setParameter(219, 32767);
    a.motor().setPosition(-123456);
    a.injectAlarm(9);
    const QJsonObject state = a.saveState();
    QCOMPARE(state.value(QStringLiteral("family")).toString(), QStringLiteral("servo-can"));
    SimServoCanDrive b(1);
    QString why;
    QVERIFY2(b.loadState(state, &why), qPrintable(why));
    QCOMPARE(b.station(), 6);
    QCOMPARE(b.parameters(), a.parameters());
    QCOMPARE(b.motor().position(), -123456);
    QCOMPARE(b.alarmCode(), 9);
}

void TestSimServoCanDrive::stateRejectsBadInput()
{
    SimServoCanDrive d(1);
    const SimServoCanDrive::Parameters before = d.parameters();
    QJsonObject s = d.saveState();
    QJsonArray params = s.value(QStringLiteral("parameters")).toArray();
    QString why;

    QJsonObject bad = s;
    bad.insert(QStringLiteral("family"), QStringLiteral("shuoke"));
    QVERIFY(!d.loadState(bad, &why));
    QVERIFY(why.contains(QStringLiteral("shuoke")));

    bad = s;
    params.removeLast();
    bad.insert(QStringLiteral("parameters"), params);
    QVERIFY(!d.loadState(bad, &why));

    bad = s;
    params = s.value(QStringLiteral("parameters")).toArray();
    params[3] = 40000;
    bad.insert(QStringLiteral("parameters"), params);
    QVERIFY(!d.loadState(bad, &why));
    QVERIFY(why.contains(QStringLiteral("parameter 3")));

    bad = s;
    bad.insert(QStringLiteral("station"), 100);
    QVERIFY(!d.loadState(bad, &why));

    QCOMPARE(d.parameters(), before); // nothing changed
    QCOMPARE(d.station(), 1);
}

QTEST_APPLESS_MAIN(TestSimServoCanDrive)
#include "tst_simservocandrive.moc"
