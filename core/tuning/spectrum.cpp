#include "core/tuning/spectrum.h"

#include <kiss_fftr.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace dd {

namespace {
constexpr double Pi = 3.14159265358979323846;
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
    return s;
}

} // namespace dd
