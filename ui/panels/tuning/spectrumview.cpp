#include "ui/panels/tuning/spectrumview.h"

#include "ui/panels/trend/trendplot.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>

namespace dd {

SpectrumView::SpectrumView(QWidget *parent)
    : QWidget(parent)
    , m_channel(new QComboBox(this))
    , m_channelLabel(new QLabel(this))
    , m_plot(new TrendPlot(this))
    , m_peaks(new QLabel(this))
{
    m_channel->setObjectName(QStringLiteral("spectrumChannel"));
    m_plot->setObjectName(QStringLiteral("spectrumPlot"));
    m_plot->setMinimumSize(200, 120);
    m_peaks->setObjectName(QStringLiteral("spectrumPeaks"));
    m_peaks->setWordWrap(true);
    m_peaks->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_peaks->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_peaks->setMinimumWidth(120);
    m_peaks->setMaximumWidth(200);
    auto *top = new QHBoxLayout;
    top->addWidget(m_channelLabel);
    top->addWidget(m_channel, 1);
    auto *body = new QHBoxLayout;
    body->addWidget(m_plot, 1);
    body->addWidget(m_peaks);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addLayout(body, 1);
    connect(m_channel, &QComboBox::currentIndexChanged, this, &SpectrumView::recompute);
    retranslate();
}

void SpectrumView::setRun(const TuningRun *run)
{
    const QString keep = channel();
    m_haveRun = run != nullptr;
    m_run = run ? *run : TuningRun{};
    const QSignalBlocker block(m_channel);
    m_channel->clear();
    for (const QString &c : m_run.capture.channels)
        m_channel->addItem(m_names.value(c, c), c);
    int i = m_channel->findData(keep.isEmpty() ? QStringLiteral("speed") : keep);
    m_channel->setCurrentIndex(i >= 0 ? i : 0);
    recompute();
}

void SpectrumView::setChannelNames(const QMap<QString, QString> &names)
{
    if (names == m_names)
        return;
    m_names = names;
    for (int i = 0; i < m_channel->count(); ++i) {
        const QString id = m_channel->itemData(i).toString();
        m_channel->setItemText(i, m_names.value(id, id));
    }
    retranslate();
}

void SpectrumView::setChannel(const QString &channel)
{
    const int i = m_channel->findData(channel);
    if (i >= 0)
        m_channel->setCurrentIndex(i);
}

QString SpectrumView::channel() const
{
    return m_channel->currentData().toString();
}

QString SpectrumView::peaksText() const
{
    return m_peaks->text();
}

void SpectrumView::recompute()
{
    m_spectrum = Spectrum{};
    m_error.clear();
    if (m_haveRun && !channel().isEmpty())
        m_spectrum = Spectrum::compute(m_run.capture, channel(), PeakCount, &m_error);
    retranslate();
}

void SpectrumView::retranslate()
{
    m_channelLabel->setText(tr("Channel:"));
    if (m_spectrum.isEmpty()) {
        m_plot->setGreyedFrom(std::nullopt);
        m_plot->setSeries({});
        m_plot->setTimeTitle(tr("Frequency (Hz)"));
        m_peaks->setText(!m_haveRun ? tr("Select a run to see its spectrum.") : tr("No spectrum: %1").arg(m_error));
        return;
    }
    m_plot->setTimeTitle(tr("Frequency (Hz) · %1 window, resolution %2 Hz, %3 points at %4 Hz, Nyquist %5 Hz")
                             .arg(m_spectrum.window)
                             .arg(m_spectrum.resolutionHz, 0, 'g', 3)
                             .arg(m_spectrum.points)
                             .arg(m_spectrum.sampleRate, 0, 'f', 0)
                             .arg(m_spectrum.nyquistHz, 0, 'f', 1));
    TrendPlot::Series s;
    s.id = QStringLiteral("spectrum");
    s.label = tr("Amplitude of %1").arg(m_names.value(channel(), channel()));
    s.color = QColor(0x1f, 0x77, 0xb4);
    double top = 0.0;
    for (int i = 0; i < m_spectrum.hz.size(); ++i) {
        s.points.append(QPointF(m_spectrum.hz.at(i), m_spectrum.magnitude.at(i)));
        top = std::max(top, m_spectrum.magnitude.at(i));
    }
    m_plot->setTimeRange(0.0, std::max(1.0, m_spectrum.hz.isEmpty() ? 1.0 : m_spectrum.hz.last()));
    TrendPlot::ValueAxis axis;
    axis.used = true;
    axis.min = 0.0;
    axis.max = top > 0.0 ? top * 1.05 : 1.0;
    axis.title = tr("Amplitude");
    m_plot->setValueAxis(TrendPlot::Left, axis);
    m_plot->setSeries({s});
    // Above the usable band (90 % of Nyquist) the spectrum cannot place a peak: greyed.
    m_plot->setGreyedFrom(m_spectrum.usableToHz);
    QStringList lines{tr("Peaks:")};
    for (const Spectrum::Peak &p : m_spectrum.peaks) {
        if (p.aliasOfHz > 0.0)
            lines << tr("%1 Hz (%2) — may be an alias of %3 Hz")
                         .arg(p.hz, 0, 'f', 1)
                         .arg(p.magnitude, 0, 'g', 3)
                         .arg(p.aliasOfHz, 0, 'f', 1);
        else if (p.nearNyquist)
            lines << tr("%1 Hz (%2) — near the Nyquist frequency").arg(p.hz, 0, 'f', 1).arg(p.magnitude, 0, 'g', 3);
        else
            lines << tr("%1 Hz (%2)").arg(p.hz, 0, 'f', 1).arg(p.magnitude, 0, 'g', 3);
    }
    for (const QString &n : m_spectrum.notes)
        lines << n;
    m_peaks->setText(lines.join(QLatin1Char('\n')));
}

void SpectrumView::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslate();
}

} // namespace dd
