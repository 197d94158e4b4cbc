#pragma once

#include "core/protocol/canframedata.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

namespace dd {

// Says in a few words what one frame on a link means, for the frame monitor, saved traffic
// logs and traces: "#1 run at 100 r/min", "#1 read PA0–PA19", "#1 PA0 = 7051, PA1 = 0, …",
// "#1 Query speed → 1000". Headless; one object per link, fed every frame of the link in
// the order they passed (a Modbus reply is only understood against the request before it,
// so a describer may remember the last request it saw).
//
// Each family has its own describer in its protocol folder (ServoCanDescriber,
// ServoModbusDescriber, ShuokeDescriber); the family table (core/drive/familytable.h) makes
// the right one for a connection: createFrameDescriber().
// A frame that does not decode reads "?" followed by the codec's technical reason in
// brackets. The words are translated (context dd::FrameDescriber for every family, and the
// codecs' own contexts for command and register names) in the language current when the
// frame is described.
class FrameDescriber
{
    Q_DECLARE_TR_FUNCTIONS(dd::FrameDescriber)

public:
    enum class Origin { Host, Drive }; // TX is the host, RX the drive

    virtual ~FrameDescriber() = default;

    // A frame of the family's serial framing / a CAN frame. A family that does not use that
    // kind of link says unknown().
    virtual QString describeSerial(Origin origin, const QByteArray &bytes);
    virtual QString describeCan(Origin origin, const CanFrameData &frame);
    // Forgets the last request (e.g. after a gap in the traffic).
    virtual void reset() { }

    static QString unknown();                     // "?"
    static QString failed(const QString &reason); // "?" or "? (reason)"
    static QString station(int address);          // "#1 "
};

} // namespace dd
