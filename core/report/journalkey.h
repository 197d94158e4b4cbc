#pragma once

#include "core/common/family.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QString>

namespace dd {

struct DriveIdentity;

// Which drive a verification journal belongs to (docs/record.md, "Verification journal"):
// the machine / project name the engineer set, the family, the address, the link it was
// reached on (serial port or CAN interface, without baud or bit rate) and what the drive
// itself tells (firmware, model). Two drives differ in the journal when any of these
// differs; what none of them tells apart (same machine name, port, address and firmware)
// shares a journal, and cannotTellApart() says so for the record.
struct JournalKey
{
    Q_DECLARE_TR_FUNCTIONS(dd::JournalKey)
public:
    QString machine; // as the engineer set it (trimmed); empty: none set
    Family family = Family::ServoModbus;
    int address = 0;
    QString link;     // "/dev/ttyUSB0", "socketcan:can0", "sim:/path/state.json"
    QString firmware; // as the drive reported it; empty: not reported
    QString model;    // likewise

    static JournalKey of(const DriveIdentity &identity, const QString &link, const QString &machine);

    // "<family>-<address>-<16 hex digits of the SHA-256 of canonicalJson()>.json": never the
    // "<family>-<address>.json" of journals made before the key existed.
    QString fileName() const;
    QJsonObject toJson() const;
    static JournalKey fromJson(const QJsonObject &json);
    bool operator==(const JournalKey &o) const;
    bool operator!=(const JournalKey &o) const { return !(*this == o); }

    // Translated, for the record: "Identified by machine “Press 3”, servo-modbus address 1
    // on /dev/ttyUSB0 and firmware 7051."
    QString identifiedBy() const;
    // Translated: what the key cannot tell apart ("" never: at least the drive's serial
    // number is missing, which no family reports).
    QString cannotTellApart() const;
};

} // namespace dd
