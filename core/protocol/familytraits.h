#pragma once

#include "core/common/family.h"

#include <QList>
#include <QString>
#include <QStringList>
#include <QVariantMap>
#include <memory>

namespace dd {

class FrameDescriber;

enum class LinkKind { Serial, Can };

// How a dictionary entry reaches its parameter on the drive: by its index alone (servo-can),
// by a Modbus register (servo-modbus: "register"), or by the command that reads it (shuoke:
// "readCommand"; write-only settings have none).
enum class ParameterAddressing { Index, Register, ReadCommand };

// The addresses a drive can have, both ends included.
struct AddressRange
{
    int first = 1;
    int last = 247;
    bool contains(int address) const { return address >= first && address <= last; }
};

// One way a family's frames travel: a framing on a kind of link.
struct FramingTraits
{
    QString id;            // the --framing value: "rtu", "ascii", "plc", "can"
    const char *name = ""; // untranslated: QT_TRANSLATE_NOOP("dd::FamilyTraits", ...)
    LinkKind link = LinkKind::Serial;
    AddressRange addresses; // a drive's address here: --address, scan ranges
    bool detect = true;     // tried by auto-detect, in the order of FamilyTraits::framings

    QString displayName() const; // translated: "RTU (binary)"
};

// Everything a front end (GUI, CLI, simulator) needs to know about a drive family, given by
// the family's own code (dd::<family>::traits() in core/protocol/<family>/<family>traits.cpp)
// and reached through familyTraits(). No front end
// switches on a family. The family's backend (the client-side drive code) is made by the
// table in core/drive/familytable.cpp, its simulated drive by the one in
// sim/bench/simfamilies.cpp.
struct FamilyTraits
{
    Family family = Family::ServoModbus;
    // Display name, untranslated: QT_TRANSLATE_NOOP("dd::FamilyTraits", ...); displayName().
    const char *name = "";
    // The framings, in auto-detect order. The first of a link kind is that link's default.
    QList<FramingTraits> framings;
    int defaultBaud = 0;    // serial links; 0 when the family has none
    QList<int> scanBauds;   // the baud sweep of a scan, most common first
    int defaultBitrate = 0; // CAN links; 0 when the family has none
    // Units of motion commands, untranslated (QT_TRANSLATE_NOOP("dd::FamilyTraits", ...)).
    const char *speedUnit = "";
    const char *positionUnit = "";
    // Motion commands' speed: the highest a command may ask for, and the GUI's defaults for
    // a jog and a move (in speedUnit).
    int maxSpeed = 0;
    int jogSpeed = 0;
    int moveSpeed = 0;
    // EEPROM operations exist (EE-Set, ...): written parameters stay in RAM until stored.
    bool eeOperations = false;
    ParameterAddressing parameterAddressing = ParameterAddressing::Index;
    // A frame describer for one connection (the frame monitor, traffic logs).
    std::unique_ptr<FrameDescriber> (*describer)(const QString &framing, const QVariantMap &options) = nullptr;
    // A motion command switches the power stage on by itself, and whether it is on cannot be
    // read back (servo-can: 0x20, 0x21 and 0x22 enable the servo; nothing reports the enable).
    // The CLI then moves only when told it may switch it on (--enable); the GUI only once its
    // own Enable switched it on.
    bool motionEnables = false;

    QString id() const { return familyId(family); }
    QString displayName() const;      // translated: "Servo (CAN)"
    QString speedUnitText() const;    // translated: "r/min"
    QString positionUnitText() const; // translated: "counts"

    bool talks(LinkKind link) const;
    // nullptr when `id` is not one of this family's framings.
    const FramingTraits *framing(const QString &id) const;
    // The link's default framing; nullptr when the family does not use that link.
    const FramingTraits *defaultFraming(LinkKind link) const;
    // The framing a connection uses: `framing`, or the link's default when empty; nullptr
    // when the connection cannot be this family's (servo-modbus on CAN, "can" on a port).
    const FramingTraits *framingFor(LinkKind link, const QString &framing) const;
    QStringList framingIds(LinkKind link) const;
    // Every address a drive of this family can have on `link` (the union of its framings).
    AddressRange addresses(LinkKind link) const;
};

// The family table: every family's traits, in auto-detect order (core/protocol/familytraits.cpp
// lists them, one line per family).
QList<const FamilyTraits *> allFamilyTraits();
const FamilyTraits &familyTraits(Family family);
// Every framing id of every family, without repeats (for --framing).
QStringList allFramingIds();
// A frame describer for one connection of `family`.
std::unique_ptr<FrameDescriber> createFrameDescriber(Family family, const QString &framing = {},
                                                     const QVariantMap &options = {});

} // namespace dd
