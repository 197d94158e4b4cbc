// Trend benchmark (issue 10): 8 channels recorded at a link's rate (default 1 kHz, above
// servo-can's 926 Hz, the fastest link) for 10 minutes, two value axes (4 channels each),
// TrendView at 1280 x 720 offscreen. Prints the buffers' memory, the append cost, a live
// update (one new reading of 8 channels + TrendView::refreshNow(): decimate, finished
// buckets from the view's DecimationCache, + hand the points to the plot) and a render (TrendPlot painted), for the default 30 s window and for
// the whole 10 minutes on screen; then the lateness of a 10 ms timer on another thread (as
// the I/O thread's keep-alives and jog leases) while the GUI thread refreshes non-stop.
//
//   QT_QPA_PLATFORM=offscreen build/tests/bench/bench_trend [--rate HZ] [--minutes M] [--screenshot FILE]

#include "core/trend/decimationcache.h"
#include "core/trend/decimator.h"
#include "core/trend/samplebuffer.h"
#include "core/trend/trendplotbuilder.h"
#include "core/trend/trendrecorder.h"
#include "ui/panels/trend/trendplot.h"
#include "ui/panels/trend/trendview.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QThread>
#include <QTimer>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <functional>
#ifdef Q_OS_UNIX
#include <time.h>
#endif

using namespace dd;

namespace {

constexpr int Series = 8;
const char *const Ids[Series] = {"speed",  "speed-command", "position-error", "encoder",
                                 "torque", "current",       "bus-voltage",    "temperature"};
const char *const Units[Series] = {"r/min", "r/min", "pulse", "pulse", "%", "A", "V", "°C"};

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
    const double x = double(i);
    switch (channel % 4) {
    case 0: return 1500.0 * std::sin(x * 0.0007 + channel) + double(i % 13);
    case 1: return 30.0 * std::sin(x * 0.011) + double((i * 7919) % 17);
    case 2: return 4.0 * std::cos(x * 0.003) + double(i % 5) * 0.1;
    default: return 311.0 + double((i * 31) % 9) * 0.25;
    }
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    const auto option = [&](const char *name, double fallback) {
        const int i = args.indexOf(QString::fromLatin1(name));
        return i >= 0 && i + 1 < args.size() ? args.at(i + 1).toDouble() : fallback;
    };
    const double rateHz = option("--rate", 1000.0);
    const double minutes = option("--minutes", 10.0);
    const QString screenshot = args.value(args.indexOf(QStringLiteral("--screenshot")) + 1);
    const qint64 n = qint64(rateHz * minutes * 60.0);
    const qint64 periodUs = qint64(std::llround(1e6 / rateHz));

    TrendRecorder rec;
    QList<TrendChannel> channels;
    for (int c = 0; c < Series; ++c)
        channels.append({QString::fromLatin1(Ids[c]), QString::fromLatin1(Ids[c]), QString::fromUtf8(Units[c]), 1});
    rec.setCapacityPerChannel(std::max<qint64>(n + 10000, SampleBuffer::DefaultCapacity));
    rec.setChannels(channels);
    const qint64 c0 = threadCpuNs();
    for (qint64 i = 0; i < n; ++i) {
        QMap<QString, double> reading;
        for (int c = 0; c < Series; ++c)
            reading.insert(channels.at(c).id, value(c, i));
        rec.appendSamples(i * periodUs, reading);
    }
    const double appendNs = double(threadCpuNs() - c0) / double(n * Series);

    TrendView view(&rec);
    view.resize(1280, 720);
    view.show();
    for (int c = 0; c < Series; ++c)
        view.setChannelAxis(channels.at(c).id, c < 4 ? TrendPlot::Left : TrendPlot::Right);
    QCoreApplication::processEvents();
    view.refreshNow();

    std::printf("Trend benchmark: %d channels at %.0f Hz for %.1f min (%lld samples per channel), two value axes "
                "(4 + 4 channels), TrendView 1280x720 offscreen (plot %d x %d px). Medians in ms, wall (thread CPU).\n",
                Series, rateHz, minutes, static_cast<long long>(n), int(view.plot()->plotRect().width()),
                int(view.plot()->plotRect().height()));
    std::printf("buffers %.1f MB, append %.0f ns per sample (CPU)\n\n", double(rec.memoryBytes()) / 1e6, appendNs);
    std::printf(
        "| window | points per series | update ms | render ms | update + render ms |\n|---|---:|---:|---:|---:|\n");

    qint64 next = n;
    const auto update = [&] {
        QMap<QString, double> reading;
        for (int c = 0; c < Series; ++c)
            reading.insert(channels.at(c).id, value(c, next));
        rec.appendSamples(next * periodUs, reading);
        ++next;
        view.refreshNow();
    };
    QImage canvas(view.plot()->size(), QImage::Format_ARGB32_Premultiplied);
    const auto render = [&] {
        QPainter p(&canvas);
        view.plot()->render(&p, QRectF(QPointF(0, 0), QSizeF(view.plot()->size())));
    };
    for (int window : {30, 600}) {
        view.setWindowSeconds(window);
        view.refreshNow();
        const int runs = 41;
        const Timing updateMs = medianMs(runs, update);
        const Timing renderMs = medianMs(runs, render);
        const Timing bothMs = medianMs(runs, [&] {
            update();
            render();
        });
        const int points = int(view.plot()->series().value(0).points.size());
        const int width = int(view.plot()->plotRect().width());
        const qint64 to = rec.lastTimeUs();
        const qint64 from = to - qint64(window) * 1000000;
        const Timing decimateMs = medianMs(runs, [&] {
            for (const TrendChannel &c : channels)
                (void)TrendPlotBuilder::build(*rec.buffer(c.id), from, to, width, 0);
        });
        // As a live update decimates: the window slid by one sample, finished buckets cached.
        QList<DecimationCache> caches(Series);
        qint64 slide = periodUs * 40;
        const Timing cachedMs = medianMs(runs, [&] {
            for (int c = 0; c < Series; ++c)
                (void)TrendPlotBuilder::build(*rec.buffer(channels.at(c).id), from - slide, to - slide, width, 0, 1.0,
                                              0.0, &caches[c]);
            slide -= periodUs; // one sample later each run (inside the recording: nothing appended)
            if (slide < 0)
                slide = periodUs * 40;
        });
        std::printf("(decimation alone, 8 channels to %d px: from scratch %s, with the bucket cache as the live "
                    "update uses it %s)\n",
                    width, fmt(decimateMs).constData(), fmt(cachedMs).constData());
        std::printf("| %d s | %d | %s | %s | %s |\n", window, points, fmt(updateMs).constData(),
                    fmt(renderMs).constData(), fmt(bothMs).constData());
        std::fflush(stdout);
    }
    if (!screenshot.isEmpty())
        view.grab().save(screenshot);

    // Another thread's 10 ms timer (the I/O thread's keep-alives and jog-lease renewals run
    // on the hub's own thread) while the GUI thread refreshes and renders without pause.
    QThread io;
    io.start();
    std::atomic<qint64> worstLateUs{0};
    std::atomic<int> ticks{0};
    auto *timer = new QTimer;
    timer->setTimerType(Qt::PreciseTimer);
    timer->setInterval(10);
    timer->moveToThread(&io);
    auto *clock = new QElapsedTimer;
    QObject::connect(timer, &QTimer::timeout, timer, [&, clock] {
        if (clock->isValid()) {
            const qint64 late = clock->nsecsElapsed() / 1000 - 10000;
            worstLateUs = std::max<qint64>(worstLateUs, late);
        }
        clock->start();
        ++ticks;
    });
    QMetaObject::invokeMethod(
        timer, [timer] { timer->start(); }, Qt::BlockingQueuedConnection);
    QElapsedTimer busy;
    busy.start();
    int frames = 0;
    while (busy.elapsed() < 3000) {
        update();
        render();
        ++frames;
    }
    QMetaObject::invokeMethod(
        timer, [timer] { timer->stop(); }, Qt::BlockingQueuedConnection);
    io.quit();
    io.wait();
    delete timer;
    delete clock;
    std::printf("\nWhile the GUI thread refreshed and rendered %d frames in 3 s (10 min window), a 10 ms timer on "
                "another thread ticked %d times, at worst %.1f ms late.\n",
                frames, ticks.load(), double(worstLateUs.load()) / 1000.0);
    return 0;
}
