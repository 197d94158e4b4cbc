#pragma once

#include <QString>
#include <QtGlobal>

namespace dd {

// One serial port as the connect dialog lists it.
struct SerialPortEntry
{
    QString path;         // what QSerialPort opens: "/dev/ttyUSB0", "COM3", "/tmp/dd-servo"
    QString description;  // "FT232R USB UART", "Pseudo-terminal (simulator)"
    QString manufacturer; // "FTDI"
    quint16 vendorId = 0;
    quint16 productId = 0;
    bool hasIds = false;    // USB VID:PID known
    bool isVirtual = false; // a link to a pseudo-terminal (simulator, socat)

    // "/dev/ttyUSB0 — FT232R USB UART (FTDI) [0403:6001]"
    QString label() const;
    bool operator==(const SerialPortEntry &o) const
    {
        return path == o.path && description == o.description && manufacturer == o.manufacturer
            && vendorId == o.vendorId && productId == o.productId && hasIds == o.hasIds && isVirtual == o.isVirtual;
    }
    bool operator!=(const SerialPortEntry &o) const { return !(*this == o); }
};

} // namespace dd
