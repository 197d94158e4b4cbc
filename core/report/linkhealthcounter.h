#pragma once

#include "core/report/recordlinkhealth.h"

#include <QObject>

namespace dd {

class TrafficTap;
struct TrafficRecord;

// Counts a link's health from its traffic tap, the way the GUI's status bar does: frames
// sent and received, discarded frames (noise, bad checksums, late replies), retries (frames
// sent again); failed operations are added by whoever sees them (countError()).
class LinkHealthCounter : public QObject
{
    Q_OBJECT
public:
    explicit LinkHealthCounter(TrafficTap *tap, QObject *parent = nullptr);

    void countError() { ++m_health.errors; }
    // The counts so far, described by `scope`.
    RecordLinkHealth health(const QString &scope) const;
    // Counts one traffic record (what the tap's signal calls).
    void count(const TrafficRecord &record);

private:
    RecordLinkHealth m_health;
};

} // namespace dd
