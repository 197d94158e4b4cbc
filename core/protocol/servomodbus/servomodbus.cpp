#include "core/protocol/servomodbus/servomodbus.h"
#include "core/common/hextext.h"

#include <QCoreApplication>

#include <algorithm>
#include <limits>
#include <utility>

namespace dd::servomodbus {

namespace {

constexpr quint16 MonitorLast = MonitorRegisterCount - 1;
constexpr quint16 ParameterLastRegister = ParameterBaseRegister + ParameterCount - 1;

bool inMonitorBlock(int first, int last)
{
    return first >= 0 && last <= MonitorLast && first <= last;
}
bool inParameterBlock(int first, int last)
{
    return first >= ParameterBaseRegister && last <= ParameterLastRegister && first <= last;
}

qint64 pairFactor(PositionPairRule rule)
{
    switch (rule) {
    case PositionPairRule::Decimal10000: return 10000;
    case PositionPairRule::Decimal100000: return 100000;
    case PositionPairRule::BinaryWords: break;
    }
    return 65536;
}

qint64 floorDiv(qint64 a, qint64 b)
{
    qint64 q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0)))
        --q;
    return q;
}

} // namespace

QString translated(const char *sourceText)
{
    return QCoreApplication::translate(TranslationContext, sourceText);
}

// ---- DP monitor ----

const QList<MonitorRegister> &monitorRegisters()
{
    static const QList<MonitorRegister> table = {
        {0x00, "DP-SPd", QT_TRANSLATE_NOOP("dd::servomodbus", "Speed"), -1},
        {0x01, "DP-PoS", QT_TRANSLATE_NOOP("dd::servomodbus", "Position, low part"), 0x02},
        {0x02, "DP-PoS.", QT_TRANSLATE_NOOP("dd::servomodbus", "Position, high part"), -1},
        {0x03, "DP-CPo", QT_TRANSLATE_NOOP("dd::servomodbus", "Command position, low part"), 0x04},
        {0x04, "DP-CPo.", QT_TRANSLATE_NOOP("dd::servomodbus", "Command position, high part"), -1},
        {0x05, "DP-EPo", QT_TRANSLATE_NOOP("dd::servomodbus", "Position error, low part"), 0x06},
        {0x06, "DP-EPo.", QT_TRANSLATE_NOOP("dd::servomodbus", "Position error, high part"), -1},
        {0x07, "DP-trq", QT_TRANSLATE_NOOP("dd::servomodbus", "Torque"), -1},
        {0x08, "DP-I", QT_TRANSLATE_NOOP("dd::servomodbus", "Current"), -1},
        {0x09, "DP-LSP", "", -1},
        {0x0A, "DP-Cnt", "", -1},
        {0x0B, "DP-Frq", QT_TRANSLATE_NOOP("dd::servomodbus", "Pulse frequency"), -1},
        {0x0C, "DP-CS", QT_TRANSLATE_NOOP("dd::servomodbus", "Speed command"), -1},
        {0x0D, "DP-Ct", QT_TRANSLATE_NOOP("dd::servomodbus", "Torque command"), -1},
        {0x0E, "DP-APo", QT_TRANSLATE_NOOP("dd::servomodbus", "Rotor absolute position"), -1},
        {0x0F, "DP-In", QT_TRANSLATE_NOOP("dd::servomodbus", "Input terminals"), -1},
        {0x10, "DP-oUt", QT_TRANSLATE_NOOP("dd::servomodbus", "Output terminals"), -1},
        {0x11, "DP-Cod", QT_TRANSLATE_NOOP("dd::servomodbus", "Encoder signals"), -1},
        {0x12, "DP-m", "", -1},
        {0x13, "DP-Err", QT_TRANSLATE_NOOP("dd::servomodbus", "Alarm"), -1},
        {0x14, "DP-tL", "", -1},
        {0x15, "DP-IA", QT_TRANSLATE_NOOP("dd::servomodbus", "Phase A current"), -1},
        {0x16, "DP-IC", QT_TRANSLATE_NOOP("dd::servomodbus", "Phase C current"), -1},
        {0x17, "DP-rES", QT_TRANSLATE_NOOP("dd::servomodbus", "Reserved"), -1},
    };
    return table;
}

const MonitorRegister *monitorRegister(quint16 reg)
{
    const auto &t = monitorRegisters();
    return reg < t.size() ? &t[reg] : nullptr;
}

// ---- PA parameters and ranges ----

int parameterIndex(quint16 reg)
{
    return (reg >= ParameterBaseRegister && reg <= ParameterLastRegister) ? reg - ParameterBaseRegister : -1;
}

bool isReadableRange(quint16 start, int count)
{
    if (count < 1 || count > MaxRegistersPerRequest)
        return false;
    const int last = start + count - 1;
    return inMonitorBlock(start, last) || inParameterBlock(start, last);
}

bool isWritableRange(quint16 start, int count)
{
    if (count < 1 || count > MaxRegistersPerRequest)
        return false;
    return inParameterBlock(start, start + count - 1);
}

// ---- Planning ----

QList<RegisterRange> planRegisterReads(const QList<quint16> &registers, int maxPerRequest)
{
    const int maxCount = std::clamp(maxPerRequest, 1, MaxRegistersPerRequest);
    QList<int> regs;
    for (quint16 r : registers) {
        if (isReadableRange(r, 1))
            regs.append(r);
    }
    std::sort(regs.begin(), regs.end());
    regs.erase(std::unique(regs.begin(), regs.end()), regs.end());

    // best[i] = (requests, registers read) for regs[i..]; end[i] = last index of the first
    // request of that plan. Lexicographic minimum; ties go to the longer first request.
    const int n = static_cast<int>(regs.size());
    QList<std::pair<int, int>> best(n + 1, {0, 0});
    QList<int> end(n, 0);
    for (int i = n - 1; i >= 0; --i) {
        std::pair<int, int> b{std::numeric_limits<int>::max(), 0};
        for (int j = i; j < n; ++j) {
            const int span = regs[j] - regs[i] + 1;
            if (span > maxCount || !isReadableRange(static_cast<quint16>(regs[i]), span))
                break;
            const std::pair<int, int> c{1 + best[j + 1].first, span + best[j + 1].second};
            if (c <= b) {
                b = c;
                end[i] = j;
            }
        }
        best[i] = b;
    }
    QList<RegisterRange> plan;
    for (int i = 0; i < n; i = end[i] + 1)
        plan.append({static_cast<quint16>(regs[i]), static_cast<quint16>(regs[end[i]] - regs[i] + 1)});
    return plan;
}

QList<RegisterRange> planReads(const QList<int> &paIndices, int maxPerRequest)
{
    QList<quint16> regs;
    for (int n : paIndices) {
        if (isParameterIndex(n))
            regs.append(parameterRegister(n));
    }
    return planRegisterReads(regs, maxPerRequest);
}

QList<RegisterWrite> planWrites(const QMap<int, quint16> &paValues, int maxPerRequest)
{
    const int maxCount = std::clamp(maxPerRequest, 1, MaxRegistersPerRequest);
    QList<RegisterWrite> plan;
    int previous = -2;
    for (auto it = paValues.cbegin(); it != paValues.cend(); ++it) {
        const int n = it.key();
        if (!isParameterIndex(n))
            continue;
        if (plan.isEmpty() || n != previous + 1 || plan.last().values.size() >= maxCount)
            plan.append(RegisterWrite{parameterRegister(n), {}});
        plan.last().values.append(it.value());
        previous = n;
    }
    return plan;
}

// ---- EE operations ----

const QList<EeOp> &allEeOps()
{
    static const QList<EeOp> ops = {EeOp::Set, EeOp::Read, EeOp::Backup, EeOp::Restore, EeOp::Defaults};
    return ops;
}

std::optional<EeOp> eeOpFromCode(quint16 code)
{
    if (code >= 1 && code <= 5)
        return static_cast<EeOp>(code);
    return std::nullopt;
}

const char *eeOpMnemonic(EeOp op)
{
    switch (op) {
    case EeOp::Set: return "EE-Set";
    case EeOp::Read: return "EE-rd";
    case EeOp::Backup: return "EE-bA";
    case EeOp::Restore: return "EE-rS";
    case EeOp::Defaults: return "EE-dEF";
    }
    return "";
}

const char *eeOpMeaning(EeOp op)
{
    switch (op) {
    case EeOp::Set: return QT_TRANSLATE_NOOP("dd::servomodbus", "Store parameters to EEPROM");
    case EeOp::Read: return QT_TRANSLATE_NOOP("dd::servomodbus", "Reload parameters from EEPROM");
    case EeOp::Backup: return QT_TRANSLATE_NOOP("dd::servomodbus", "Back up parameters");
    case EeOp::Restore: return QT_TRANSLATE_NOOP("dd::servomodbus", "Restore the parameter backup");
    case EeOp::Defaults: return QT_TRANSLATE_NOOP("dd::servomodbus", "Restore factory defaults");
    }
    return "";
}

bool eeOpNeedsConfirmation(EeOp op)
{
    return op == EeOp::Read || op == EeOp::Restore || op == EeOp::Defaults;
}

EeFormat eeFormatForFirmware(quint16 pa2)
{
    return pa2 < FirstNewEeFirmware ? EeFormat::Legacy : EeFormat::New;
}

std::optional<EeFormat> chooseEeFormat(EeFormatChoice choice, std::optional<quint16> pa2)
{
    switch (choice) {
    case EeFormatChoice::Legacy: return EeFormat::Legacy;
    case EeFormatChoice::New: return EeFormat::New;
    case EeFormatChoice::Auto: break;
    }
    if (!pa2)
        return std::nullopt;
    return eeFormatForFirmware(*pa2);
}

QString eeFormatChoiceId(EeFormatChoice choice)
{
    switch (choice) {
    case EeFormatChoice::Legacy: return QStringLiteral("legacy");
    case EeFormatChoice::New: return QStringLiteral("new");
    case EeFormatChoice::Auto: break;
    }
    return QStringLiteral("auto");
}

std::optional<EeFormatChoice> eeFormatChoiceFromId(const QString &id)
{
    for (auto c : {EeFormatChoice::Auto, EeFormatChoice::Legacy, EeFormatChoice::New}) {
        if (id == eeFormatChoiceId(c))
            return c;
    }
    return std::nullopt;
}

modbusrtu::Request eeRequest(quint8 address, EeOp op, EeFormat format)
{
    modbusrtu::Request r;
    r.address = address;
    r.count = 1;
    r.values = {static_cast<quint16>(op)};
    if (format == EeFormat::Legacy) {
        r.function = modbusrtu::WriteSingleRegister;
        r.start = EeLegacyRegister;
    } else {
        r.function = modbusrtu::WriteMultipleRegisters;
        r.start = EeNewRegister;
    }
    return r;
}

QByteArray encodeEeRequest(quint8 address, EeOp op, EeFormat format)
{
    return modbusrtu::encodeRequest(eeRequest(address, op, format));
}

EeProgress interpretLegacyEeReply(quint16 value, EeOp op)
{
    if (value == 0)
        return EeProgress::Running;
    return value == static_cast<quint16>(op) ? EeProgress::Finished : EeProgress::Failed;
}

// ---- Position pairs ----

qint64 combinePositionPair(quint16 low, quint16 high, PositionPairRule rule)
{
    return static_cast<qint64>(static_cast<qint16>(high)) * pairFactor(rule) + low;
}

std::optional<RegisterPair> splitPosition(qint64 value, PositionPairRule rule)
{
    const qint64 f = pairFactor(rule);
    const qint64 high = floorDiv(value, f);
    const qint64 low = value - high * f;
    if (high < std::numeric_limits<qint16>::min() || high > std::numeric_limits<qint16>::max() || low > 0xFFFF)
        return std::nullopt;
    return RegisterPair{static_cast<quint16>(low), static_cast<quint16>(static_cast<qint16>(high))};
}

QString positionPairRuleId(PositionPairRule rule)
{
    switch (rule) {
    case PositionPairRule::Decimal10000: return QStringLiteral("decimal-10000");
    case PositionPairRule::Decimal100000: return QStringLiteral("decimal-100000");
    case PositionPairRule::BinaryWords: break;
    }
    return QStringLiteral("binary-words");
}

std::optional<PositionPairRule> positionPairRuleFromId(const QString &id)
{
    for (auto r : {PositionPairRule::BinaryWords, PositionPairRule::Decimal10000, PositionPairRule::Decimal100000}) {
        if (id == positionPairRuleId(r))
            return r;
    }
    return std::nullopt;
}

// ---- Validation ----

QString validateRequest(const modbusrtu::Request &r)
{
    using namespace modbusrtu;
    switch (r.function) {
    case ReadHoldingRegisters:
        if (r.address == BroadcastAddress)
            return QStringLiteral("a read to the broadcast address gets no reply");
        if (!isReadableRange(r.start, r.count))
            return QStringLiteral("cannot read %1 registers at %2 (1..20 within 0x0000..0x0017 or 0x0064..0x009F)")
                .arg(r.count)
                .arg(hexText(r.start, 4));
        return {};
    case WriteMultipleRegisters:
        if (r.values.size() != r.count)
            return QStringLiteral("%1 values for a count of %2").arg(r.values.size()).arg(r.count);
        if (r.start == EeNewRegister && r.count == 1) {
            if (!eeOpFromCode(r.values.first()))
                return QStringLiteral("EE operation code %1 is not 1..5").arg(r.values.first());
            return {};
        }
        if (!isWritableRange(r.start, r.count))
            return QStringLiteral("cannot write %1 registers at %2 (1..20 within 0x0064..0x009F)")
                .arg(r.count)
                .arg(hexText(r.start, 4));
        return {};
    case WriteSingleRegister:
        if (r.values.size() != 1)
            return QStringLiteral("function 0x06 carries exactly one value");
        if (r.start != EeLegacyRegister)
            return QStringLiteral("function 0x06 is only for EE operations at register 0x0000, not %1")
                .arg(hexText(r.start, 4));
        if (!eeOpFromCode(r.values.first()))
            return QStringLiteral("EE operation code %1 is not 1..5").arg(r.values.first());
        return {};
    default:
        return QStringLiteral("function 0x%1 is not supported by this drive").arg(r.function, 2, 16, QLatin1Char('0'));
    }
}

} // namespace dd::servomodbus
