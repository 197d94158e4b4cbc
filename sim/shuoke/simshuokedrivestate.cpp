// SimShuokeDrive: state save / load for drivedesk-sim --state (see simshuokedrive.h).
#include "sim/shuoke/simshuokedrive.h"

#include <QJsonArray>
#include <cmath>

namespace dd {

using namespace shuoke;

namespace {

QString hexKey(quint8 command)
{
    return QStringLiteral("0x%1").arg(command, 2, 16, QLatin1Char('0'));
}

std::optional<Model> modelFromName(const QString &name)
{
    for (Model m : {Model::M6505, Model::M4505, Model::M4505S})
        if (name.compare(modelName(m), Qt::CaseInsensitive) == 0)
            return m;
    return std::nullopt;
}

} // namespace

QJsonObject SimShuokeDrive::saveState() const
{
    QJsonObject o;
    o.insert(QStringLiteral("family"), QStringLiteral("shuoke"));
    o.insert(QStringLiteral("model"), modelName(m_config.model));
    o.insert(QStringLiteral("address"), m_config.address);
    o.insert(QStringLiteral("baudCode"), m_config.baudCode);
    o.insert(QStringLiteral("canBitrateCode"), m_config.canBitrateCode);
    o.insert(QStringLiteral("canExtended"), m_config.canExtended);
    o.insert(QStringLiteral("byteOrder"),
             m_config.byteOrder == ByteOrder::BigEndian ? QStringLiteral("big") : QStringLiteral("little"));
    QJsonArray broadcasts;
    for (quint8 b : m_config.broadcasts)
        broadcasts.append(b);
    o.insert(QStringLiteral("broadcasts"), broadcasts);
    o.insert(QStringLiteral("plcBase"), m_config.plcBase);
    o.insert(QStringLiteral("powerUpWindowMs"), m_config.powerUpWindowMs);
    o.insert(QStringLiteral("minCommandGapMs"), m_config.minCommandGapMs);
    o.insert(QStringLiteral("enableInput"), m_config.enableInput);
    o.insert(QStringLiteral("inputs"), m_config.inputs);
    o.insert(QStringLiteral("controlInputs"), m_config.controlInputs);
    if (m_pendingAddress)
        o.insert(QStringLiteral("pendingAddress"), *m_pendingAddress);
    QJsonObject settings;
    for (auto it = m_settings.cbegin(); it != m_settings.cend(); ++it)
        settings.insert(hexKey(it.key()), static_cast<double>(it.value()));
    o.insert(QStringLiteral("settings"), settings);
    QJsonObject io;
    for (auto it = m_ioSubstitution.cbegin(); it != m_ioSubstitution.cend(); ++it)
        io.insert(QString::number(it.key()), QString::fromLatin1(it.value().toHex()));
    o.insert(QStringLiteral("ioSubstitution"), io);
    o.insert(QStringLiteral("axis"), m_axis.save());
    return o;
}

bool SimShuokeDrive::loadState(const QJsonObject &state, QString *error)
{
    auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (state.value(QStringLiteral("family")).toString(QStringLiteral("shuoke")) != QLatin1String("shuoke"))
        return fail(QStringLiteral("state is not of a shuoke drive"));
    Config c = m_config;
    if (state.contains(QStringLiteral("model"))) {
        const auto m = modelFromName(state.value(QStringLiteral("model")).toString());
        if (!m)
            return fail(QStringLiteral("unknown model \"%1\"").arg(state.value(QStringLiteral("model")).toString()));
        c.model = *m;
    }
    const int address = state.value(QStringLiteral("address")).toInt(c.address);
    if (!isUnicastAddress(address))
        return fail(QStringLiteral("address %1 is not 1..247").arg(address));
    c.address = static_cast<quint8>(address);
    c.baudCode = state.value(QStringLiteral("baudCode")).toInt(c.baudCode);
    if (!isUsableBaudCode(c.baudCode))
        return fail(QStringLiteral("baud code %1 is not 1..8").arg(c.baudCode));
    c.canBitrateCode = state.value(QStringLiteral("canBitrateCode")).toInt(c.canBitrateCode);
    if (!canBitrateForCode(c.canBitrateCode))
        return fail(QStringLiteral("CAN bitrate code %1 is not 1..18").arg(c.canBitrateCode));
    c.canExtended = state.value(QStringLiteral("canExtended")).toBool(c.canExtended);
    const QString order = state.value(QStringLiteral("byteOrder")).toString(QStringLiteral("little"));
    if (order != QLatin1String("little") && order != QLatin1String("big"))
        return fail(QStringLiteral("byteOrder must be little or big"));
    c.byteOrder = order == QLatin1String("big") ? ByteOrder::BigEndian : ByteOrder::LittleEndian;
    if (state.contains(QStringLiteral("broadcasts"))) {
        c.broadcasts.clear();
        for (const QJsonValue &v : state.value(QStringLiteral("broadcasts")).toArray())
            c.broadcasts.append(static_cast<quint8>(v.toInt()));
    }
    c.plcBase = static_cast<quint16>(state.value(QStringLiteral("plcBase")).toInt(c.plcBase));
    c.powerUpWindowMs = state.value(QStringLiteral("powerUpWindowMs")).toInt(c.powerUpWindowMs);
    c.minCommandGapMs = state.value(QStringLiteral("minCommandGapMs")).toInt(c.minCommandGapMs);
    c.enableInput = state.value(QStringLiteral("enableInput")).toBool(c.enableInput);
    c.inputs = static_cast<quint8>(state.value(QStringLiteral("inputs")).toInt(c.inputs));
    c.controlInputs = static_cast<quint8>(state.value(QStringLiteral("controlInputs")).toInt(c.controlInputs));

    m_config = c;
    m_axis.setClosedLoop(c.model == Model::M6505);
    resetSettings();
    const QJsonObject settings = state.value(QStringLiteral("settings")).toObject();
    for (auto it = settings.begin(); it != settings.end(); ++it) {
        bool ok = false;
        const uint code = it.key().toUInt(&ok, 0);
        if (!ok || code > 0xFF || !commandInfo(static_cast<quint8>(code)))
            return fail(QStringLiteral("settings: \"%1\" is not a command code").arg(it.key()));
        setSetting(static_cast<quint8>(code), static_cast<qint64>(std::llround(it.value().toDouble())));
    }
    m_config.baudCode = static_cast<int>(m_settings.value(CmdSetBaudCode, c.baudCode));
    const QJsonObject io = state.value(QStringLiteral("ioSubstitution")).toObject();
    for (auto it = io.begin(); it != io.end(); ++it)
        m_ioSubstitution.insert(it.key().toInt(), QByteArray::fromHex(it.value().toString().toLatin1()));
    m_pendingAddress.reset();
    if (state.contains(QStringLiteral("pendingAddress")))
        m_pendingAddress = static_cast<quint8>(state.value(QStringLiteral("pendingAddress")).toInt());
    m_axis.load(state.value(QStringLiteral("axis")).toObject());
    m_axis.setPowered(c.enableInput);
    return true;
}

} // namespace dd
