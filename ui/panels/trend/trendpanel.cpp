#include "ui/panels/trend/trendpanel.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/driveresult.h"
#include "core/trend/trendrecorder.h"
#include "ui/panels/trend/trendview.h"

#include <QLabel>
#include <QPointer>
#include <QScrollArea>
#include <QVBoxLayout>

namespace dd {

TrendPanel::TrendPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
    , m_recorder(new TrendRecorder(this))
{
    m_view = new TrendView(m_recorder, this);
    m_view->setSampleRate(DefaultRateHz);
    m_unavailable = new QLabel(this);
    m_unavailable->setAlignment(Qt::AlignCenter);
    m_unavailable->setWordWrap(true);
    // The view's minimum width (plot + channel list) must not squeeze the bus tree on every
    // tab: in a narrow window the trend scrolls instead.
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(m_view);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_unavailable);
    layout->addWidget(scroll, 1);
    m_scroll = scroll;

    m_clock.start();
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &TrendPanel::sample);
    connect(m_view, &TrendView::sampleRateChanged, this, &TrendPanel::setRate);
    setRate(DefaultRateHz);
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

void TrendPanel::activeChanged(bool)
{
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
    }
    updateState();
}

void TrendPanel::updateState()
{
    const bool capable = driveInfo().capabilities.testFlag(Capability::Monitor);
    const bool ready = capable && m_channelsSet;
    m_scroll->setVisible(ready);
    m_unavailable->setVisible(!ready);
    if (!driveInfo().valid)
        m_unavailable->setText(tr("Reading the drive's identity…"));
    else if (!capable)
        m_unavailable->setText(tr("This drive offers no live values: %1").arg(driveInfo().reason(Capability::Monitor)));
    else if (!m_channelsSet)
        m_unavailable->setText(tr("This drive reports no live channels."));
    if (ready && isActive())
        m_timer.start();
    else
        m_timer.stop();
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
    if (m_inFlight || !context().isValid())
        return; // the link is slower than the rate: skip rather than queue
    const QStringList ids = channelsToRead();
    if (ids.isEmpty())
        return;
    m_inFlight = true;
    QPointer<TrendPanel> self(this);
    context().hub->run(
        context().connectionId, context().address, [ids](Drive &d) { return d.readChannels(ids); },
        [self](const DriveResult &r) {
            if (!self)
                return;
            self->m_inFlight = false;
            if (!r.ok()) {
                if (!self->m_failing) // once per outage, not at the sample rate
                    self->reportResult(r);
                self->m_failing = true;
                return;
            }
            self->m_failing = false;
            // The drive's time stamp when it gives one (µs since the epoch), else ours.
            const qint64 t = r.sampleTimeUs > 0 ? r.sampleTimeUs : self->m_clock.nsecsElapsed() / 1000;
            self->m_recorder->appendSamples(t, r.samples);
        });
}

void TrendPanel::retranslate()
{
    updateState();
}

} // namespace dd
