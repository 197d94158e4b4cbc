#pragma once

#include "core/common/family.h"

#include <QFlags>
#include <QList>
#include <QMetaType>
#include <QString>
#include <QVariantMap>

namespace dd {

// What a drive can do. Actions a family lacks are shown disabled with the reason.
enum class Capability : quint32 {
    ReadParameters = 1u << 0,
    WriteParameters = 1u << 1,
    Monitor = 1u << 2,
    Jog = 1u << 3,
    MoveRelative = 1u << 4,
    MoveAbsolute = 1u << 5,
    Home = 1u << 6,
    Enable = 1u << 7,
    Stop = 1u << 8,
    EmergencyStop = 1u << 9,
    ReadAlarm = 1u << 10,
    ClearAlarm = 1u << 11,
    EeOperations = 1u << 12,
    SetPosition = 1u << 13,
};
Q_DECLARE_FLAGS(Capabilities, Capability)
Q_DECLARE_OPERATORS_FOR_FLAGS(Capabilities)

QString capabilityId(Capability c); // "jog", "ee-operations", ...
QStringList capabilityIds(Capabilities caps);

// Who the drive is.
struct DriveIdentity
{
    Family family = Family::ServoModbus;
    int address = 0;  // station / Modbus address / Shuoke address
    QString firmware; // as the drive reports it; empty when not readable
    QString model;    // e.g. "M6505" when known
    QString link;     // "/dev/ttyUSB0 @ 115200", "virtualcan:can0"
};

// A live value the drive offers for trends and the CLI's monitor.
struct ChannelInfo
{
    QString id;   // stable: "speed", "torque", "current", "bus-voltage", "position",
                  // "position-error", "temperature", "inputs", "outputs", ...
    QString name; // translated display name
    QString unit; // untranslated, one of channelUnits() or "": "r/min", "%", "A", "pulse", ...
    int decimals = 0;
};

// The units a ChannelInfo (or a bundled dictionary's parameter) may carry. They stay
// untranslated in the drive layer (they name CSV columns, the CLI's output and run files); each is registered for translation in the
// context "dd::ChannelUnit", and what shows them to a user translates them there
// (channelUnitText; DisplayText::unit in the GUI), so they follow a live language switch.
QStringList channelUnits();
// A unit in the language of the moment ("pulse/s" -> "脉冲/秒"); one not in channelUnits()
// as it is.
QString channelUnitText(const QString &unit);

// The "status" channel of a drive that reports its motion state and switch inputs as one
// value (shuoke 0x3B): these bits.
namespace StatusChannelBits {
constexpr int Running = 1;
constexpr int LeftLimit = 2;
constexpr int Origin = 4;
constexpr int RightLimit = 8;
constexpr int EnableInput = 16;
} // namespace StatusChannelBits

// The last known state of a drive, refreshed by heartbeats or polling.
struct DriveStatus
{
    bool online = false;
    bool running = false;
    bool enabled = false;
    bool positionValid = false;
    qint64 position = 0;
    int alarmCode = 0;    // 0 = none
    qint64 updatedMs = 0; // QDateTime::currentMSecsSinceEpoch() of the last update
};

// One parameter write and its outcome.
struct ParameterWrite
{
    int index = 0;
    qint64 value = 0;
};

// How one parameter write ended; WriteVerification decides it the same way for every family.
enum class WriteOutcome {
    Verified,       // read back equal to the value written
    Mismatch,       // the drive took the write, but reads back another value
    NotWritten,     // refused by the drive or never sent, or unanswered and the read-back
                    // shows another value: the drive did not take it
    Unknown,        // the write was not confirmed and could not be read back
    ReadBackFailed, // the drive took the write, but the read-back got no (valid) answer
    WriteOnly       // written; a write-only setting, which nothing can read back
};

struct ParameterWriteResult
{
    int index = 0;
    qint64 requested = 0;
    qint64 readBack = 0;
    bool written = false;                            // the drive accepted the write
    bool verified = false;                           // read back and equal (write-only: never)
    bool readable = true;                            // false for write-only parameters
    bool readBackFailed = false;                     // no answer to the read-back (nor to the write, if !written):
                                                     // what the drive holds is unknown
    QString error;                                   // translated reason when !written or !verified
    WriteOutcome outcome = WriteOutcome::NotWritten; // what the fields above add up to
};

// How a jog ended and what brings the axis to rest (Drive::jogEnded(), the "stoppedBy" info
// of a stop reply).
struct JogEnd
{
    enum class StoppedBy {
        Command,       // a stop command reached the drive (it was heard from after the stop)
        DriveWatchdog, // no stop could be sent or confirmed: the drive's own watchdog stops it
        Nothing        // no stop could be sent or confirmed and the drive has no watchdog
    };
    StoppedBy stoppedBy = StoppedBy::Command;
    bool leaseExpired = false; // the holder stopped renewing the jog lease
    bool linkLost = false;     // the link went away while jogging
    QString message;           // translated: what happened, what to do
};
QString stoppedById(JogEnd::StoppedBy by); // "command", "drive-watchdog", "nothing"

// servo-modbus EEPROM operations (op codes of the seed).
enum class EeOperation { Save = 1, Reload = 2, Backup = 3, RestoreBackup = 4, FactoryDefaults = 5 };
QString eeMnemonic(EeOperation op);                         // "EE-Set", "EE-rd", "EE-bA", "EE-rS", "EE-dEF"
QString eeMeaning(EeOperation op);                          // translated meaning
bool eeIsDestructive(EeOperation op);                       // asks for confirmation (rd, rS, dEF)
std::optional<EeOperation> eeFromText(const QString &text); // "set", "EE-Set", "1", ...

// A drive found by discovery.
struct DiscoveredDrive
{
    Family family = Family::ServoModbus;
    int address = 0;
    int baud = 0;    // serial
    int bitrate = 0; // CAN
    QString framing; // shuoke: rtu / ascii / can / plc
    QString firmware;
    QString state; // translated: "idle", "running", "alarm 12", ...
    QString link;
};

} // namespace dd

Q_DECLARE_METATYPE(dd::DriveStatus)
Q_DECLARE_METATYPE(dd::DiscoveredDrive)
Q_DECLARE_METATYPE(dd::JogEnd)
