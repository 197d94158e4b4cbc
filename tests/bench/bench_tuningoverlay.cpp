// Tuning overlay benchmark (issue 12): 8 runs of 10 000 samples each (a second-order step
// response with noise, 0.1 ms apart, 20 % before the trigger) overlaid in the Tuning tab's
// CapturePlot at 1280 x 720, offscreen. A redraw is what a change of the overlay, zoom or
// size costs: the curves min/max-decimated to the plot's pixel columns and handed to the
// plot (CapturePlot::rebuild()), then the plot painted (TrendPlot::render() into an image).
// Printed: medians of 41 runs, ms wall (thread CPU), for the whole record and for a 10 %
// zoom, and for comparison the paint of the undecimated 80 000 points.
//
//   QT_QPA_PLATFORM=offscreen build/tests/bench/bench_tuningoverlay [--runs N] [--samples N]

#include "ui/panels/trend/trendplot.h"
#include "ui/panels/tuning/captureplot.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#ifdef Q_OS_UNIX
#include <time.h>
#endif

using namespace dd;

namespace {

qint64 threadCpuNs()
{
#ifdef Q_OS_UNIX
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return qint64(ts.tv_sec) * 1000000000 + ts.tv_nsec;
#else
    return 0;
#endif
}

struct Timing
{
    double wallMs;
    double cpuMs;
};

Timing medianMs(int runs, const std::function<void()> &f)
{
    QList<double> wall, cpu;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer timer;
        const qint64 c0 = threadCpuNs();
        timer.start();
        f();
        wall.append(double(timer.nsecsElapsed()) / 1e6);
        cpu.append(double(threadCpuNs() - c0) / 1e6);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall.at(wall.size() / 2), cpu.at(cpu.size() / 2)};
}

void print(const char *what, const Timing &t)
{
    std::printf("%-44s %8.2f (%6.2f)\n", what, t.wallMs, t.cpuMs);
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    const auto option = [&](const char *name, int fallback) {
        const int i = args.indexOf(QString::fromLatin1(name));
        return i >= 0 && i + 1 < args.size() ? args.at(i + 1).toInt() : fallback;
    };
    const int runCount = option("--runs", 8);
    const int samples = option("--samples", 10000);
    const double dt = 1e-4;

    QList<CapturePlot::Curve> curves;
    for (int r = 0; r < runCount; ++r) {
        CapturePlot::Curve c;
        c.label = QStringLiteral("run %1").arg(r + 1);
        c.color = QColor::fromHsv((r * 45) % 360, 200, 200);
        const double zeta = 0.2 + 0.08 * r;
        const double wn = 2 * M_PI * 40.0;
        quint32 seed = 12345u + quint32(r);
        for (int i = 0; i < samples; ++i) {
            const double t = (i - samples / 5) * dt;
            double y = 0.0;
            if (t >= 0.0) {
                const double wd = wn * std::sqrt(1 - zeta * zeta);
                y = 500.0
                    * (1
                       - std::exp(-zeta * wn * t)
                           * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
            }
            seed = seed * 1664525u + 1013904223u;
            y += double(seed >> 24) / 255.0 * 4.0 - 2.0; // ±2 r/min of noise
            c.time << t;
            c.values << y;
        }
        curves << c;
    }

    CapturePlot plot;
    plot.resize(1280, 720);
    plot.show();
    QApplication::processEvents();
    plot.setCurves(curves, QStringLiteral("Speed (r/min)"));
    const QSize size = plot.plot()->size();
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    auto paint = [&] {
        QPainter p(&image);
        plot.plot()->render(&p, QRectF(QPointF(0, 0), QSizeF(size)));
    };

    std::printf("%d runs x %d samples, CapturePlot 1280 x 720 (plot %d x %d, plot area %.0f px wide)\n", runCount,
                samples, size.width(), size.height(), plot.plot()->plotRect().width());
    qsizetype points = 0;
    for (const TrendPlot::Series &s : plot.plot()->series())
        points += s.points.size();
    std::printf("points handed to the plot: %lld (of %lld samples)\n", qlonglong(points),
                qlonglong(runCount) * samples);
    std::printf("%-44s %8s (%6s)\n", "", "ms wall", "CPU");
    const int n = 41;
    print("decimate (rebuild), whole record", medianMs(n, [&] { plot.rebuild(); }));
    print("paint", medianMs(n, paint));
    print("redraw = decimate + paint, whole record", medianMs(n, [&] {
              plot.rebuild();
              paint();
          }));
    const double from = curves.first().time.first();
    const double span = curves.first().time.last() - from;
    plot.setTimeWindow(from + span * 0.18, from + span * 0.28);
    print("redraw, 10 % zoom", medianMs(n, [&] {
              plot.rebuild();
              paint();
          }));
    plot.resetZoom();

    // For comparison: the raw samples handed to the plot, no decimation.
    QList<TrendPlot::Series> raw;
    for (int k = 0; k < curves.size(); ++k) {
        TrendPlot::Series s;
        s.id = QString::number(k);
        s.label = curves.at(k).label;
        s.color = curves.at(k).color;
        for (int i = 0; i < samples; ++i)
            s.points.append(QPointF(curves.at(k).time.at(i), curves.at(k).values.at(i)));
        raw << s;
    }
    plot.plot()->setSeries(raw);
    print("paint without decimation (all samples)", medianMs(11, paint));
    return 0;
}
