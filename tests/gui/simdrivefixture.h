#pragma once
// For the panel tests: one simulated drive on a pty, servo-modbus (start()) or shuoke RTU
// (startShuoke()) — a SimBench on the test's thread, so the test can look into the
// simulated drive directly — a DriveHub connected to it, the drive's DriveInfo and a
// DriveContext for panels. Every frame the hub's links send is recorded in `traffic`.

#include "core/drive/drivehub.h"
#include "core/link/trafficrecord.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "sim/shuoke/simshuokeserialdevice.h"
#include "ui/bus/driveinfo.h"
#include "ui/workspace/drivecontext.h"

#include <QList>
#include <QTest>
#include <functional>

namespace dd {

class SimDriveFixture
{
public:
    SimDriveFixture()
    {
        QObject::connect(&hub, &DriveHub::trafficRecorded, &hub,
                         [this](int, const TrafficRecord &r) { traffic.append(r); });
    }

    // Starts the bench; `beforeConnect` may adjust the simulated drive (firmware, values)
    // before DriveDesk first talks to it.
    bool start(const std::function<void(SimServoModbusDrive *)> &beforeConnect = {})
    {
        SimBenchOptions options;
        options.family = Family::ServoModbus;
        if (Error e = bench.start(options)) {
            qWarning("SimBench: %s", qPrintable(e.message));
            return false;
        }
        if (beforeConnect)
            beforeConnect(drive());
        return connectHub();
    }

    bool startShuoke()
    {
        SimBenchOptions options;
        options.family = Family::Shuoke;
        if (Error e = bench.start(options)) {
            qWarning("SimBench: %s", qPrintable(e.message));
            return false;
        }
        m_family = Family::Shuoke;
        return connectHub();
    }

    bool connectHub()
    {
        bool opened = false;
        hub.openConnection(bench.clientSettings(), [&](int id, const Error &e) {
            connectionId = id;
            opened = true;
            if (e)
                qWarning("openConnection: %s", qPrintable(e.message));
        });
        if (!QTest::qWaitFor([&] { return opened; }, 5000) || connectionId <= 0)
            return false;
        bool fetched = false;
        fetchDriveInfo(&hub, connectionId, address, [&](const DriveInfo &i, const Error &) {
            info = i;
            fetched = true;
        });
        return QTest::qWaitFor([&] { return fetched; }, 10000) && info.valid;
    }

    SimServoModbusDrive *drive() const
    {
        return bench.serialBus() ? static_cast<SimServoModbusDrive *>(bench.serialBus()->device(0)) : nullptr;
    }

    SimShuokeDrive *shuokeDrive() const
    {
        return bench.serialBus() ? &static_cast<SimShuokeSerialDevice *>(bench.serialBus()->device(0))->drive()
                                 : nullptr;
    }

    DriveContext context() const
    {
        DriveContext c;
        c.hub = const_cast<DriveHub *>(&hub);
        c.connectionId = connectionId;
        c.address = address;
        c.family = m_family;
        c.capabilities = info.capabilities;
        return c;
    }

    // Sent frames (serial: Modbus RTU, function code at byte 1) since the last clear.
    QList<QByteArray> sentFrames() const
    {
        QList<QByteArray> out;
        for (const TrafficRecord &r : traffic)
            if (r.direction == TrafficRecord::Direction::Tx)
                out << r.bytes;
        return out;
    }
    int sentWithFunction(quint8 function) const
    {
        int n = 0;
        for (const QByteArray &f : sentFrames())
            n += f.size() > 1 && quint8(f.at(1)) == function ? 1 : 0;
        return n;
    }

    SimBench bench;
    DriveHub hub;
    int connectionId = 0;
    int address = 1;
    DriveInfo info;
    QList<TrafficRecord> traffic;

private:
    Family m_family = Family::ServoModbus;
};

} // namespace dd
