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
//
// What it cannot see (issue 26): nothing above the Nyquist frequency (half the grid's
// rate), and whatever is there folds back below it. Every spectrum states nyquistHz and its
// usable band (usableFromHz: two bins; usableToHz: 90 % of Nyquist) in its first note.
// A peak within 10 % of Nyquist is marked nearNyquist. A peak is marked as a possible alias
// (aliasOfHz) when the samples, at their own (irregular) times, fit a frequency above
// Nyquist that would fold onto it (k · rate ± f, k = 1, 2, searched ± 10 % of the rate) as
// well as the peak's own frequency (within 1 %) or better: with perfectly even sampling the two cannot be
// told apart (so it is marked), with the jitter of real arrival times the true one fits best.
struct Spectrum
{
    Q_DECLARE_TR_FUNCTIONS(dd::Spectrum)

public:
    struct Peak
    {
        double hz = 0.0;
        double magnitude = 0.0;   // amplitude, in the channel's unit
        bool nearNyquist = false; // within 10 % of the Nyquist frequency: not a reliable frequency
        double aliasOfHz = 0.0;   // > 0: may be the alias of this frequency above Nyquist

        bool isSuspect() const { return nearNyquist || aliasOfHz > 0.0; }
    };

    QVector<double> hz;        // bin frequencies, 0 .. Nyquist
    QVector<double> magnitude; // amplitude per bin
    double sampleRate = 0.0;   // Hz, of the uniform grid
    double resolutionHz = 0.0;
    double nyquistHz = 0.0;    // sampleRate / 2
    double usableFromHz = 0.0; // the band whose peaks the spectrum can place: two bins ...
    double usableToHz = 0.0;   // ... to 90 % of Nyquist
    int points = 0;            // N
    QString window = QStringLiteral("Hann");
    QList<Peak> peaks; // the highest local maxima, highest first
    QStringList notes;

    bool isEmpty() const { return hz.isEmpty(); }
    // Fails (empty result, *error) with fewer than 16 finite samples or an unknown channel.
    // Peaks are looked for at `fromHz` and above (0: everywhere but the first two bins).
    static Spectrum compute(const CaptureData &capture, const QString &channel, int peakCount, QString *error,
                            double fromHz = 0.0);
    // Only the samples from t1 to t2 (seconds from the trigger); the capture's gaps inside
    // that stretch are noted as above.
    static Spectrum compute(const CaptureData &capture, const QString &channel, int peakCount, QString *error,
                            double fromHz, double t1, double t2);
    // The same from plain arrays (times in seconds, values; NaN skipped).
    static Spectrum compute(const QVector<double> &time, const QVector<double> &values, int peakCount, QString *error,
                            double fromHz = 0.0);
};

} // namespace dd
