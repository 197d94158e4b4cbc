#pragma once
// For the panel tests: one simulated servo-modbus drive on a pty (a SimBench on the test's
// thread, so the test can look into the simulated drive directly), a DriveHub connected to
// it, the drive's DriveInfo and a DriveContext for panels. Every frame the hub's links send
// is recorded in `traffic`.

#include "drive/drivehub.h"
#include "drivecontext.h"
#include "driveinfo.h"
#include "link/trafficrecord.h"
#include "simbench.h"
#include "simserialbus.h"
#include "simservomodbusdrive.h"

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
        return QTest::qWaitFor([&] { return fetched; }, 5000) && info.valid;
    }

    SimServoModbusDrive *drive() const
    {
        return bench.serialBus() ? static_cast<SimServoModbusDrive *>(bench.serialBus()->device(0)) : nullptr;
    }

    DriveContext context() const
    {
        DriveContext c;
        c.hub = const_cast<DriveHub *>(&hub);
        c.connectionId = connectionId;
        c.address = address;
        c.family = Family::ServoModbus;
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
};

} // namespace dd
