#pragma once

#include "sim/bench/simfamilies.h"
#include "sim/bus/simcandevice.h"
#include "sim/shuoke/simshuokedrive.h"

#include <functional>

namespace dd {

// A simulated Shuoke drive on a CAN bus (SimCanBus): frames with identifier = its address
// or 0 (broadcast), data = [addr][cmd][len][data] zero-padded to 8 bytes. Replies carry
// the drive's address as identifier, in the frame format the drive is configured for
// (0x4A: extended frames, identifier = address). The drive sends nothing on its own.
class SimShuokeCanDevice : public SimCanDevice
{
public:
    explicit SimShuokeCanDevice(const SimShuokeDrive::Config &config = {});

    QList<CanFrameData> onCanFrame(const CanFrameData &frame, qint64 nowUs) override;
    QList<CanFrameData> tick(qint64 nowUs) override;
    QString describe() const override;
    void advanceTo(qint64 nowUs) override;

    // The bus clock (SimCanBus::nowUs): drive() then brings the drive up to date.
    void setClock(std::function<qint64()> nowUs) { m_clock = std::move(nowUs); }
    // The family's CAN entry in the simulator table (sim/bench/simfamilies.h).
    static std::unique_ptr<SimCanDevice> create(const SimDeviceSpec &spec, Error *error);
    SimShuokeDrive &drive();
    const SimShuokeDrive &drive() const { return m_drive; }
    void powerCycle();

private:
    SimShuokeDrive m_drive;
    std::function<qint64()> m_clock;
    qint64 m_nowUs = 0;
};

} // namespace dd
