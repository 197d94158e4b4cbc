#include "core/tuning/spectrum.h"
#include "core/common/mathconstants.h"

#include <kiss_fftr.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace dd {

namespace {
}

Spectrum Spectrum::compute(const CaptureData &capture, const QString &channel, int peakCount, QString *error,
                           double fromHz)
{
    const int col = capture.columnOf(channel);
    if (col < 0) {
        *error = tr("channel %1 is not in the capture (it has %2)")
                     .arg(channel, capture.channels.join(QStringLiteral(", ")));
        return {};
    }
    Spectrum s = compute(capture.time, capture.columns.at(col), peakCount, error, fromHz);
    if (!capture.gaps.isEmpty() && !s.isEmpty())
        s.notes << tr("%n gap(s) in the capture were bridged by interpolation", nullptr, int(capture.gaps.size()));
    return s;
}

Spectrum Spectrum::compute(const CaptureData &capture, const QString &channel, int peakCount, QString *error,
                           double fromHz, double t1, double t2)
{
    const int col = capture.columnOf(channel);
    if (col < 0) {
        *error = tr("channel %1 is not in the capture (it has %2)")
                     .arg(channel, capture.channels.join(QStringLiteral(", ")));
        return {};
    }
    const QVector<double> &column = capture.columns.at(col);
    QVector<double> time, values;
    for (int i = 0; i < capture.time.size() && i < column.size(); ++i)
        if (capture.time.at(i) >= t1 && capture.time.at(i) <= t2) {
            time << capture.time.at(i);
            values << column.at(i);
        }
    Spectrum s = compute(time, values, peakCount, error, fromHz);
    int gaps = 0;
    for (const CaptureGap &g : capture.gaps)
        if (g.to > t1 && g.from < t2)
            ++gaps;
    if (gaps > 0 && !s.isEmpty())
        s.notes << tr("%n gap(s) in the capture were bridged by interpolation", nullptr, gaps);
    return s;
}

namespace {

// The amplitude of frequency f in samples taken at irregular times (a direct Fourier sum
// with a Hann window over the span): what a sine of that frequency would need to be to
// explain the samples, at their own times rather than on the uniform grid.
double amplitudeAt(const std::vector<double> &t, const std::vector<double> &v, const std::vector<double> &w,
                   double wSum, double f)
{
    double re = 0.0, im = 0.0;
    for (size_t i = 0; i < t.size(); ++i) {
        const double ph = 2.0 * Pi * f * t[i];
        re += w[i] * v[i] * std::cos(ph);
        im -= w[i] * v[i] * std::sin(ph);
    }
    return 2.0 * std::hypot(re, im) / wSum;
}

// The best fit (frequency, amplitude) from `from` to `to` in steps of `step`.
std::pair<double, double> bestFit(const std::vector<double> &t, const std::vector<double> &v,
                                  const std::vector<double> &w, double wSum, double from, double to, double step)
{
    std::pair<double, double> best{from, -1.0};
    for (double f = from; f <= to; f += step) {
        const double a = amplitudeAt(t, v, w, wSum, f);
        if (a > best.second)
            best = {f, a};
    }
    // Refined around the best step (golden-section search): the two fits compared must
    // not differ by where the steps happened to fall.
    double lo = best.first - step, hi = best.first + step;
    constexpr double g = 0.6180339887498949;
    for (int i = 0; i < 24; ++i) {
        const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
        if (amplitudeAt(t, v, w, wSum, x1) < amplitudeAt(t, v, w, wSum, x2))
            lo = x1;
        else
            hi = x2;
    }
    const double f = 0.5 * (lo + hi), a = amplitudeAt(t, v, w, wSum, f);
    if (a > best.second)
        best = {f, a};
    return best;
}

} // namespace

Spectrum Spectrum::compute(const QVector<double> &time, const QVector<double> &values, int peakCount, QString *error,
                           double fromHz)
{
    QVector<double> t, v;
    for (int i = 0; i < time.size() && i < values.size(); ++i) {
        if (std::isfinite(values.at(i)) && std::isfinite(time.at(i))) {
            t.append(time.at(i));
            v.append(values.at(i));
        }
    }
    if (t.size() < 16 || t.last() <= t.first()) {
        *error = tr("a spectrum needs at least 16 samples over a time span");
        return {};
    }
    Spectrum s;
    const double dt = (t.last() - t.first()) / double(t.size() - 1);
    int n = int(t.size());
    n -= n % 2; // kiss_fftr wants an even length
    // Uniform grid by linear interpolation.
    std::vector<float> grid(static_cast<size_t>(n), 0.0f);
    int j = 0;
    double mean = 0.0;
    std::vector<double> u(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double at = t.first() + i * dt;
        while (j + 1 < t.size() && t.at(j + 1) < at)
            ++j;
        const int k = std::min<int>(j + 1, int(t.size()) - 1);
        const double span = t.at(k) - t.at(j);
        const double f = span > 0.0 ? std::clamp((at - t.at(j)) / span, 0.0, 1.0) : 0.0;
        u[size_t(i)] = v.at(j) + f * (v.at(k) - v.at(j));
        mean += u[size_t(i)];
    }
    mean /= n;
    double windowSum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double w = 0.5 - 0.5 * std::cos(2.0 * Pi * i / double(n)); // periodic Hann
        windowSum += w;
        grid[size_t(i)] = float((u[size_t(i)] - mean) * w);
    }
    kiss_fftr_cfg cfg = kiss_fftr_alloc(n, 0, nullptr, nullptr);
    if (!cfg) {
        *error = tr("the FFT could not be set up for %1 points").arg(n);
        return {};
    }
    std::vector<kiss_fft_cpx> out(size_t(n / 2 + 1));
    kiss_fftr(cfg, grid.data(), out.data());
    kiss_fftr_free(cfg);

    s.points = n;
    s.sampleRate = 1.0 / dt;
    s.resolutionHz = 1.0 / (n * dt);
    const double scale = 2.0 / windowSum; // amplitude of a sine in the middle of a bin
    for (int k = 0; k <= n / 2; ++k) {
        s.hz.append(k * s.resolutionHz);
        s.magnitude.append(std::hypot(double(out[size_t(k)].r), double(out[size_t(k)].i)) * scale);
    }
    // Peaks: local maxima above the first two bins (what is left of the mean and a trend),
    // their frequency refined by a parabola through the three bins.
    QList<Peak> found;
    for (int k = 2; k + 1 < s.magnitude.size(); ++k) {
        const double a = s.magnitude.at(k - 1), b = s.magnitude.at(k), c = s.magnitude.at(k + 1);
        if (b > a && b >= c && b > 0.0 && s.hz.at(k) >= fromHz) {
            const double denom = a - 2.0 * b + c;
            const double shift = denom != 0.0 ? 0.5 * (a - c) / denom : 0.0;
            found.append({(k + std::clamp(shift, -0.5, 0.5)) * s.resolutionHz, b});
        }
    }
    std::sort(found.begin(), found.end(), [](const Peak &x, const Peak &y) { return x.magnitude > y.magnitude; });
    s.peaks = found.mid(0, std::max(peakCount, 0));

    // What it cannot see: the band above Nyquist, folded back into it.
    s.nyquistHz = s.sampleRate / 2.0;
    s.usableFromHz = 2.0 * s.resolutionHz;
    s.usableToHz = 0.9 * s.nyquistHz;
    s.notes << tr("Nyquist frequency %1 Hz (half the %2 Hz sample rate): usable band %3–%4 Hz; nothing above %1 Hz "
                  "can be seen, and what is there folds back below it")
                   .arg(s.nyquistHz, 0, 'f', 1)
                   .arg(s.sampleRate, 0, 'f', 1)
                   .arg(s.usableFromHz, 0, 'f', 1)
                   .arg(s.usableToHz, 0, 'f', 1);
    // The alias check, on the raw samples at their own times: a stretch of at most 512 from
    // the middle (the search costs samples × frequencies), its own Hann window.
    const int m = std::min<int>(int(t.size()), 512);
    const int first = (int(t.size()) - m) / 2;
    std::vector<double> rt(static_cast<size_t>(m)), rv(static_cast<size_t>(m)), rw(static_cast<size_t>(m));
    double rMean = 0.0, rwSum = 0.0;
    for (int i = 0; i < m; ++i)
        rMean += v.at(first + i);
    rMean /= m;
    const double t0 = t.at(first), span = t.at(first + m - 1) - t0;
    for (int i = 0; i < m; ++i) {
        rt[size_t(i)] = t.at(first + i) - t0;
        rv[size_t(i)] = v.at(first + i) - rMean;
        rw[size_t(i)] = span > 0.0 ? 0.5 - 0.5 * std::cos(2.0 * Pi * rt[size_t(i)] / span) : 1.0;
        rwSum += rw[size_t(i)];
    }
    const double rRes = span > 0.0 ? 1.0 / span : s.resolutionHz; // the stretch's resolution
    const double step = rRes / 2.0;                               // the Hann main lobe is 4 bins wide; refined below
    const int checked = std::min<int>(int(s.peaks.size()), 3);    // the highest: where a notch would go
    for (int p = 0; p < s.peaks.size(); ++p) {
        Peak &peak = s.peaks[p];
        peak.nearNyquist = peak.hz >= s.usableToHz;
        if (p >= checked || rwSum <= 0.0)
            continue;
        const double own = bestFit(rt, rv, rw, rwSum, std::max(0.0, peak.hz - 2.0 * rRes), peak.hz + 2.0 * rRes, step)
                               .second;
        std::pair<double, double> other{0.0, -1.0};
        for (int k = 1; k <= 2; ++k) {
            for (const double c : {k * s.sampleRate - peak.hz, k * s.sampleRate + peak.hz}) {
                if (c <= s.nyquistHz)
                    continue;
                const double reach = 0.1 * s.sampleRate;
                const auto fit = bestFit(rt, rv, rw, rwSum, std::max(s.nyquistHz, c - reach), c + reach, step);
                if (fit.second > other.second)
                    other = fit;
            }
        }
        if (own > 0.0 && other.second >= 0.99 * own) // as well (within 1 %) or better
            peak.aliasOfHz = other.first;
    }
    for (const Peak &peak : std::as_const(s.peaks)) {
        if (peak.aliasOfHz > 0.0)
            s.notes << tr("the peak at %1 Hz may be an alias: the samples, at their own times, fit %2 Hz (above the "
                          "Nyquist frequency) as well or better; capture at a higher rate before placing a notch")
                           .arg(peak.hz, 0, 'f', 1)
                           .arg(peak.aliasOfHz, 0, 'f', 1);
        else if (peak.nearNyquist)
            s.notes << tr("the peak at %1 Hz is within 10 % of the Nyquist frequency: its frequency is not reliable, "
                          "it may be an alias")
                           .arg(peak.hz, 0, 'f', 1);
    }
    return s;
}

} // namespace dd
