#include "ui/panels/trend/trendpanel.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/driveresult.h"
#include "core/protocol/familytraits.h"
#include "core/trend/linkrate.h"
#include "core/trend/trendrecorder.h"
#include "ui/bus/driveinfo.h"
#include "ui/panels/trend/trendview.h"

#include <QDateTime>
#include <QLabel>
#include <QPointer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <memory>

namespace dd {

namespace {

// Sample times on the drives' clock (µs since the epoch) when a reply has none, and for gaps.
qint64 nowUs()
{
    return QDateTime::currentMSecsSinceEpoch() * 1000;
}

} // namespace

TrendPanel::TrendPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
    , m_recorder(new TrendRecorder(this))
{
    m_view = new TrendView(m_recorder, this);
    m_view->setSampleRate(m_defaultRateHz);
    m_unavailable = new QLabel(this);
    m_unavailable->setAlignment(Qt::AlignCenter);
    m_unavailable->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_unavailable);
    layout->addWidget(m_view, 1);

    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &TrendPanel::sample);
    connect(m_view, &TrendView::sampleRateChanged, this, [this](double hz) {
        m_userRate = true;
        setRate(hz);
    });
    connect(m_view, &TrendView::recordToggled, this, &TrendPanel::setRecording);
    connect(m_view, &TrendView::fileWritten, this, &DrivePanel::fileUsed);
    setRate(m_defaultRateHz);
    retranslate();
    updateState();
}

TrendPanel::~TrendPanel() = default;

QString TrendPanel::title() const
{
    return tr("Trend");
}

void TrendPanel::setRate(double hz)
{
    m_timer.setInterval(qMax(1, int(1000.0 / qMax(0.1, hz))));
}

double TrendPanel::rateForReadUs(double readUs)
{
    return LinkRate::forReadUs(readUs, FallbackRateHz); // the CLI's monitor uses the same
}

void TrendPanel::setRecording(bool recording)
{
    m_started = m_started || recording;
    if (recording == m_recording) {
        m_view->setRecording(recording);
        return;
    }
    m_recording = recording;
    ++m_run;
    m_inFlight = false;
    if (!recording)
        markGap(); // a later recording must not join this one with a ramp
    m_view->setRecording(recording);
    updateState();
}

void TrendPanel::markGap()
{
    m_recorder->appendGap(nowUs());
}

void TrendPanel::activeChanged(bool active)
{
    // The first look at the tab starts the recording; after that only the user stops it.
    if (active && !m_started && m_channelsSet && driveInfo().capabilities.testFlag(Capability::Monitor))
        setRecording(true);
    updateState();
}

void TrendPanel::driveInfoChanged(const DriveInfo &info)
{
    if (!m_channelsSet && !info.channels.isEmpty()) {
        m_recorder->setChannels(TrendChannel::fromInfos(info.channels));
        // A readable plot to start with: the usual tuning quantities, else the first three.
        const QStringList preferred{QStringLiteral("speed"), QStringLiteral("torque"), QStringLiteral("current")};
        QStringList shown;
        for (const ChannelInfo &c : info.channels)
            if (preferred.contains(c.id))
                shown << c.id;
        for (int i = 0; shown.isEmpty() && i < qMin<qsizetype>(3, info.channels.size()); ++i)
            shown << info.channels.at(i).id;
        for (const ChannelInfo &c : info.channels)
            m_view->setChannelVisible(c.id, shown.contains(c.id));
        m_channelsSet = true;
    } else if (m_channelsSet) {
        for (const ChannelInfo &c : info.channels) // names follow the language
            m_recorder->addChannel(TrendChannel::fromInfo(c));
    }
    updateDriveTitle();
    activeChanged(isActive());
}

void TrendPanel::updateDriveTitle()
{
    const DriveInfo &info = driveInfo();
    QString title = tr("%1, address %2").arg(familyTraits(context().family).displayName()).arg(context().address);
    if (!info.identity.model.isEmpty())
        title += QStringLiteral(", ") + info.identity.model;
    if (!info.identity.link.isEmpty())
        title += QStringLiteral(" (") + info.identity.link + QLatin1Char(')');
    m_view->setDriveTitle(title);
}

void TrendPanel::updateState()
{
    const bool capable = driveInfo().capabilities.testFlag(Capability::Monitor);
    const bool ready = capable && m_channelsSet;
    m_view->setVisible(ready);
    m_unavailable->setVisible(!ready);
    if (!driveInfo().valid)
        m_unavailable->setText(tr("Reading the drive's identity…"));
    else if (!capable)
        m_unavailable->setText(tr("This drive offers no live values: %1").arg(driveInfo().reason(Capability::Monitor)));
    else if (!m_channelsSet)
        m_unavailable->setText(tr("This drive reports no live channels."));
    // Recording does not depend on the tab or the drive shown (isActive()).
    if (ready && m_recording) {
        if (!m_timer.isActive())
            m_timer.start();
    } else {
        m_timer.stop();
    }
}

QStringList TrendPanel::channelsToRead() const
{
    QStringList ids;
    for (const QString &id : m_recorder->channelIds())
        if (m_view->isChannelVisible(id))
            ids << id;
    return ids;
}

void TrendPanel::sample()
{
    if (m_inFlight || !context().isValid() || !m_recording)
        return; // the link is slower than the rate: skip rather than queue
    const QStringList ids = channelsToRead();
    if (ids.isEmpty())
        return;
    m_inFlight = true;
    QPointer<TrendPanel> self(this);
    const quint64 run = m_run;
    // The first reading also asks what the link carries (on the I/O thread, where the drive
    // lives; read here only after the reply, which the hub's queued callback orders).
    auto readUs = std::make_shared<double>(0.0);
    const bool askRate = !m_rateKnown;
    context().hub->run(
        context().connectionId, context().address,
        [ids, readUs, askRate](Drive &d) {
            if (askRate)
                *readUs = d.channelReadUs(ids);
            return d.readChannels(ids);
        },
        [self, run, readUs](const DriveResult &r) {
            if (!self)
                return;
            if (*readUs > 0.0 && !self->m_rateKnown) {
                self->m_rateKnown = true;
                self->m_defaultRateHz = rateForReadUs(*readUs);
                if (!self->m_userRate) {
                    self->setRate(self->m_defaultRateHz);
                    self->m_view->setSampleRate(self->m_defaultRateHz);
                }
            }
            if (run != self->m_run)
                return; // stopped (or restarted) since: not this recording's sample
            self->m_inFlight = false;
            if (!r.ok()) {
                // Link lost or drive silent: a gap, drawn and exported as such.
                self->markGap();
                if (!self->m_failing) // once per outage, not at the sample rate
                    self->reportResult(r);
                self->m_failing = true;
                return;
            }
            self->m_failing = false;
            // The drive's time stamp when it gives one (µs since the epoch), else ours.
            const qint64 t = r.sampleTimeUs > 0 ? r.sampleTimeUs : nowUs();
            self->m_recorder->appendSamples(t, r.samples);
        });
}

void TrendPanel::refreshChannelNames()
{
    if (!context().isValid() || !m_channelsSet)
        return;
    // Channel names come from the drive, translated when read: read them again.
    QPointer<TrendPanel> self(this);
    fetchDriveInfo(context().hub, context().connectionId, context().address,
                   [self](const DriveInfo &info, const Error &) {
                       if (!self) // the channels are known even when the identity read fails
                           return;
                       for (const ChannelInfo &c : info.channels)
                           self->m_recorder->addChannel(TrendChannel::fromInfo(c));
                   });
}

void TrendPanel::retranslate()
{
    updateState();
    updateDriveTitle();
    refreshChannelNames();
}

} // namespace dd
