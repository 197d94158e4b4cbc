#include <QtTest>

#include "core/protocol/servocan/servocan.h"

#include <limits>
#include <set>

using namespace dd;
namespace sc = dd::servocan;

Q_DECLARE_METATYPE(dd::CanFrameData)

namespace {

CanFrameData raw(quint32 id, const char *hex, bool extended = false)
{
    CanFrameData f;
    f.id = id;
    f.data = QByteArray::fromHex(hex);
    f.extended = extended;
    return f;
}

constexpr qint32 kMin32 = std::numeric_limits<qint32>::min();
constexpr qint32 kMax32 = std::numeric_limits<qint32>::max();
constexpr qint16 kMin16 = std::numeric_limits<qint16>::min();
constexpr qint16 kMax16 = std::numeric_limits<qint16>::max();

} // namespace

class TestServoCanCodec : public QObject
{
    Q_OBJECT
private slots:
    // ---- Encoding, byte-exact -------------------------------------------------------------
    void seedExamples_data()
    {
        QTest::addColumn<CanFrameData>("frame");
        QTest::addColumn<QByteArray>("expected");
        // Station 0, ID 0x064 (docs/protocols/servo-can.md, seed examples).
        QTest::newRow("keep-alive") << sc::keepAlive(0) << QByteArray::fromHex("00080000000000ff");
        QTest::newRow("enable on") << sc::enable(0, true) << QByteArray::fromHex("00250100000000ff");
        QTest::newRow("speed +100") << sc::runSpeed(0, 100) << QByteArray::fromHex("00200064000000ff");
        QTest::newRow("positioning speed 200")
            << sc::positioningSpeed(0, 200) << QByteArray::fromHex("002300c8000000ff");
        QTest::newRow("relative +1000") << sc::moveRelative(0, 1000) << QByteArray::fromHex("002100e8030000ff");
        // The seed shows C8 03 (= 968) for target 1000: a typo, 1000 is E8 03.
        QTest::newRow("absolute 1000") << sc::moveAbsolute(0, 1000) << QByteArray::fromHex("002200e8030000ff");
    }
    void seedExamples()
    {
        QFETCH(CanFrameData, frame);
        QFETCH(QByteArray, expected);
        QCOMPARE(frame.id, 0x064u);
        QVERIFY(!frame.extended);
        QCOMPARE(frame.data.toHex(' '), expected.toHex(' '));
    }

    void encodings_data()
    {
        QTest::addColumn<CanFrameData>("frame");
        QTest::addColumn<quint32>("id");
        QTest::addColumn<QByteArray>("expected");
        auto row = [](const char *name, const CanFrameData &f, quint32 id, const char *hex) {
            QTest::newRow(name) << f << id << QByteArray::fromHex(hex);
        };
        // host -> drive, station 5 (ID 0x69)
        row("keep-alive", sc::keepAlive(5), 0x69, "05080000000000ff");
        row("read parameter 75", sc::readParameter(5, 75), 0x69, "0512fa4b000000ff");
        row("read parameter 0", sc::readParameter(5, 0), 0x69, "0512fa00000000ff");
        row("read parameter 219", sc::readParameter(5, 219), 0x69, "0512fadb000000ff");
        row("read speed", sc::read(5, sc::ReadType::Speed), 0x69, "0512fc00000000ff");
        row("write P74=1", sc::writeParameter(5, 74, 1), 0x69, "0515014a000100ff");
        row("write P4=8", sc::writeParameter(5, 4, 8), 0x69, "05150104000800ff");
        row("write P219=-1", sc::writeParameter(5, 219, -1), 0x69, "051501db00ffffff");
        row("write int16 min", sc::writeParameter(5, 10, kMin16), 0x69, "0515010a000080ff");
        row("write int16 max", sc::writeParameter(5, 10, kMax16), 0x69, "0515010a00ff7fff");
        row("write 0x1234", sc::writeParameter(5, 1, 0x1234), 0x69, "05150101003412ff");
        row("run speed -100", sc::runSpeed(5, -100), 0x69, "0520009cffffffff");
        row("run speed 0", sc::runSpeed(5, 0), 0x69, "05200000000000ff");
        row("relative int32 min", sc::moveRelative(5, kMin32), 0x69, "05210000000080ff");
        row("relative -1000", sc::moveRelative(5, -1000), 0x69, "05210018fcffffff");
        row("absolute int32 max", sc::moveAbsolute(5, kMax32), 0x69, "052200ffffff7fff");
        row("absolute 0x12345678", sc::moveAbsolute(5, 0x12345678), 0x69, "05220078563412ff");
        row("positioning speed 3000", sc::positioningSpeed(5, 3000), 0x69, "052300b80b0000ff");
        row("enable off", sc::enable(5, false), 0x69, "05250000000000ff");
        row("enable on", sc::enable(5, true), 0x69, "05250100000000ff");
        row("stop", sc::stop(5), 0x69, "05260000000000ff");
        row("stop and disable", sc::stopAndDisable(5), 0x69, "05280000000000ff");
        row("set position -1", sc::setPosition(5, -1), 0x69, "055000ffffffffff");
        row("set position 0", sc::setPosition(5, 0), 0x69, "05500000000000ff");
        row("clear alarm", sc::clearAlarm(5), 0x69, "05810000000000ff");
        // station extremes
        row("station 0", sc::stop(0), 0x64, "00260000000000ff");
        row("station 99", sc::stop(99), 0xC7, "63260000000000ff");
        row("station 1 (seed: ID 0x65)", sc::keepAlive(1), 0x65, "01080000000000ff");
        // drive -> host
        row("heartbeat idle", sc::heartbeat(5, 0x88, 0), 0x69, "05108800000000ff");
        row("heartbeat running -123456", sc::heartbeat(5, 0x00, -123456), 0x69, "051000c01dfeffff");
        row("heartbeat other state max", sc::heartbeat(5, 0x01, kMax32), 0x69, "051001ffffff7fff");
        row("alarm 0x1234", sc::alarm(5, 0x1234), 0x69, "05053412000000ff");
        row("alarm cleared", sc::alarm(5, 0), 0x69, "05050000000000ff");
        row("alarm 0xFFFF", sc::alarm(5, 0xFFFF), 0x69, "0505ffff000000ff");
        row("reply P75=5", sc::readReplyParameter(5, 75, 5), 0x69, "0512fa4b000500ff");
        row("reply P3=int16 min", sc::readReplyParameter(5, 3, kMin16), 0x69, "0512fa03000080ff");
        row("reply current 12.34 A", sc::readReply(5, sc::ReadType::OutputCurrent, 1234), 0x69, "0512a4d2040000ff");
        row("reply speed -3000", sc::readReply(5, sc::ReadType::Speed, -3000), 0x69, "0512fc48f4ffffff");
        row("reply position int32 min", sc::readReply(5, sc::ReadType::Position, kMin32), 0x69, "0512fd00000080ff");
        row("generic frame", sc::frame(7, sc::Command::Heartbeat, 0x42, 0x01020304), 0x6B, "07104204030201ff");
    }
    void encodings()
    {
        QFETCH(CanFrameData, frame);
        QFETCH(quint32, id);
        QFETCH(QByteArray, expected);
        QCOMPARE(frame.id, id);
        QVERIFY(!frame.extended);
        QCOMPARE(frame.data.size(), 8);
        QCOMPARE(frame.data.toHex(' '), expected.toHex(' '));
    }

    void readRequests_data()
    {
        QTest::addColumn<int>("type");
        for (sc::ReadType t : sc::allReadTypes())
            QTest::newRow(sc::readTypeInfo(t).key) << int(t);
    }
    void readRequests()
    {
        QFETCH(int, type);
        const auto t = static_cast<sc::ReadType>(type);
        const CanFrameData f = sc::read(42, t);
        QCOMPARE(f.id, 0x64u + 42);
        QByteArray expected = QByteArray::fromHex("2a120000000000ff");
        expected[2] = static_cast<char>(type);
        QCOMPARE(f.data.toHex(' '), expected.toHex(' '));
    }

    // ---- Round trips ----------------------------------------------------------------------
    void roundTrip_data()
    {
        QTest::addColumn<CanFrameData>("frame");
        QTest::addColumn<int>("station");
        QTest::addColumn<int>("command");
        QTest::addColumn<int>("b2");
        QTest::addColumn<int>("paramIndex");
        QTest::addColumn<int>("paramValue");
        QTest::addColumn<qint32>("value");
        auto row = [](const QByteArray &name, const CanFrameData &f, int st, sc::Command c, int b2, int idx, int pv,
                      qint32 v) { QTest::newRow(name.constData()) << f << st << int(c) << b2 << idx << pv << v; };
        using C = sc::Command;
        row("keep-alive", sc::keepAlive(3), 3, C::KeepAlive, 0, 0, 0, 0);
        row("read parameter", sc::readParameter(3, 200), 3, C::Read, 0xFA, 200, 0, 200);
        row("write parameter -2", sc::writeParameter(99, 219, -2), 99, C::Write, 0x01, 219, -2, qint32(0xFFFE00DB));
        row("write int16 max", sc::writeParameter(0, 0, kMax16), 0, C::Write, 0x01, 0, kMax16, qint32(0x7FFF0000));
        row("run speed int32 min", sc::runSpeed(3, kMin32), 3, C::RunSpeed, 0, 0, 0, kMin32);
        row("run speed int32 max", sc::runSpeed(3, kMax32), 3, C::RunSpeed, 0, 0, 0, kMax32);
        row("move relative -1", sc::moveRelative(3, -1), 3, C::MoveRelative, 0, 0, 0, -1);
        row("move absolute 1000", sc::moveAbsolute(3, 1000), 3, C::MoveAbsolute, 0, 0, 0, 1000);
        row("positioning speed 200", sc::positioningSpeed(3, 200), 3, C::PositioningSpeed, 0, 0, 0, 200);
        row("enable on", sc::enable(3, true), 3, C::Enable, 1, 0, 0, 0);
        row("enable off", sc::enable(3, false), 3, C::Enable, 0, 0, 0, 0);
        row("stop", sc::stop(3), 3, C::Stop, 0, 0, 0, 0);
        row("stop and disable", sc::stopAndDisable(3), 3, C::StopAndDisable, 0, 0, 0, 0);
        row("set position int32 min", sc::setPosition(3, kMin32), 3, C::SetPosition, 0, 0, 0, kMin32);
        row("clear alarm", sc::clearAlarm(3), 3, C::ClearAlarm, 0, 0, 0, 0);
        row("heartbeat idle", sc::heartbeat(3, 0x88, -5), 3, C::Heartbeat, 0x88, 0, 0, -5);
        row("heartbeat running", sc::heartbeat(3, 0x00, kMax32), 3, C::Heartbeat, 0x00, 0, 0, kMax32);
        row("alarm 0xBEEF", sc::alarm(3, 0xBEEF), 3, C::Alarm, 0xEF, 0, 0, 0xBE);
        row("reply parameter int16 min", sc::readReplyParameter(3, 219, kMin16), 3, C::Read, 0xFA, 219, kMin16,
            qint32(0x800000DB));
        for (sc::ReadType t : sc::allReadTypes()) {
            const QByteArray key = sc::readTypeInfo(t).key;
            row("read request " + key, sc::read(3, t), 3, C::Read, int(t), 0, 0, 0);
            if (t == sc::ReadType::Parameter)
                continue;
            row("reply " + key + " -7", sc::readReply(3, t, -7), 3, C::Read, int(t), 0, 0, -7);
            row("reply " + key + " int32 min", sc::readReply(3, t, kMin32), 3, C::Read, int(t), 0, 0, kMin32);
            row("reply " + key + " int32 max", sc::readReply(3, t, kMax32), 3, C::Read, int(t), 0, 0, kMax32);
        }
    }
    void roundTrip()
    {
        QFETCH(CanFrameData, frame);
        QFETCH(int, station);
        QFETCH(int, command);
        QFETCH(int, b2);
        QFETCH(int, paramIndex);
        QFETCH(int, paramValue);
        QFETCH(qint32, value);
        const Decoded<sc::Message> d = sc::decode(frame);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QVERIFY(d.error.isEmpty());
        const sc::Message &m = *d.value;
        QCOMPARE(int(m.station), station);
        QCOMPARE(int(m.command), command);
        QCOMPARE(int(m.b2), b2);
        QCOMPARE(int(m.paramIndex), paramIndex);
        QCOMPARE(int(m.paramValue), paramValue);
        QCOMPARE(m.value, value);
        QVERIFY(m.reservedByteOk);
        QCOMPARE(QByteArray(reinterpret_cast<const char *>(m.raw.data()), 8).toHex(' '), frame.data.toHex(' '));
        // Re-encoding the decoded fields gives the same bytes.
        if (m.isParameterFrame()) {
            const CanFrameData again = m.command == sc::Command::Write
                ? sc::writeParameter(m.station, m.paramIndex, m.paramValue)
                : sc::readReplyParameter(m.station, m.paramIndex, m.paramValue);
            QCOMPARE(again, frame);
        } else if (m.command == sc::Command::Alarm) {
            QCOMPARE(sc::alarm(m.station, m.alarmCode()), frame);
        } else {
            QCOMPARE(sc::frame(m.station, m.command, m.b2, m.value), frame);
        }
    }

    void messageAccessors()
    {
        const sc::Message a = *sc::decode(sc::alarm(1, 0x0102)).value;
        QCOMPARE(a.alarmCode(), quint16(0x0102));
        QCOMPARE(sc::decode(sc::alarm(1, 0)).value->alarmCode(), quint16(0));
        QVERIFY(sc::decode(sc::enable(1, true)).value->enableOn());
        QVERIFY(!sc::decode(sc::enable(1, false)).value->enableOn());
        // "non-zero = on": any non-zero b2 enables
        QVERIFY(sc::decode(raw(0x65, "0125ff00000000ff")).value->enableOn());
        QVERIFY(sc::decode(sc::heartbeat(1, 0x88, 0)).value->heartbeatIdle());
        QVERIFY(!sc::decode(sc::heartbeat(1, 0x00, 0)).value->heartbeatIdle());
        QCOMPARE(sc::decode(sc::read(1, sc::ReadType::BusVoltage)).value->readType(),
                 std::optional<sc::ReadType>(sc::ReadType::BusVoltage));
        QVERIFY(!sc::decode(sc::heartbeat(1, 0xFA, 0)).value->readType().has_value());
        QVERIFY(!sc::decode(sc::heartbeat(1, 0xFA, 0)).value->isParameterFrame());
        QVERIFY(!sc::decode(sc::read(1, sc::ReadType::Speed)).value->isParameterFrame());
        // Not a parameter frame: paramIndex / paramValue stay 0 although b3..b6 are set.
        const sc::Message s = *sc::decode(sc::readReply(1, sc::ReadType::Speed, 0x7FFF0012)).value;
        QCOMPARE(int(s.paramIndex), 0);
        QCOMPARE(int(s.paramValue), 0);
    }

    // ---- Lenient decoding ------------------------------------------------------------------
    void reservedByte_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<bool>("flag");
        QTest::newRow("0xFF") << QByteArray::fromHex("00100012345678ff") << true;
        QTest::newRow("0x00") << QByteArray::fromHex("0010001234567800") << false;
        QTest::newRow("0xFE") << QByteArray::fromHex("00100012345678fe") << false;
    }
    void reservedByte()
    {
        QFETCH(QByteArray, data);
        QFETCH(bool, flag);
        CanFrameData f;
        f.id = 0x64;
        f.data = data;
        const auto d = sc::decode(f);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(d.value->reservedByteOk, flag);
        QCOMPARE(d.value->value, qint32(0x78563412));
        QCOMPARE(int(d.value->raw[7]), int(quint8(data[7])));
    }
    void parameterB4Ignored()
    {
        const auto d = sc::decode(raw(0x64, "0012fa0a01fbffff"));
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(int(d.value->paramIndex), 10);
        QCOMPARE(int(d.value->paramValue), -5);
    }
    void boundariesAccepted_data()
    {
        QTest::addColumn<CanFrameData>("frame");
        QTest::newRow("ID 0x64 station 0") << raw(0x64, "00260000000000ff");
        QTest::newRow("ID 0xC7 station 99") << raw(0xC7, "63260000000000ff");
        QTest::newRow("read index 219") << raw(0x64, "0012fadb000000ff");
        QTest::newRow("write index 219") << raw(0x64, "001501db000000ff");
        QTest::newRow("read type 0xA0") << raw(0x64, "0012a000000000ff");
        QTest::newRow("read type 0xAB") << raw(0x64, "0012ab00000000ff");
    }
    void boundariesAccepted()
    {
        QFETCH(CanFrameData, frame);
        const auto d = sc::decode(frame);
        QVERIFY2(d.ok(), qPrintable(d.error));
    }

    // ---- Rejections ------------------------------------------------------------------------
    void rejections_data()
    {
        QTest::addColumn<CanFrameData>("frame");
        QTest::addColumn<QString>("reason");
        QTest::newRow("extended ID") << raw(0x64, "00080000000000ff", true) << "extended";
        QTest::newRow("extended ID in range") << raw(0x65, "01080000000000ff", true) << "extended";
        QTest::newRow("ID 0x63") << raw(0x63, "ff080000000000ff") << "outside 0x064..0x0C7";
        QTest::newRow("ID 0xC8") << raw(0xC8, "64080000000000ff") << "outside 0x064..0x0C7";
        QTest::newRow("ID 0x000") << raw(0x000, "00080000000000ff") << "outside 0x064..0x0C7";
        QTest::newRow("ID 0x7FF") << raw(0x7FF, "00080000000000ff") << "outside 0x064..0x0C7";
        QTest::newRow("DLC 7") << raw(0x64, "00080000000000") << "DLC 7";
        QTest::newRow("DLC 0") << raw(0x64, "") << "DLC 0";
        QTest::newRow("DLC 1") << raw(0x64, "00") << "DLC 1";
        QTest::newRow("DLC 9 (CAN FD)") << raw(0x64, "00080000000000ff00") << "DLC 9";
        QTest::newRow("b0 1 on ID 0x64") << raw(0x64, "01080000000000ff") << "does not match";
        QTest::newRow("b0 0 on ID 0xC7") << raw(0xC7, "00080000000000ff") << "does not match";
        QTest::newRow("b0 0x64 on ID 0x64") << raw(0x64, "64080000000000ff") << "does not match";
        QTest::newRow("command 0x00") << raw(0x64, "00000000000000ff") << "unknown command 0x00";
        QTest::newRow("command 0x13") << raw(0x64, "00130000000000ff") << "unknown command 0x13";
        QTest::newRow("command 0xFF") << raw(0x64, "00ff0000000000ff") << "unknown command 0xFF";
        QTest::newRow("command 0x24") << raw(0x64, "00240000000000ff") << "unknown command 0x24";
        QTest::newRow("read type 0x00") << raw(0x64, "00120000000000ff") << "unknown read type 0x00";
        QTest::newRow("read type 0xFB") << raw(0x64, "0012fb00000000ff") << "unknown read type 0xFB";
        QTest::newRow("read type 0xAC") << raw(0x64, "0012ac00000000ff") << "unknown read type 0xAC";
        QTest::newRow("write type 0x00") << raw(0x64, "00150000000000ff") << "reserved write type 0x00";
        QTest::newRow("write type 0x02") << raw(0x64, "0015024a000100ff") << "reserved write type 0x02";
        QTest::newRow("read index 220") << raw(0x64, "0012fadc000000ff") << "parameter index 220";
        QTest::newRow("read index 255") << raw(0x64, "0012faff000000ff") << "parameter index 255";
        QTest::newRow("write index 220") << raw(0x64, "001501dc000100ff") << "parameter index 220";
    }
    void rejections()
    {
        QFETCH(CanFrameData, frame);
        QFETCH(QString, reason);
        const auto d = sc::decode(frame);
        QVERIFY(!d.ok());
        QVERIFY(!d.value.has_value());
        QVERIFY2(d.error.contains(reason), qPrintable(d.error));
    }
    void nonParameterIndexByteUnchecked()
    {
        // b3 = 0xDC (220) is a plain data byte outside parameter frames.
        QVERIFY(sc::decode(raw(0x64, "0012fcdc000000ff")).ok());
        QVERIFY(sc::decode(raw(0x64, "001000dc000000ff")).ok());
    }

    // ---- Reply matching --------------------------------------------------------------------
    void isReplyTo_data()
    {
        QTest::addColumn<CanFrameData>("request");
        QTest::addColumn<CanFrameData>("received");
        QTest::addColumn<bool>("match");
        using T = sc::ReadType;
        QTest::newRow("parameter") << sc::readParameter(4, 75) << sc::readReplyParameter(4, 75, 4) << true;
        QTest::newRow("parameter other index") << sc::readParameter(4, 75) << sc::readReplyParameter(4, 74, 1) << false;
        QTest::newRow("parameter other station")
            << sc::readParameter(4, 75) << sc::readReplyParameter(5, 75, 5) << false;
        QTest::newRow("speed") << sc::read(4, T::Speed) << sc::readReply(4, T::Speed, 1500) << true;
        QTest::newRow("speed, b3 set") << sc::read(4, T::Speed) << sc::readReply(4, T::Speed, 75) << true;
        QTest::newRow("speed vs position") << sc::read(4, T::Speed) << sc::readReply(4, T::Position, 1500) << false;
        QTest::newRow("current other station")
            << sc::read(4, T::OutputCurrent) << sc::readReply(9, T::OutputCurrent, 1) << false;
        QTest::newRow("speed vs parameter") << sc::read(4, T::Speed) << sc::readReplyParameter(4, 0, 0) << false;
        QTest::newRow("heartbeat is no reply") << sc::read(4, T::Position) << sc::heartbeat(4, 0xFD, 0) << false;
        QTest::newRow("alarm is no reply") << sc::read(4, T::AlarmCode) << sc::alarm(4, 0xAA) << false;
        QTest::newRow("request not a read") << sc::heartbeat(4, 0xFC, 0) << sc::readReply(4, T::Speed, 0) << false;
    }
    void isReplyTo()
    {
        QFETCH(CanFrameData, request);
        QFETCH(CanFrameData, received);
        QFETCH(bool, match);
        const auto req = sc::decode(request);
        const auto rec = sc::decode(received);
        QVERIFY(req.ok() && rec.ok());
        QCOMPARE(sc::isReplyTo(*rec.value, *req.value), match);
        if (const auto type = req.value->readType())
            QCOMPARE(sc::isReplyTo(*rec.value, req.value->station, *type, req.value->paramIndex), match);
    }

    // ---- Tables and helpers ----------------------------------------------------------------
    void commandTable()
    {
        QCOMPARE(sc::allCommands().size(), size_t(14));
        const QList<int> bytes = {0x05, 0x08, 0x10, 0x12, 0x15, 0x20, 0x21, 0x22, 0x23, 0x25, 0x26, 0x28, 0x50, 0x81};
        std::set<QString> names;
        for (int b = 0; b < 256; ++b) {
            const auto c = sc::commandFromByte(quint8(b));
            QCOMPARE(c.has_value(), bytes.contains(b));
            if (c) {
                QCOMPARE(int(*c), b);
                QVERIFY(!sc::commandName(*c).isEmpty());
                names.insert(sc::commandName(*c));
            }
        }
        QCOMPARE(names.size(), size_t(14));
        QCOMPARE(sc::commandDirection(sc::Command::Heartbeat), sc::Direction::DriveToHost);
        QCOMPARE(sc::commandDirection(sc::Command::Alarm), sc::Direction::DriveToHost);
        QCOMPARE(sc::commandDirection(sc::Command::Read), sc::Direction::Both);
        QCOMPARE(sc::commandDirection(sc::Command::KeepAlive), sc::Direction::HostToDrive);
        QCOMPARE(sc::commandDirection(sc::Command::ClearAlarm), sc::Direction::HostToDrive);
    }
    void readTypeTable()
    {
        QCOMPARE(sc::allReadTypes().size(), size_t(15));
        std::set<QString> keys;
        for (int b = 0; b < 256; ++b) {
            const auto t = sc::readTypeFromByte(quint8(b));
            const bool known = b == 0xFA || b == 0xFC || b == 0xFD || (b >= 0xA0 && b <= 0xAB);
            QCOMPARE(t.has_value(), known);
            if (!t)
                continue;
            const sc::ReadTypeInfo info = sc::readTypeInfo(*t);
            QCOMPARE(info.type, *t);
            QVERIFY(info.key && *info.key);
            QVERIFY(info.name && *info.name);
            QVERIFY(info.unit);
            keys.insert(QString::fromLatin1(info.key));
            if (*t == sc::ReadType::OutputCurrent) {
                QCOMPARE(info.scale, 0.01);
                QCOMPARE(info.decimals, 2);
            } else {
                QCOMPARE(info.scale, 1.0);
                QCOMPARE(info.decimals, 0);
            }
            QCOMPARE(info.bitField, *t == sc::ReadType::InputIo || *t == sc::ReadType::OutputIo);
        }
        QCOMPARE(keys.size(), size_t(15));
        QCOMPARE(sc::scaledValue(sc::ReadType::OutputCurrent, 1234), 12.34);
        QCOMPARE(sc::scaledValue(sc::ReadType::OutputCurrent, -50), -0.5);
        QCOMPARE(sc::scaledValue(sc::ReadType::BusVoltage, 310), 310.0);
        QCOMPARE(QString::fromUtf8(sc::readTypeInfo(sc::ReadType::Speed).unit), QStringLiteral("r/min"));
    }
    void heartbeatIdle_data()
    {
        QTest::addColumn<int>("state");
        QTest::addColumn<bool>("idle");
        QTest::newRow("0x88 idle") << 0x88 << true;
        QTest::newRow("0x00 running") << 0x00 << false;
        QTest::newRow("0x87 other") << 0x87 << false;
        QTest::newRow("0x08 other") << 0x08 << false;
        QTest::newRow("0xFF other") << 0xFF << false;
    }
    void heartbeatIdle()
    {
        QFETCH(int, state);
        QFETCH(bool, idle);
        QCOMPARE(sc::isHeartbeatIdle(quint8(state)), idle);
    }
    void constantsAndValidation()
    {
        QCOMPARE(sc::kIdBase, 0x64u);
        QCOMPARE(sc::kMaxId, 0xC7u);
        QCOMPARE(sc::kStationCount, 100);
        QCOMPARE(sc::kParameterCount, 220);
        QCOMPARE(sc::kKeepAlivePeriod.count(), 100);
        QCOMPARE(sc::kHeartbeatPeriod.count(), 30);
        QCOMPARE(sc::kWatchdog.count(), 2000);
        QVERIFY(sc::isValidStation(0) && sc::isValidStation(99));
        QVERIFY(!sc::isValidStation(-1) && !sc::isValidStation(100));
        QVERIFY(sc::isValidParameterIndex(0) && sc::isValidParameterIndex(219));
        QVERIFY(!sc::isValidParameterIndex(-1) && !sc::isValidParameterIndex(220));
        QCOMPARE(sc::frameId(1), 0x65u);
    }
};

QTEST_APPLESS_MAIN(TestServoCanCodec)
#include "tst_servocancodec.moc"
