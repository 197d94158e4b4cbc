#pragma once

#include "core/tuning/spectrum.h"
#include "core/tuning/tuningrun.h"

#include <QMap>
#include <QWidget>

class QComboBox;
class QLabel;

namespace dd {

class TrendPlot;

// The spectrum of one channel of the selected run (core Spectrum: Hann window, kissfft):
// amplitude over frequency on the trend's plot surface, the window and the resolution
// written on the plot's axis, the highest peaks listed beside it.
class SpectrumView : public QWidget
{
    Q_OBJECT
public:
    static constexpr int PeakCount = 5;

    explicit SpectrumView(QWidget *parent = nullptr);

    // The run whose channel is analysed (nullptr: none selected).
    void setRun(const TuningRun *run);
    void setChannel(const QString &channel);
    // Display names of channel ids (the drive's, translated); ids without one show as is.
    void setChannelNames(const QMap<QString, QString> &names);
    QString channel() const;
    const Spectrum &spectrum() const { return m_spectrum; }
    QString peaksText() const;
    TrendPlot *plot() const { return m_plot; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void recompute();
    void retranslate();

    TuningRun m_run;
    QMap<QString, QString> m_names;
    bool m_haveRun = false;
    Spectrum m_spectrum;
    QString m_error;
    QComboBox *m_channel = nullptr;
    QLabel *m_channelLabel = nullptr;
    TrendPlot *m_plot = nullptr;
    QLabel *m_peaks = nullptr;
};

} // namespace dd
