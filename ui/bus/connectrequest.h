#pragma once

#include "core/drive/discovery.h"
#include "core/link/connectionsettings.h"
#include "core/protocol/familytraits.h"

#include <QList>
#include <QString>

class QSettings;

namespace dd {

// What the connect dialog (or --connect) asks for: a link, a family or "detect", and the
// scan to run once connected.
struct ConnectRequest
{
    ConnectionSettings settings; // `family` is ignored when `detect` is set
    bool detect = false;
    bool scan = true;        // scan for drives after connecting
    ScanOptions scanOptions; // address range and probe timeout (bauds: see sweepBauds)
    bool sweepBauds = false; // serial scan: try each of the family's scan bauds

    ConnectRequest()
    {
        scanOptions.from = DefaultFrom;
        scanOptions.to = DefaultTo;
        scanOptions.timeoutMs = DefaultProbeTimeoutMs;
    }

    // Detect: the families tried in order, one connection each, stopping at the first that
    // finds a drive (a bus speaks one protocol): every framing of the link's kind that the
    // family table marks for detection, in table order (serial: servo-modbus, then shuoke
    // RTU, then shuoke ASCII; CAN: servo-can, then shuoke CAN). Otherwise: just `settings`.
    QList<ConnectionSettings> attempts() const;

    // The scan of one attempt: the address range clipped to what the attempt's family and
    // framing allow, and (sweepBauds) that family's baud sweep.
    ScanOptions scanOptionsFor(const ConnectionSettings &attempt) const;
    // Default address range of a scan (a commissioning bench rarely has more than a few
    // drives; the dialog lets the user widen it to 1..247).
    static constexpr int DefaultFrom = 1;
    static constexpr int DefaultTo = 32;
    // Per-probe timeout of a serial scan. The scanners' adaptive default (wire time + a few
    // ms) misses drives behind USB adapters with a 16 ms latency timer (FTDI's default), so
    // the GUI starts from a safe fixed value; 32 addresses then take about 2 s.
    static constexpr int DefaultProbeTimeoutMs = 50;

    // From drivedesk's --connect LINK [--family F] [--baud N] [--bitrate N] [--framing F]:
    // LINK is "plugin:interface" when the part before the first ':' names an installed Qt
    // CAN plugin, otherwise a serial port; family "" or "detect" detects. Scans 1..32.
    // False with a message for an unknown family or framing.
    static bool fromCommandLine(const QString &link, const QString &family, int baud, int bitrate,
                                const QString &framing, ConnectRequest *out, QString *error);

    // Persisted in the "connect" group.
    void save(QSettings &settings) const;
    static ConnectRequest load(QSettings &settings);
    // One line for menus and logs: "servo-modbus on /dev/ttyUSB0 @ 19200".
    QString describe() const;
};

} // namespace dd
