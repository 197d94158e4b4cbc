#pragma once

#include <QString>

namespace dd {

// How to open a CAN bus through Qt's QCanBus plugins.
struct CanSettings
{
    QString plugin = QStringLiteral("socketcan"); // socketcan, virtualcan, peakcan, ...
    QString interface = QStringLiteral("can0");
    int bitrate = 1000000;
    // socketcan: Qt tries to set the bitrate itself (needs privileges); by default leave an
    // already configured interface alone.
    bool configureBitrate = false;
    int maxInFlight = 32; // pipelined requests outstanding at once
    int responseTimeoutMs = 50;
    int retries = 2;

    // "virtualcan:can0" → plugin + interface; false when the text has no ':'.
    static bool parse(const QString &text, CanSettings *out);
    QString toString() const { return plugin + QLatin1Char(':') + interface; }
};

} // namespace dd
