#include "ui/panels/tuning/hubcapture.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/driveresult.h"

#include <QPointer>
#include <cmath>

namespace dd {

HubCapture::HubCapture(DriveHub *hub, int connectionId, int address, QObject *parent)
    : QObject(parent)
    , m_hub(hub)
    , m_connectionId(connectionId)
    , m_address(address)
{
}

void HubCapture::start(const CaptureSettings &settings, const QStringList &channels)
{
    m_settings = settings;
    m_channels = channels;
    ++m_generation;
    m_inFlight = 0;
    m_clock.start();
    m_recorder.arm(settings, channels);
    m_running = true;
    emit stateChanged();
    readNext();
}

void HubCapture::stop()
{
    if (!m_running)
        return;
    m_running = false;
    ++m_generation;
    m_inFlight = 0;
    m_recorder.reset();
    emit stateChanged();
}

void HubCapture::forceTrigger(const QString &source)
{
    if (!m_running)
        return;
    m_recorder.trigger(now(), source);
    emit stateChanged();
}

void HubCapture::alarmRaised()
{
    if (m_running && m_settings.trigger.kind == TriggerSpec::Kind::Alarm)
        forceTrigger(QStringLiteral("alarm"));
}

void HubCapture::readNext()
{
    if (!m_running || m_inFlight >= MaxInFlight || !m_hub)
        return;
    ++m_inFlight;
    QPointer<HubCapture> self(this);
    const quint64 generation = m_generation;
    const QStringList ids = m_channels;
    m_hub->run(
        m_connectionId, m_address, [ids](Drive &d) { return d.readChannels(ids); },
        [self, generation](const DriveResult &r) {
            if (!self || generation != self->m_generation)
                return;
            --self->m_inFlight;
            if (!self->m_running)
                return; // the capture ended (done, or failed) while this read was on its way
            if (!r.ok()) {
                self->m_running = false;
                self->m_recorder.reset();
                emit self->stateChanged();
                emit self->failed(r.error);
                return;
            }
            const double t = self->now();
            QVector<double> row;
            row.reserve(self->m_channels.size());
            for (const QString &c : std::as_const(self->m_channels))
                row.append(r.samples.value(c, std::nan("")));
            const CaptureRecorder::State before = self->m_recorder.state();
            if (self->m_recorder.feed(t, row)) {
                const CaptureData data = self->m_recorder.take();
                if (self->m_settings.mode == CaptureSettings::Mode::Normal)
                    self->m_recorder.arm(self->m_settings, self->m_channels);
                else
                    self->m_running = false;
                emit self->stateChanged();
                emit self->captured(data);
                if (!self)
                    return;
            } else if (self->m_recorder.state() != before) {
                emit self->stateChanged();
            }
            self->readNext();
        });
    readNext(); // the second read in flight
}

} // namespace dd
