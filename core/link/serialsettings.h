#pragma once

#include <QSerialPort>
#include <QString>

namespace dd {

// How to open a serial port and pace transactions on it.
struct SerialSettings
{
    QString portName; // "/dev/ttyUSB0", "COM3", a pty path
    qint32 baud = 9600;
    QSerialPort::DataBits dataBits = QSerialPort::Data8;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
    int bitsPerChar = 10; // start + 8 data + (parity) + stop
    int minGapMs = 0;     // quiet time after each transaction
    // Commands arrive at least this far apart, counted as the drive counts: from the last
    // byte of one command to the last byte of the next (shuoke: 50, its "50 ms between
    // commands"). 0: no such rule. Applies on top of minGapMs.
    int minCommandSpacingMs = 0;
    int responseTimeoutMs = 100; // allowance beyond the wire time of request + reply
    int retries = 2;             // extra attempts after a timeout / corrupt reply
};

} // namespace dd
