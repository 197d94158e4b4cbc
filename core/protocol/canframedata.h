#pragma once

#include <QByteArray>
#include <QtGlobal>

namespace dd {

// A CAN frame as the codecs see it: identifier, data bytes, frame format. Links convert it
// to and from QCanBusFrame; codecs stay free of Qt SerialBus.
struct CanFrameData
{
    quint32 id = 0;
    QByteArray data;       // 0..8 bytes
    bool extended = false; // 29-bit identifier

    bool operator==(const CanFrameData &o) const { return id == o.id && data == o.data && extended == o.extended; }
    bool operator!=(const CanFrameData &o) const { return !(*this == o); }
};

} // namespace dd
