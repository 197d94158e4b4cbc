#pragma once

#include "core/tuning/capturedata.h"

#include <QCoreApplication>
#include <QList>
#include <QVector>

namespace dd {

// The amplitude spectrum of one channel of a capture (docs/tuning.md). The samples,
// timestamped by arrival, are first put on a uniform grid at their mean interval (linear
// interpolation; across a gap too, which `notes` then says), the mean is removed, a Hann
// window applied and a real FFT taken (Debian's libkissfft). Resolution: 1 / (N · dt).
struct Spectrum
{
    Q_DECLARE_TR_FUNCTIONS(dd::Spectrum)

public:
    struct Peak
    {
        double hz = 0.0;
        double magnitude = 0.0; // amplitude, in the channel's unit
    };

    QVector<double> hz;        // bin frequencies, 0 .. Nyquist
    QVector<double> magnitude; // amplitude per bin
    double sampleRate = 0.0;   // Hz, of the uniform grid
    double resolutionHz = 0.0;
    int points = 0; // N
    QString window = QStringLiteral("Hann");
    QList<Peak> peaks; // the highest local maxima, highest first
    QStringList notes;

    bool isEmpty() const { return hz.isEmpty(); }
    // Fails (empty result, *error) with fewer than 16 finite samples or an unknown channel.
    // Peaks are looked for at `fromHz` and above (0: everywhere but the first two bins).
    static Spectrum compute(const CaptureData &capture, const QString &channel, int peakCount, QString *error,
                            double fromHz = 0.0);
    // The same from plain arrays (times in seconds, values; NaN skipped).
    static Spectrum compute(const QVector<double> &time, const QVector<double> &values, int peakCount, QString *error,
                            double fromHz = 0.0);
};

} // namespace dd
