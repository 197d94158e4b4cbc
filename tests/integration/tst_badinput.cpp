// Bad input at the Drive API, the layer every front end (CLI arguments, GUI table cells,
// backup files after loading) goes through: unknown parameters, values outside the
// parameter's range or its register, huge numbers, duplicates, read-only parameters,
// unknown channels, impossible motion values, unknown EE operations. Each must be refused
// with its own typed error and a message that names the culprit, before anything is sent:
// the traffic tap sees no frame and the simulated drives keep every value.
// (Malformed backup and dictionary files are refused before they reach a drive:
// tests/unit/tst_backupfile.cpp badFiles, tst_parameterdictionary.cpp badDictionary.)
#include <QtTest>

#include "core/drive/servocan/servocanbackend.h"
#include "core/drive/servocan/servocandrive.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/drive/servomodbus/servomodbusbackend.h"
#include "core/link/traffictap.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/simserialbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/integration/faultcheck.h"
#include "tests/support/requiretool.h"

#include <limits>
#include <memory>

using namespace dd;
using namespace dd::faultcheck;

namespace {

constexpr qint64 kMax = std::numeric_limits<qint64>::max();
constexpr qint64 kMin = std::numeric_limits<qint64>::min();

struct Case
{
    QString name;
    std::function<DriveReply *(Drive &)> op;
    ErrorCode code;
    QString fragment; // the message names the culprit
};

// Runs every case; returns the first problem ("" when all are refused as expected).
QString runCases(Drive &d, const QList<Case> &cases)
{
    for (const Case &c : cases) {
        DriveReply *r = c.op(d);
        if (!waitFinished(r, 2000))
            return c.name + QStringLiteral(": no answer");
        if (r->error().code != c.code)
            return QStringLiteral("%1: %2 (%3) instead of %4")
                .arg(c.name, errorCodeName(r->error().code), r->error().message, errorCodeName(c.code));
        if (!r->error().message.contains(c.fragment))
            return QStringLiteral("%1: \"%2\" does not name \"%3\"").arg(c.name, r->error().message, c.fragment);
        if (!r->parameters().isEmpty() || !r->writeResults().isEmpty() || !r->samples().isEmpty())
            return c.name + QStringLiteral(": results for a refused request");
        r->deleteLater();
    }
    return {};
}

int txCount(const QList<TrafficRecord> &records)
{
    return int(std::count_if(records.begin(), records.end(),
                             [](const TrafficRecord &r) { return r.direction == TrafficRecord::Direction::Tx; }));
}

} // namespace

class TestBadInput : public QObject
{
    Q_OBJECT

private slots:
    void servoModbus();
    void servoCan();
};

void TestBadInput::servoModbus()
{
    DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this platform");
    auto *pty = new PtyEndpoint;
    QVERIFY(!pty->open().isError());
    SimSerialBus bus(pty);
    SimServoModbusDrive::Config c;
    c.baud = 115200;
    auto *sim = static_cast<SimServoModbusDrive *>(bus.addDevice(std::make_unique<SimServoModbusDrive>(c)));
    const auto before = sim->parameters();
    TrafficTap tap;
    QList<TrafficRecord> records;
    connect(&tap, &TrafficTap::frameRecorded, this, [&](const TrafficRecord &r) { records << r; });
    ServoModbusBackend backend;
    ConnectionSettings cs;
    cs.family = Family::ServoModbus;
    cs.port = pty->clientPath();
    cs.baud = 115200;
    Error e;
    QVERIFY2(backend.open(cs, &tap, &e), qPrintable(e.message));

    auto write = [](QList<ParameterWrite> w) { return [w](Drive &d) { return d.writeParameters(w); }; };
    const QList<Case> cases = {
        {"nothing", write({}), ErrorCode::InvalidArgument, "No parameter"},
        {"index 60", write({{60, 1}}), ErrorCode::InvalidArgument, "PA60"},
        {"index -1", write({{-1, 1}}), ErrorCode::InvalidArgument, "PA-1"},
        {"70000", write({{10, 70000}}), ErrorCode::OutOfRange, "70000"},
        {"int64 max", write({{10, kMax}}), ErrorCode::OutOfRange, QString::number(kMax)},
        {"int64 min", write({{10, kMin}}), ErrorCode::OutOfRange, QString::number(kMin)},
        {"int16 range", write({{11, 40000}}), ErrorCode::OutOfRange, "PA11"},
        {"address range", write({{51, 300}}), ErrorCode::OutOfRange, "PA51"},
        {"read-only", write({{2, 7000}}), ErrorCode::NotSupported, "PA2"},
        {"twice", write({{5, 1}, {5, 2}}), ErrorCode::InvalidArgument, "PA5"},
        {"good then bad", write({{12, 1}, {13, 99999}}), ErrorCode::OutOfRange, "PA13"},
        {"read 60",
         [](Drive &d) {
             return d.readParameters({1, 60});
         },
         ErrorCode::InvalidArgument, "PA60"},
        {"channel",
         [](Drive &d) {
             return d.readChannels({"speed", "warp"});
         },
         ErrorCode::InvalidArgument, "warp"},
        {"ee 9", [](Drive &d) { return d.eeOperation(static_cast<EeOperation>(9)); }, ErrorCode::InvalidArgument, "EE"},
        {"jog", [](Drive &d) { return d.jog(100); }, ErrorCode::NotSupported, "servo-modbus"},
    };
    const QString problem = runCases(*backend.drive(1), cases);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCoreApplication::processEvents();
    QCOMPARE(txCount(records), 0);
    QVERIFY(sim->parameters() == before);
}

void TestBadInput::servoCan()
{
    VirtualCanHub hub;
    QVERIFY(hub.start());
    SimCanBus bus;
    auto *sim = static_cast<SimServoCanDrive *>(bus.addDevice(std::make_unique<SimServoCanDrive>(1)));
    QVERIFY(!bus.open(QStringLiteral("virtualcan"), hub.interfaceName(0)).isError());
    TrafficTap tap;
    QList<TrafficRecord> records;
    ServoCanBackend backend;
    ConnectionSettings cs;
    cs.family = Family::ServoCan;
    cs.can = QStringLiteral("virtualcan:") + hub.interfaceName(0);
    Error e;
    QVERIFY2(backend.open(cs, &tap, &e), qPrintable(e.message));
    QVERIFY(waitUntil([&] { return backend.tracker()->isOnline(1); }, 3000));
    const auto before = sim->parameters();
    // From now on: the keep-alive is expected, nothing else.
    connect(&tap, &TrafficTap::frameRecorded, this, [&](const TrafficRecord &r) {
        if (r.bytes.size() == 8 && quint8(r.bytes.at(1)) != 0x08)
            records << r;
    });

    auto write = [](QList<ParameterWrite> w) { return [w](Drive &d) { return d.writeParameters(w); }; };
    const qint64 far = qint64(1) << 40;
    const QList<Case> cases = {
        {"nothing", write({}), ErrorCode::InvalidArgument, "No parameter"},
        {"index 220", write({{220, 1}}), ErrorCode::InvalidArgument, "220"},
        {"index -1", write({{-1, 1}}), ErrorCode::InvalidArgument, "-1"},
        {"40000", write({{10, 40000}}), ErrorCode::OutOfRange, "40000"},
        {"int64 max", write({{10, kMax}}), ErrorCode::OutOfRange, QString::number(kMax)},
        {"int64 min", write({{10, kMin}}), ErrorCode::OutOfRange, QString::number(kMin)},
        {"station range", write({{75, 150}}), ErrorCode::OutOfRange, "150"},
        {"twice", write({{10, 1}, {10, 2}}), ErrorCode::InvalidArgument, "P10"},
        {"good then bad", write({{12, 1}, {13, 99999}}), ErrorCode::OutOfRange, "P13"},
        {"read 220",
         [](Drive &d) {
             return d.readParameters({1, 220});
         },
         ErrorCode::InvalidArgument, "220"},
        {"channel",
         [](Drive &d) {
             return d.readChannels({"speed", "warp"});
         },
         ErrorCode::InvalidArgument, "warp"},
        {"move far", [far](Drive &d) { return d.moveRelative(far, 100); }, ErrorCode::OutOfRange, QString::number(far)},
        {"move speed 0", [](Drive &d) { return d.moveRelative(100, 0); }, ErrorCode::InvalidArgument, "speed"},
        {"target far", [far](Drive &d) { return d.moveAbsolute(-far, 100); }, ErrorCode::OutOfRange,
         QString::number(-far)},
        {"position far", [far](Drive &d) { return d.setPosition(far); }, ErrorCode::OutOfRange, QString::number(far)},
        {"home", [](Drive &d) { return d.home(true); }, ErrorCode::NotSupported, "homing"},
        {"ee", [](Drive &d) { return d.eeOperation(EeOperation::Save); }, ErrorCode::NotSupported, "EEPROM"},
    };
    const QString problem = runCases(*backend.drive(1), cases);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCoreApplication::processEvents();
    QCOMPARE(txCount(records), 0);
    QVERIFY(sim->parameters() == before);
    QVERIFY(!sim->motor().isMoving());
}

QTEST_GUILESS_MAIN(TestBadInput)
#include "tst_badinput.moc"
