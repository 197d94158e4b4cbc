#pragma once

#include "core/common/error.h"
#include "core/common/family.h"

#include <QList>
#include <QString>
#include <functional>
#include <memory>

namespace dd {

class SimCanDevice;
class SimSerialDevice;

// What the bench asks a family's simulator for: one drive.
struct SimDeviceSpec
{
    int address = 1;
    int baud = 0;                  // serial
    int bitrate = 0;               // CAN
    QString framing;               // the family's framing id; empty: the link's default
    bool demoMotion = false;       // move on its own (a slow demo profile)
    std::function<qint64()> clock; // the bus's clock (µs)
    double resonanceHz = 0.0;      // > 0: a compliant load resonating here (closed-loop drives)
};

// The simulator of one family: the drives it makes on a serial bus and on a CAN bus (null
// where the family has no such link). Each family's simulator lives in its own folder
// (sim/<family>/); this table (simfamilies.cpp, one line per family) is the one place that
// lists them. The family's traits (core/protocol/familytraits.h) say the rest.
struct SimFamily
{
    Family family;
    std::unique_ptr<SimSerialDevice> (*serial)(const SimDeviceSpec &spec, Error *error);
    std::unique_ptr<SimCanDevice> (*can)(const SimDeviceSpec &spec, Error *error);
    // The demo bench lets this family's drive move on its own: it has no motion commands
    // of its own to try.
    bool demoMotion;
};

const SimFamily &simFamily(Family family);

} // namespace dd
