#include "sim/shuoke/simshuokecandevice.h"

#include <QCoreApplication>

#include "core/protocol/shuoke/shuokecan.h"

namespace dd {

using namespace shuoke;

namespace {
constexpr quint8 kCanMaxAddress = 250; // 251..255 仍然保留 (reserved)
} // namespace

SimShuokeCanDevice::SimShuokeCanDevice(const SimShuokeDrive::Config &config)
    : m_drive(config)
{
}

QList<CanFrameData> SimShuokeCanDevice::onCanFrame(const CanFrameData &frame, qint64 nowUs)
{
    advanceTo(nowUs);
    // The seed's filter: ID = first data byte = device address (1..250, 0 = broadcast,
    // 251..255 reserved) and CAN的数据长度 = 8. Anything else is not for the drive.
    if (frame.data.size() != kCanFrameBytes)
        return {};
    const Decoded<Frame> request = decodeCan(frame);
    if (!request.ok() || request.value->address > kCanMaxAddress)
        return {};
    const std::optional<Frame> reply = m_drive.handle(*request.value, SimShuokeDrive::Medium::Can, nowUs);
    if (!reply)
        return {};
    CanOptions options;
    options.extended = m_drive.config().canExtended;
    const Decoded<CanFrameData> out = encodeCan(*reply, options);
    if (!out.ok())
        return {};
    return {*out.value};
}

SimShuokeDrive &SimShuokeCanDevice::drive()
{
    if (m_clock)
        advanceTo(m_clock());
    return m_drive;
}

void SimShuokeCanDevice::powerCycle()
{
    m_drive.powerCycle(m_clock ? std::max(m_nowUs, m_clock()) : m_nowUs);
}

QList<CanFrameData> SimShuokeCanDevice::tick(qint64 nowUs)
{
    advanceTo(nowUs);
    return {};
}

QString SimShuokeCanDevice::describe() const
{
    return QStringLiteral("shuoke %1 addr %2 CAN").arg(modelName(m_drive.model())).arg(m_drive.address());
}

void SimShuokeCanDevice::advanceTo(qint64 nowUs)
{
    if (nowUs > m_nowUs)
        m_nowUs = nowUs;
    m_drive.advanceTo(nowUs);
}

std::unique_ptr<SimCanDevice> SimShuokeCanDevice::create(const SimDeviceSpec &spec, Error *error)
{
    if (!spec.framing.isEmpty() && spec.framing != QLatin1String("can")) {
        *error = {ErrorCode::InvalidArgument,
                  QCoreApplication::translate("dd::SimBench", "The shuoke %1 framing runs on RS232/RS485: use --pty.")
                      .arg(spec.framing)};
        return nullptr;
    }
    if (spec.address < 1 || spec.address > 250) {
        *error = {
            ErrorCode::InvalidArgument,
            QCoreApplication::translate("dd::SimBench", "A shuoke CAN address is 1..250, not %1.").arg(spec.address)};
        return nullptr;
    }
    SimShuokeDrive::Config c;
    c.address = static_cast<quint8>(spec.address);
    const int code = shuoke::canBitrateCodeFor(spec.bitrate);
    if (code > 0)
        c.canBitrateCode = code;
    auto device = std::make_unique<SimShuokeCanDevice>(c);
    device->setClock(spec.clock);
    return device;
}

} // namespace dd
