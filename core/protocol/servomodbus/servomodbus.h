#pragma once

#include "core/protocol/modbus/modbusrtu.h"

#include <QByteArray>
#include <QList>
#include <QMap>
#include <QString>
#include <QtGlobal>
#include <optional>

// Register map of the `servo-modbus` family (docs/protocols/servo-modbus.md): DP monitor
// registers, PA parameters, EE operations, request planning and validation.
// Pure functions and constant tables; framing is in protocol/modbusrtu.h.
namespace dd::servomodbus {

// Context of the translatable texts below (meanings are marked with QT_TRANSLATE_NOOP).
constexpr const char *TranslationContext = "dd::servomodbus";
QString translated(const char *sourceText); // QCoreApplication::translate in that context

constexpr int MaxRegistersPerRequest = 20; // the drive's limit for 0x03 and 0x10
constexpr int ParameterCount = 60;         // PA0..PA59
constexpr quint16 ParameterBaseRegister = 0x0064;
constexpr quint16 MonitorRegisterCount = 24; // 0x0000..0x0017
constexpr int AddressParameter = 51;         // PA51 = drive address
constexpr int FirmwareParameter = 2;         // PA2 = software version, chooses the EE format

// ---- DP monitor ----
struct MonitorRegister
{
    quint16 reg;
    const char *mnemonic; // exactly as on the drive's display / docs/protocols/servo-modbus.md, e.g. "DP-PoS."
    const char *meaning;  // English, QT_TRANSLATE_NOOP; empty where nobody documents it
    int highRegister;     // for the low part of a position pair: its high part; else -1
};
const QList<MonitorRegister> &monitorRegisters();    // 0x00..0x17 in order
const MonitorRegister *monitorRegister(quint16 reg); // nullptr outside 0x00..0x17

// ---- PA parameters ----
constexpr bool isParameterIndex(int n)
{
    return n >= 0 && n < ParameterCount;
}
constexpr quint16 parameterRegister(int n)
{
    return static_cast<quint16>(ParameterBaseRegister + n);
}
int parameterIndex(quint16 reg); // -1 when reg is not a PA register

// Whole request ranges the drive accepts.
bool isReadableRange(quint16 start, int count); // 1..20, all in 0x00..0x17 or all in PA
bool isWritableRange(quint16 start, int count); // 1..20, all in PA

// ---- Request planning ----
struct RegisterRange
{
    quint16 start = 0;
    quint16 count = 0;
    bool operator==(const RegisterRange &o) const { return start == o.start && count == o.count; }
};
struct RegisterWrite
{
    quint16 start = 0;
    QList<quint16> values;
    bool operator==(const RegisterWrite &o) const { return start == o.start && values == o.values; }
};

// Fewest 0x03 requests of <= maxPerRequest registers that cover `registers` (any order,
// duplicates allowed). A request may span registers nobody asked for (a gap) only when
// that saves a request: among the plans with the fewest requests the one reading the fewest
// registers is taken, and a plan without gap reads reads fewer registers than any plan with
// them; on a further tie the earlier requests are the longer ones (PA0..PA59 -> 20/20/20).
// A request never spans the hole between the monitor block and the PA block. Registers the
// drive cannot read are left out of the plan.
QList<RegisterRange> planRegisterReads(const QList<quint16> &registers, int maxPerRequest = MaxRegistersPerRequest);
// The same over PA indices; indices outside 0..59 are left out.
QList<RegisterRange> planReads(const QList<int> &paIndices, int maxPerRequest = MaxRegistersPerRequest);
// 0x10 writes of PA values (index -> raw 16-bit value): runs of consecutive indices, each
// split into pieces of <= maxPerRequest; never across a gap (that would overwrite a
// parameter nobody asked to change). Indices outside 0..59 are left out.
QList<RegisterWrite> planWrites(const QMap<int, quint16> &paValues, int maxPerRequest = MaxRegistersPerRequest);

// ---- EE operations ----
enum class EeOp : quint16 { Set = 1, Read = 2, Backup = 3, Restore = 4, Defaults = 5 };
const QList<EeOp> &allEeOps();
std::optional<EeOp> eeOpFromCode(quint16 code);
const char *eeOpMnemonic(EeOp op);   // "EE-Set", "EE-rd", "EE-bA", "EE-rS", "EE-dEF"
const char *eeOpMeaning(EeOp op);    // English, QT_TRANSLATE_NOOP in TranslationContext
bool eeOpNeedsConfirmation(EeOp op); // Read, Restore, Defaults overwrite the working set

enum class EeFormat {
    Legacy, // fc 0x06, register 0x0000, value = op; the reply value reports progress
    New     // fc 0x10, one register at 0x003A, value = op
};
enum class EeFormatChoice { Auto, Legacy, New }; // the manual override setting

constexpr quint16 EeLegacyRegister = 0x0000;
constexpr quint16 EeNewRegister = 0x003A;
// The seed: legacy "below 705X (PA2)". PA2 holds the version as four digits, version and
// revision (7051 = 705 rev 1), so X is the revision digit: legacy when PA2 / 10 < 705,
// i.e. PA2 < 7050. A drive that shows its version another way needs the override.
constexpr int FirstNewEeFirmware = 7050;
EeFormat eeFormatForFirmware(quint16 pa2);
// Legacy / New: that format. Auto: from PA2, or nullopt when PA2 is unknown (ask the user).
std::optional<EeFormat> chooseEeFormat(EeFormatChoice choice, std::optional<quint16> pa2);
QString eeFormatChoiceId(EeFormatChoice choice); // "auto", "legacy", "new" (settings)
std::optional<EeFormatChoice> eeFormatChoiceFromId(const QString &id);

modbusrtu::Request eeRequest(quint8 address, EeOp op, EeFormat format);
QByteArray encodeEeRequest(quint8 address, EeOp op, EeFormat format);

// Legacy format: the 0x06 reply's value. 0 = still running (poll again), == op = finished,
// anything else = failed.
enum class EeProgress { Running, Finished, Failed };
EeProgress interpretLegacyEeReply(quint16 value, EeOp op);

// ---- Position pairs (DP-PoS / DP-PoS., DP-CPo / DP-CPo., DP-EPo / DP-EPo.) ----
// value = (int16) high * F + (uint16) low, with F = 65536 (BinaryWords, the default: the
// pair is one int32), 10000 or 100000 (decimal split: low = 0..F-1, high carries the sign,
// floor division). With F = 100000 a low part above 65535 cannot be carried.
enum class PositionPairRule { BinaryWords, Decimal10000, Decimal100000 };
qint64 combinePositionPair(quint16 low, quint16 high, PositionPairRule rule = PositionPairRule::BinaryWords);
struct RegisterPair
{
    quint16 low = 0;
    quint16 high = 0;
    bool operator==(const RegisterPair &o) const { return low == o.low && high == o.high; }
};
// The inverse (for the simulator); nullopt when the rule cannot carry the value.
std::optional<RegisterPair> splitPosition(qint64 value, PositionPairRule rule = PositionPairRule::BinaryWords);
QString positionPairRuleId(PositionPairRule rule); // "binary-words", "decimal-10000", "decimal-100000"
std::optional<PositionPairRule> positionPairRuleFromId(const QString &id);

// ---- Validation of what a host sends ----
// Empty when the drive accepts the request; otherwise the reason (technical English).
// Accepted: 0x03 over isReadableRange (not to the broadcast address: nobody would reply);
// 0x10 over isWritableRange with matching values, or one register at 0x003A with an EE op;
// 0x06 to register 0x0000 with an EE op.
QString validateRequest(const modbusrtu::Request &request);

} // namespace dd::servomodbus
