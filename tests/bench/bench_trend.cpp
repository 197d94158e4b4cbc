// Trend plot benchmark: for 4 series × recordings of 10k / 100k / 1M samples per series,
// prints the memory of the buffers, the decimation time, and the chart update (decimate +
// replace()) and render (QWidget::grab) time of a TrendView, all offscreen. The baseline
// row replaces the undecimated samples into the series, to show what decimation saves.
//
//   QT_QPA_PLATFORM=offscreen build/tests/bench/bench_trend [--quick] [--screenshot FILE]

#include "core/trend/decimator.h"
#include "core/trend/samplebuffer.h"
#include "core/trend/trendplotbuilder.h"
#include "core/trend/trendrecorder.h"
#include "ui/panels/trend/trendview.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QElapsedTimer>
#include <QLineSeries>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#ifdef Q_OS_UNIX
#include <time.h>
#endif

using namespace dd;

namespace {

constexpr int Series = 4;
constexpr qint64 WindowUs = 600LL * 1000000; // the longest window the view offers

const char *const Ids[Series] = {"speed", "torque", "current", "bus-voltage"};

// CPU time of this thread (ns); on a shared machine it varies far less than wall time.
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

// Medians of `runs` timings of f(), in milliseconds.
Timing medianMs(int runs, const std::function<void()> &f)
{
    QList<double> wall;
    QList<double> cpu;
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

QByteArray fmt(const Timing &t)
{
    return QByteArray::number(t.wallMs, 'f', 2) + " (" + QByteArray::number(t.cpuMs, 'f', 2) + ")";
}

double value(int channel, qint64 i)
{
    switch (channel) {
    case 0: return 1500.0 * std::sin(double(i) * 0.0007) + double(i % 13);
    case 1: return 30.0 * std::sin(double(i) * 0.011) + double((i * 7919) % 17);
    case 2: return 4.0 * std::cos(double(i) * 0.003) + double(i % 5) * 0.1;
    default: return 311.0 + double((i * 31) % 9) * 0.25;
    }
}

// n samples per series spread evenly over the 10-minute window (10k: every 60 ms,
// 100k: every 6 ms, 1M: every 0.6 ms), so the whole recording is on screen.
void fill(TrendRecorder &rec, qint64 n, double *appendNsPerSample)
{
    QList<TrendChannel> channels;
    for (const char *id : Ids)
        channels.append({QString::fromLatin1(id), QString::fromLatin1(id), QString(), 1});
    rec.setCapacityPerChannel(std::max<qint64>(n, SampleBuffer::DefaultCapacity));
    rec.setChannels(channels);
    const qint64 c0 = threadCpuNs();
    for (qint64 i = 0; i < n; ++i) {
        const qint64 t = i * (WindowUs - 1) / n;
        for (int c = 0; c < Series; ++c)
            rec.append(channels.at(c).id, t, value(c, i));
    }
    *appendNsPerSample = double(threadCpuNs() - c0) / double(n * Series);
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    const bool quick = args.contains(QStringLiteral("--quick"));
    const QString screenshot = args.value(args.indexOf(QStringLiteral("--screenshot")) + 1);

    std::printf("Trend plot benchmark: %d series, view 1280x720 offscreen, window 10 min, "
                "whole recording visible. Times are medians in ms, wall (thread CPU).\n\n",
                Series);
    std::printf("| samples/series | buffers MB | append ns/sample (CPU) | decimate 4 series ms "
                "| points/series | update ms | render ms | update+render ms |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");

    QList<QByteArray> scans;
    const QList<qint64> sizes = quick ? QList<qint64>{10000, 100000} : QList<qint64>{10000, 100000, 1000000};
    for (qint64 n : sizes) {
        TrendRecorder rec;
        double appendNs = 0;
        fill(rec, n, &appendNs);
        const int runs = n >= 1000000 ? 9 : 21;

        // Decimation alone, to a 1,000-pixel-wide plot.
        int points = 0;
        const Timing decimateMs = medianMs(runs, [&] {
            for (const char *id : Ids) {
                const auto r = TrendPlotBuilder::build(*rec.buffer(QString::fromLatin1(id)), 0, WindowUs - 1, 1000, 0);
                points = int(r.points.size());
            }
        });

        // The same without the block summaries: a plain scan of every sample (Decimator's
        // list overload over copies of the buffers).
        QList<QList<TrendSample>> copies;
        for (const char *id : Ids)
            copies.append(rec.buffer(QString::fromLatin1(id))->samples());
        const Timing scanMs = medianMs(runs, [&] {
            for (const auto &c : std::as_const(copies))
                points = int(Decimator::minMax(c, 0, WindowUs - 1, 999).size()) + 2;
        });
        scans.append(QByteArray::number(n) + " | " + fmt(decimateMs) + " | " + fmt(scanMs));
        copies.clear();

        TrendView view(&rec);
        view.resize(1280, 720);
        view.setWindowSeconds(600);
        view.show();
        QCoreApplication::processEvents();
        view.refreshNow();
        const QString first = QString::fromLatin1(Ids[0]);
        // A live update: one new reading, then decimate + replace() (refreshNow redraws
        // because the recording changed).
        qint64 next = n;
        const auto update = [&] {
            const qint64 t = next * (WindowUs - 1) / n;
            for (int c = 0; c < Series; ++c)
                rec.append(QString::fromLatin1(Ids[c]), t, value(c, next));
            ++next;
            view.refreshNow();
        };
        const Timing updateMs = medianMs(runs, update);
        const Timing renderMs = medianMs(runs, [&] { (void)view.chartView()->grab(); });
        const Timing bothMs = medianMs(runs, [&] {
            update();
            (void)view.chartView()->grab();
        });
        const int shown = int(view.series(first)->count());
        std::printf("| %lld | %.1f | %.0f | %s | %d (view: %d) | %s | %s | %s |\n", static_cast<long long>(n),
                    double(rec.memoryBytes()) / 1e6, appendNs, fmt(decimateMs).constData(), points, shown,
                    fmt(updateMs).constData(), fmt(renderMs).constData(), fmt(bothMs).constData());
        std::fflush(stdout);
        if (!screenshot.isEmpty() && n == sizes.first())
            view.grab().save(screenshot);
    }

    std::printf(
        "\nDecimation of 4 series to 1,000 px: the strategy the view uses (Auto: summaries from 256 samples per bucket) vs a plain scan:\n\n");
    std::printf("| samples/series | Auto ms | plain scan ms |\n|---:|---:|---:|\n");
    for (const QByteArray &row : std::as_const(scans))
        std::printf("| %s |\n", row.constData());

    // Baseline: every sample into the series (no decimation), replace() + render.
    std::printf("\nBaseline without decimation (replace() of every sample, then render):\n\n");
    std::printf("| samples/series | replace ms | render ms |\n|---:|---:|---:|\n");
    for (qint64 n : QList<qint64>{10000, 100000}) {
        QChart *chart = new QChart;
        auto *x = new QValueAxis(chart);
        auto *y = new QValueAxis(chart);
        chart->addAxis(x, Qt::AlignBottom);
        chart->addAxis(y, Qt::AlignLeft);
        QList<QLineSeries *> series;
        QList<QList<QPointF>> data(Series);
        for (int c = 0; c < Series; ++c) {
            auto *s = new QLineSeries;
            chart->addSeries(s);
            s->attachAxis(x);
            s->attachAxis(y);
            series.append(s);
            for (qint64 i = 0; i < n; ++i)
                data[c].append(QPointF(double(i) * 600.0 / double(n), value(c, i)));
        }
        x->setRange(0, 600);
        y->setRange(-1600, 1600);
        QChartView cv(chart);
        cv.resize(1000, 600);
        cv.show();
        QCoreApplication::processEvents();
        const int runs = n >= 100000 ? 3 : 9;
        const Timing replaceMs = medianMs(runs, [&] {
            for (int c = 0; c < Series; ++c)
                series[c]->replace(data[c]);
        });
        const Timing renderMs = medianMs(runs, [&] { (void)cv.grab(); });
        std::printf("| %lld | %s | %s |\n", static_cast<long long>(n), fmt(replaceMs).constData(),
                    fmt(renderMs).constData());
        std::fflush(stdout);
    }
    return 0;
}
