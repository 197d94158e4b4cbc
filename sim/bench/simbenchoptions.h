#pragma once

#include "core/common/family.h"
#include "sim/bus/faultinjector.h"

#include <QList>
#include <QMap>
#include <QString>

namespace dd {

// What one simulated bus with its drives looks like (drivedesk-sim's options, the demo
// bench, CLI --sim, tests).
struct SimBenchOptions
{
    Family family = Family::ServoModbus;
    QList<int> addresses; // empty: one drive at the family's default address
    QString can;          // "plugin:interface" for a CAN bus; empty: a pty
    QString linkPath;     // pty: also make a symbolic link here
    int baud = 0;         // 0: family default
    QMap<int, int> bauds; // serial: the baud of the drive at an address, overriding `baud`
    int bitrate = 0;      // 0: family default
    QString framing;      // shuoke: rtu | ascii | can | plc
    int latencyUs = -1;   // drive reply latency; -1: device default
    FaultSettings faults;
    QString stateFile;        // load at start (if it exists), save at stop
    bool demoMotion = false;  // drives move on their own (demo bench)
    double resonanceHz = 0.0; // > 0: the closed-loop drives carry a compliant load resonating here

    static int defaultAddress(Family family); // servo-can 1, servo-modbus 1, shuoke 1
    static int defaultBaud(Family family);    // servo-modbus 19200, shuoke 9600
    static int defaultBitrate(Family family); // servo-can 1 M, shuoke 100 k
};

} // namespace dd
