#pragma once

#include "core/link/linkhealth.h"
#include "core/report/recordlinkhealth.h"

#include <QHash>
#include <QObject>

namespace dd {

class TrafficTap;

// A link's health per drive for the commissioning record: one core/link LinkHealth per
// address a request went to (fed every traffic record of the link, each keeping its own
// address's, as the Link health view and `ping` count), plus the failed operations whoever
// sees them reports with countError().
class LinkHealthCounter : public QObject
{
    Q_OBJECT
public:
    // `baud` > 0: the serial baud rate (LinkHealth's wire time); 0: CAN. `tap` may be null:
    // count() is then called by the owner.
    LinkHealthCounter(TrafficTap *tap, int baud, QObject *parent = nullptr);

    void count(const TrafficRecord &record);
    void countError(int address) { ++m_errors[address]; }
    // Every operation has finished: see LinkHealth::closeOutstanding().
    void closeOutstanding();
    // The figures of the drive at `address`, described by `scope`.
    RecordLinkHealth health(int address, const QString &scope) const;

private:
    int m_baud = 0;
    QHash<int, LinkHealth> m_health;
    QHash<int, int> m_errors;
};

} // namespace dd
