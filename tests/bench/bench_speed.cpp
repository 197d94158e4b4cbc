// Link speed benchmark: backup, scan and monitor against the simulated drives (SimBench, the
// simulator's wire-timing model and default drive latency), with DriveConnection as the
// client exactly as the CLI uses it. For each case it prints the measured time (median and
// minimum of N runs), the wire-time floor, their ratio, the target and PASS / MISS.
//
//   build/tests/bench/bench_speed [--runs N] [--scan-runs N] [--only TEXT] [--same-thread]
//                                 [--gui-rates]
//
// The simulator runs in a thread of its own (as drivedesk-sim would in its own process), so
// that the client's work does not delay the simulated drive's replies; --same-thread puts
// it on the client's event loop instead (the CLI's --sim). --gui-rates samples every monitor
// at the GUI trend's default rate (from Drive::channelReadUs()) instead of as fast as the
// link allows, and judges it against that rate. The simulator's and the client's
// virtualcan devices open from different threads: VirtualCanHub settles the plugin's
// process-wide server first (see virtualcanhub.h), so no cross-thread warning is printed.
//
// Floors (see docs/performance.md, "Link speed"):
//  - Serial (Modbus RTU): every request and reply byte at 10 bits per character, plus the
//    drive's configured latency (end of request -> start of reply) per transaction, plus the
//    silence between the end of a reply and the next request: to the same drive 3.5
//    characters (what ModbusLink keeps there, docs/reliability.md), to another drive the
//    Modbus t3.5 (1750 us above 19200 baud). The request -> reply gap is the
//    drive's latency, not t3.5: that is what the simulated drive does, and the client
//    cannot shorten it.
//  - CAN: every request and reply frame at its worst-case stuffed length (as SimCanBus
//    paces them) at the bitrate. n pipelined reads cannot end sooner than 2n frames of bus
//    time, nor sooner than n requests + latency + one reply: floor = max of the two.
//    Heartbeats and keep-alives (< 1 % of the bus) are left out.
//  - Scan: each probed address costs its request bytes and a t3.5 silence; the drives that
//    are present add their latency and reply. How long to wait for an absent address is
//    a policy, not wire time, so it is not part of the floor (the targets are absolute).
//  - Monitor: the CLI's ChannelSampler at 1 ms (its --rate 1000) for 2 s: one sample = one
//    read of the channels; behind the rate the sampler keeps two reads queued, so the
//    next one waits on the link when the previous one is in; the floor is one such read
//    (serial: + 3.5 characters before the next; CAN: half of two samples' reads pipelined, i.e. their
//    bus time, since the next sample's requests overlap this one's latency). The median
//    sample interval ("typical sample") is taken over two samples, as CAN replies of two
//    pipelined reads may come in pairs. The rate is judged; the
//    median sample interval is printed beside it, since on a loaded machine a few samples
//    delayed by the scheduler pull the rate down.
//  - Shuoke (monitor only, speed): on RTU the seed's "at least 50 ms between commands"
//    (the simulated drive ignores a command sooner than 50 ms after the previous one)
//    makes the floor max(50 ms, one transaction).

#include "core/common/eventdispatcherchoice.h"
#include "core/common/localtimezone.h"
#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/link/linkreply.h"
#include "core/link/modbuslink.h"
#include "core/link/seriallink.h"
#include "core/link/wiretime.h"
#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/servomodbus/servomodbus.h"
#include "core/trend/channelsampler.h"
#include "core/tuning/capturesession.h"
#include "sim/bench/simbench.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simcandevice.h"
#include "sim/bus/simserialdevice.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QLoggingCategory>
#include <QThread>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#ifdef DD_BENCH_LIBMODBUS
#include <cerrno>
#include <modbus.h>
#endif

using namespace dd;

namespace {

// ---- Output -------------------------------------------------------------------------------

void out(const QString &line)
{
    std::fputs(qPrintable(line + QLatin1Char('\n')), stdout);
    std::fflush(stdout);
}

QString loadAverage()
{
    QFile f(QStringLiteral("/proc/loadavg"));
    if (!f.open(QIODevice::ReadOnly))
        return QStringLiteral("n/a");
    return QString::fromLatin1(f.readAll()).section(QLatin1Char(' '), 0, 2);
}

struct Row
{
    QString name;
    QString measured; // median (min)
    QString floor;
    double ratio = 0;      // median / floor, time per operation
    double limit = 0;      // target on the ratio, or (absolute targets) 0
    double absoluteMs = 0; // absolute target on the median, ms (0: none)
    double medianMs = 0;
    QString note;
    bool failed = false;  // an operation failed: no figure
    bool complete = true; // scans: every run found every drive
    bool skipped = false; // not available in this build
};

QList<Row> g_rows;

// Targets (issue #11): backups within 1.10x of the wire-time floor, monitors at >= 95 % of
// the link's rate (or, with --gui-rates, of the rate the GUI's trend asks for).
constexpr double BackupLimit = 1.10;
constexpr double MonitorLimit = 1 / 0.95;
constexpr double LibmodbusLimit = 1.05; // a backup against libmodbus on the same drive
bool g_guiRates = false;

// The GUI trend's default rate for a read of `readUs` (TrendPanel::rateForReadUs, which
// lives in the UI layer): the link's rate rounded down to two significant digits, <= 1 kHz.
double guiRateHz(double readUs)
{
    const double hz = std::min(1000.0, 1e6 / readUs);
    const double unit = std::pow(10.0, std::floor(std::log10(hz)) - 1);
    return std::max(0.1, std::floor(hz / unit) * unit);
}

QString ms(double v)
{
    return v >= 100 ? QString::number(v, 'f', 0) + QStringLiteral(" ms")
                    : QString::number(v, 'f', 1) + QStringLiteral(" ms");
}

bool passed(const Row &r)
{
    if (r.failed || !r.complete)
        return false;
    if (r.absoluteMs > 0)
        return r.medianMs < r.absoluteMs;
    return r.ratio <= r.limit;
}

void printTable()
{
    out(QString());
    out(QStringLiteral("%1 %2 %3 %4 %5 %6")
            .arg(QStringLiteral("case"), -44)
            .arg(QStringLiteral("measured: median (min)"), -26)
            .arg(QStringLiteral("floor"), -12)
            .arg(QStringLiteral("ratio"), -7)
            .arg(QStringLiteral("target"), -16)
            .arg(QStringLiteral("result")));
    for (const Row &r : std::as_const(g_rows)) {
        QString target = r.absoluteMs > 0 ? QStringLiteral("< %1").arg(ms(r.absoluteMs))
                                          : QStringLiteral("<= %1x").arg(r.limit, 0, 'f', 2);
        out(QStringLiteral("%1 %2 %3 %4 %5 %6")
                .arg(r.name, -44)
                .arg(r.skipped      ? QStringLiteral("skipped")
                         : r.failed ? QStringLiteral("FAILED")
                                    : r.measured,
                     -26)
                .arg(r.floor, -12)
                .arg(r.failed || r.skipped ? QStringLiteral("-") : QString::number(r.ratio, 'f', 2), -7)
                .arg(target, -16)
                .arg(r.skipped       ? QStringLiteral("-")
                         : passed(r) ? QStringLiteral("PASS")
                                     : QStringLiteral("MISS")));
        if (!r.note.isEmpty())
            out(QStringLiteral("    ") + r.note);
    }
}

// ---- Waiting ------------------------------------------------------------------------------

// Runs the event loop until `sender` emits `signal` or `timeoutMs` pass (never a polling
// loop: a spinning client thread would take the CPU from the simulator).
template <typename Sender, typename Signal>
void waitForSignal(Sender *sender, Signal signal, int timeoutMs)
{
    QEventLoop loop;
    QObject::connect(sender, signal, &loop, &QEventLoop::quit);
    QTimer guard;
    guard.setSingleShot(true);
    QObject::connect(&guard, &QTimer::timeout, &loop, &QEventLoop::quit);
    guard.start(timeoutMs);
    loop.exec();
}

// Waits for `reply` to finish; returns its error (Timeout if it never did). Deletes it.
// Lets `ms` pass in the event loop (the simulator thread and the link carry on).
void idle(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

Error await(DriveReply *reply, int timeoutMs, double *elapsedMs = nullptr)
{
    QElapsedTimer t;
    t.start();
    QEventLoop loop;
    QObject::connect(reply, &DriveReply::finished, &loop, &QEventLoop::quit);
    QTimer guard;
    guard.setSingleShot(true);
    QObject::connect(&guard, &QTimer::timeout, &loop, &QEventLoop::quit);
    if (!reply->isFinished()) {
        guard.start(timeoutMs);
        loop.exec();
    }
    if (elapsedMs)
        *elapsedMs = double(t.nsecsElapsed()) / 1e6;
    const Error e = reply->isFinished() ? reply->error()
                                        : Error{ErrorCode::Timeout, QStringLiteral("benchmark guard timeout")};
    reply->deleteLater();
    return e;
}

struct Stats
{
    double median = 0;
    double min = 0;
};

Stats statsOf(QList<double> v)
{
    std::sort(v.begin(), v.end());
    if (v.isEmpty())
        return {};
    const qsizetype n = v.size();
    const double median = n % 2 ? v.at(n / 2) : (v.at(n / 2 - 1) + v.at(n / 2)) / 2;
    return {median, v.first()};
}

// ---- The simulator, in its own thread -----------------------------------------------------

class SimHost
{
public:
    explicit SimHost(bool ownThread)
    {
        if (ownThread) {
            m_thread = std::make_unique<QThread>();
            m_thread->setObjectName(QStringLiteral("simulator"));
            m_thread->start();
        }
    }
    ~SimHost()
    {
        stop();
        if (m_thread) {
            m_thread->quit();
            m_thread->wait();
        }
    }

    Error start(const SimBenchOptions &options)
    {
        Error e;
        run([&] {
            m_bench = new SimBench;
            e = m_bench->start(options);
            if (!e.isError())
                m_settings = m_bench->clientSettings();
        });
        return e;
    }
    void stop()
    {
        run([&] {
            delete m_bench;
            m_bench = nullptr;
        });
    }
    ConnectionSettings clientSettings() const { return m_settings; }

private:
    void run(const std::function<void()> &f)
    {
        if (!m_thread) {
            f();
            return;
        }
        QObject context;
        context.moveToThread(m_thread.get());
        QMetaObject::invokeMethod(&context, f, Qt::BlockingQueuedConnection);
    }

    std::unique_ptr<QThread> m_thread;
    SimBench *m_bench = nullptr;
    ConnectionSettings m_settings;
};

bool g_ownThread = true;
int g_runs = 5;
int g_scanRuns = 3;
QString g_only;

bool wanted(const QString &name)
{
    return g_only.isEmpty() || name.contains(g_only, Qt::CaseInsensitive);
}

// A simulated bench with a connected client whose first drive answers.
struct Setup
{
    std::unique_ptr<SimHost> sim;
    std::unique_ptr<DriveConnection> connection;
    Drive *drive = nullptr;
    Error error;
};

std::unique_ptr<Setup> standUp(const SimBenchOptions &options)
{
    auto s = std::make_unique<Setup>();
    s->sim = std::make_unique<SimHost>(g_ownThread);
    if ((s->error = s->sim->start(options)))
        return s;
    s->connection = std::make_unique<DriveConnection>();
    if (!s->connection->open(s->sim->clientSettings(), &s->error))
        return s;
    s->drive = s->connection->drive(options.addresses.value(0, SimBenchOptions::defaultAddress(options.family)));
    if (!s->drive) {
        s->error = {ErrorCode::InvalidArgument, QStringLiteral("no drive object")};
        return s;
    }
    // A CAN bus connects asynchronously: the first identity read waits for it.
    for (int attempt = 0; attempt < 20; ++attempt) {
        s->error = await(s->drive->refreshIdentity(), 5000);
        if (!s->error)
            break;
    }
    return s;
}

// ---- Floors -------------------------------------------------------------------------------

// One Modbus 0x03 transaction reading `count` registers: request 8 bytes, reply 5 + 2 count.
double modbusReadUs(int count, int baud, qint64 latencyUs)
{
    return WireTime::serialBytesUs(8 + 5 + 2 * count, baud) + double(latencyUs);
}

// Reading `registers` consecutive registers in requests of at most 20, back to back.
double modbusBlockReadUs(int registers, int baud, qint64 latencyUs)
{
    double us = 0;
    int requests = 0;
    for (int left = registers; left > 0; left -= 20, ++requests)
        us += modbusReadUs(std::min(left, 20), baud, latencyUs);
    return us + (requests - 1) * WireTime::modbusSameDriveSilenceUs(baud); // to the same drive
}

// n pipelined servo-can reads: 2n frames on the bus, and the last reply cannot leave
// sooner than the drive's latency after the last request.
double canPipelinedReadsUs(int n, int bitrate, qint64 latencyUs)
{
    const double frame = WireTime::canFrameUs(8, false, bitrate, CanStuffing::WorstCase);
    return std::max(2 * n * frame, (n + 1) * frame + double(latencyUs));
}

// One monitor sample of n pipelined CAN reads while the sampler keeps two samples' reads on
// the bus (ChannelSampler::maxPendingReads()): the next sample's requests overlap this
// one's latency, so only the bus time is left: floor of 2n reads, per sample.
double canMonitorSampleUs(int n, int bitrate, qint64 latencyUs)
{
    return canPipelinedReadsUs(2 * n, bitrate, latencyUs) / 2;
}

// ---- Cases --------------------------------------------------------------------------------

void addFailure(const QString &name, const QString &floor, double limit, const Error &e)
{
    Row r;
    r.name = name;
    r.floor = floor;
    r.limit = limit;
    r.failed = true;
    r.note = QStringLiteral("error: ") + e.message;
    g_rows.append(r);
    out(QStringLiteral("  %1: FAILED: %2").arg(name, e.message));
}

Row &addTimed(const QString &name, const QList<double> &runsMs, double floorMs, double limit, double absoluteMs = 0,
              const QString &note = {})
{
    const Stats s = statsOf(runsMs);
    Row r;
    r.name = name;
    r.measured = QStringLiteral("%1 (%2)").arg(ms(s.median), ms(s.min));
    r.floor = ms(floorMs);
    r.ratio = s.median / floorMs;
    r.limit = limit;
    r.absoluteMs = absoluteMs;
    r.medianMs = s.median;
    r.note = note;
    g_rows.append(r);
    QStringList each;
    for (double v : runsMs)
        each << QString::number(v, 'f', 1);
    out(QStringLiteral("  %1: runs [%2] ms, floor %3").arg(name, each.join(QStringLiteral(", ")), ms(floorMs)));
    return g_rows.last();
}

void benchModbusBackup(int baud)
{
    const QString name = QStringLiteral("backup servo-modbus PA0-PA59 @ %1").arg(baud);
    if (!wanted(name))
        return;
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = baud;
    const double floorMs = modbusBlockReadUs(60, baud, SimSerialDevice::DefaultLatencyUs) / 1000;
    auto s = standUp(o);
    if (s->error)
        return addFailure(name, ms(floorMs), BackupLimit, s->error);
    QList<int> indices;
    for (int i = 0; i < 60; ++i)
        indices << i;
    QList<double> runs;
    for (int i = 0; i < g_runs; ++i) {
        idle(20); // a backup starts on a quiet line (else it waits t3.5 after the last run)
        double t = 0;
        if (Error e = await(s->drive->readParameters(indices), 10000, &t))
            return addFailure(name, ms(floorMs), BackupLimit, e);
        runs << t;
    }
    const Stats ours = statsOf(runs);
    addTimed(name, runs, floorMs, BackupLimit);
#ifdef DD_BENCH_LIBMODBUS
    // The same simulated drive read by libmodbus (modbus_read_registers, 3 x 20 registers),
    // after DriveDesk's client let go of the port.
    const QString vs = QStringLiteral("backup PA0-PA59 @ %1 vs libmodbus").arg(baud);
    const QString port = s->connection->settings().port;
    s->connection->close();
    modbus_t *ctx = modbus_new_rtu(qPrintable(port), baud, 'N', 8, 1);
    if (!ctx || modbus_connect(ctx) != 0) {
        if (ctx)
            modbus_free(ctx);
        return addFailure(vs, QStringLiteral("-"), LibmodbusLimit,
                          {ErrorCode::OpenFailed, QStringLiteral("libmodbus")});
    }
    modbus_set_slave(ctx, SimBenchOptions::defaultAddress(Family::ServoModbus));
    modbus_set_response_timeout(ctx, 1, 0);
    QList<double> theirs;
    for (int i = 0; i <= g_runs; ++i) { // the first run warms up, as our identity read did
        idle(20);
        QElapsedTimer t;
        t.start();
        bool ok = true;
        for (int block = 0; block < 3 && ok; ++block) {
            quint16 regs[20];
            ok = modbus_read_registers(ctx, servomodbus::parameterRegister(20 * block), 20, regs) == 20;
        }
        if (!ok) {
            modbus_close(ctx);
            modbus_free(ctx);
            return addFailure(
                vs, QStringLiteral("-"), LibmodbusLimit,
                {ErrorCode::Timeout, QStringLiteral("libmodbus: %1").arg(QLatin1String(modbus_strerror(errno)))});
        }
        if (i > 0)
            theirs << double(t.nsecsElapsed()) / 1e6;
    }
    modbus_close(ctx);
    modbus_free(ctx);
    QStringList each;
    for (double v : theirs)
        each << QString::number(v, 'f', 1);
    out(QStringLiteral("  libmodbus PA0-PA59 @ %1: runs [%2] ms").arg(baud).arg(each.join(QStringLiteral(", "))));
    const Stats lm = statsOf(theirs);
    Row r;
    r.name = vs;
    r.measured = QStringLiteral("%1 (%2)").arg(ms(ours.median), ms(ours.min));
    r.floor = ms(lm.median);
    r.ratio = ours.median / lm.median;
    r.limit = LibmodbusLimit;
    r.medianMs = ours.median;
    r.note = QStringLiteral("\"floor\" here is libmodbus's median on the same drive (min %1)").arg(ms(lm.min));
    g_rows.append(r);
#endif
}

void benchCanBackup()
{
    const QString name = QStringLiteral("backup servo-can P0-P219 @ 1 Mbit/s");
    if (!wanted(name))
        return;
    SimBenchOptions o;
    o.family = Family::ServoCan;
    o.can = QStringLiteral("virtualcan:auto");
    const double floorMs = canPipelinedReadsUs(220, 1000000, SimCanDevice::DefaultLatencyUs) / 1000;
    auto s = standUp(o);
    if (s->error)
        return addFailure(name, ms(floorMs), BackupLimit, s->error);
    QList<int> indices;
    for (int i = 0; i < 220; ++i)
        indices << i;
    QList<double> runs;
    for (int i = 0; i < g_runs; ++i) {
        double t = 0;
        if (Error e = await(s->drive->readParameters(indices), 10000, &t))
            return addFailure(name, ms(floorMs), BackupLimit, e);
        runs << t;
    }
    addTimed(name, runs, floorMs, BackupLimit);
}

// What an absent address costs a probe (8-byte read of one register, 7-byte reply, timeout
// = wire time + 4 ms, no retries) on a pty nobody answers, on ModbusLink: with the link's
// default quiet time after a timeout (max(2 x timeout, 20 ms)), and as the scanner probes
// (no first byte by request + 3 ms, then only t3.5). Printed, not judged: what a scan's
// absent address costs (docs/performance.md).
void benchDeadProbes(int baud)
{
    const QString name = QStringLiteral("dead-address probes @ %1").arg(baud);
    if (!wanted(name))
        return;
    constexpr int N = 40;
    PtyEndpoint pty;
    if (pty.open().isError())
        return out(QStringLiteral("  %1: skipped (no pty)").arg(name));
    SerialSettings ss;
    ss.portName = pty.clientPath();
    ss.baud = baud;
    ss.retries = 0;
    const double wireUs = WireTime::serialBytesUs(15, baud);
    const int timeoutMs = int(std::ceil((wireUs + 4000) / 1000));
    QStringList parts;
    for (const bool asScanner : {false, true}) {
        ModbusLink link;
        if (!link.open(ss))
            return out(QStringLiteral("  %1: ModbusLink did not open").arg(name));
        QElapsedTimer t;
        t.start();
        for (int i = 0; i < N; ++i) {
            ModbusRequest q;
            q.pdu = {quint8(2 + i), modbusrtu::ReadHoldingRegisters, 0x66, 1, {}};
            q.timeoutMs = timeoutMs;
            q.retries = 0;
            if (asScanner) {
                q.quietAfterTimeoutUs = link.interFrameGapUs();
                q.firstByteTimeoutUs = link.wireTimeUs(8) + 3000;
            }
            LinkReply *r = link.send(q);
            waitForSignal(r, &LinkReply::finished, 5000);
            delete r;
        }
        parts << QStringLiteral("%1 %2 ms")
                     .arg(asScanner ? QStringLiteral("as the scanner probes") : QStringLiteral("default quiet"))
                     .arg(t.nsecsElapsed() / 1e6 / N, 0, 'f', 1);
    }
    out(QStringLiteral("  %1 (timeout %2 ms, wire %3 ms + t3.5 %4 ms): per address %5")
            .arg(name)
            .arg(timeoutMs)
            .arg(WireTime::serialBytesUs(8, baud) / 1000.0, 0, 'f', 2)
            .arg(WireTime::modbusSilenceUs(baud) / 1000.0, 0, 'f', 2)
            .arg(parts.join(QStringLiteral(", "))));
}

void benchModbusScan(int baud, double limitMs)
{
    const QString name = QStringLiteral("scan servo-modbus 1-247 @ %1, 2 drives").arg(baud);
    if (!wanted(name))
        return;
    const QList<int> present = {17, 200};
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = baud;
    o.addresses = present;
    const qint64 latency = SimSerialDevice::DefaultLatencyUs;
    const double floorMs = (247 * (WireTime::serialBytesUs(8, baud) + WireTime::modbusSilenceUs(baud))
                            + present.size() * (latency + WireTime::serialBytesUs(7, baud)))
        / 1000;
    auto s = standUp(o);
    if (s->error)
        return addFailure(name, ms(floorMs), 0, s->error);
    QList<double> runs;
    QStringList misses;
    for (int i = 0; i < g_scanRuns; ++i) {
        ScanOptions so;
        so.from = 1;
        so.to = 247;
        Discovery *d = s->connection->createDiscovery(so);
        bool finished = false;
        Error result;
        QObject::connect(d, &Discovery::finished, d, [&](const Error &e) {
            finished = true;
            result = e;
        });
        QElapsedTimer t;
        t.start();
        d->start();
        waitForSignal(d, &Discovery::finished, 300000);
        if (!finished)
            result = {ErrorCode::Timeout, QStringLiteral("the scan did not finish in 5 minutes")};
        const double elapsed = double(t.nsecsElapsed()) / 1e6;
        QList<int> found;
        for (const DiscoveredDrive &dd : d->results())
            found << dd.address;
        std::sort(found.begin(), found.end());
        delete d;
        if (result)
            return addFailure(name, ms(floorMs), 0, result);
        if (found != present) {
            QStringList f;
            for (int a : found)
                f << QString::number(a);
            misses << QStringLiteral("run %1 found [%2]").arg(i + 1).arg(f.join(QLatin1Char(',')));
        }
        runs << elapsed;
    }
    Row &r = addTimed(name, runs, floorMs, 0, limitMs,
                      misses.isEmpty() ? QStringLiteral("both drives (17, 200) found in every run")
                                       : QStringLiteral("NOT FOUND: %1").arg(misses.join(QStringLiteral("; "))));
    r.complete = misses.isEmpty();
}

// Samples the channels as the CLI's monitor does, asked for more than the link allows, for
// 2 s: the highest sample rate the client achieves.
void benchMonitor(const QString &name, const SimBenchOptions &o, const QStringList &channels, double floorUs,
                  QString note)
{
    if (!wanted(name))
        return;
    auto s = standUp(o);
    if (s->error.code == ErrorCode::NotSupported) {
        Row r;
        r.name = name;
        r.floor = QStringLiteral("%1 Hz").arg(1e6 / floorUs, 0, 'f', 0);
        r.limit = MonitorLimit;
        r.skipped = true;
        r.note = s->error.message;
        g_rows.append(r);
        out(QStringLiteral("  %1: skipped: %2").arg(name, s->error.message));
        return;
    }
    if (s->error)
        return addFailure(name, QString(), MonitorLimit, s->error);
    constexpr int Ms = 2000;
    // --gui-rates: the rate the GUI's trend starts with (Drive::channelReadUs()); judged
    // against that rate instead of the link's floor.
    int intervalMs = 1;
    if (g_guiRates) {
        const double readUs = s->drive->channelReadUs(channels);
        const double rate = guiRateHz(readUs);
        intervalMs = std::max(1, int(std::lround(1000 / rate)));
        note += QStringLiteral("; GUI default %1 Hz (channelReadUs %2 us), sampler every %3 ms")
                    .arg(rate, 0, 'g', 3)
                    .arg(readUs, 0, 'f', 0)
                    .arg(intervalMs);
        floorUs = std::max(floorUs, intervalMs * 1000.0);
    }
    QList<double> runs; // ms per sample
    QList<double> each; // every sample's interval, ms
    for (int i = 0; i < g_runs; ++i) {
        // As the CLI's monitor at --rate 1000 (its most): more than any of these links
        // allows, so the sampler keeps two reads queued and the link never idles.
        ChannelSampler sampler(s->drive);
        sampler.setChannels(channels);
        sampler.setIntervalMs(intervalMs);
        QList<double> times;
        Error failure;
        QObject::connect(&sampler, &ChannelSampler::sampled, &sampler,
                         [&times](double t, const QMap<QString, double> &) { times << t; });
        QObject::connect(&sampler, &ChannelSampler::failed, &sampler, [&failure](const Error &e) { failure = e; });
        sampler.start();
        waitForSignal(&sampler, &ChannelSampler::failed, Ms);
        sampler.stop();
        if (failure)
            return addFailure(name, QString(), MonitorLimit, failure);
        if (times.size() < 3)
            return addFailure(name, QString(), MonitorLimit,
                              {ErrorCode::Timeout, QStringLiteral("fewer than 3 samples")});
        // Over two samples: with two reads pipelined (CAN) their replies may come in pairs,
        // and a single interval would then alternate short and long.
        for (qsizetype k = 2; k < times.size(); ++k)
            each << (times.at(k) - times.at(k - 2)) * 1000 / 2;
        runs << (times.last() - times.first()) * 1000 / double(times.size() - 1);
    }
    const Stats st = statsOf(runs);
    Row r;
    r.name = name;
    r.measured = QStringLiteral("%1 Hz (best %2)").arg(1000 / st.median, 0, 'f', 0).arg(1000 / st.min, 0, 'f', 0);
    r.floor = QStringLiteral("%1 Hz").arg(1e6 / floorUs, 0, 'f', 0);
    r.ratio = st.median / (floorUs / 1000);
    r.limit = MonitorLimit;
    r.medianMs = st.median;
    // The typical sample (median interval) shows what the client does when the machine
    // lets it run; the rate above also counts every sample a busy machine delayed.
    const double typicalMs = statsOf(each).median;
    r.note = QStringLiteral("%1; %2 % of the link's rate (typical sample %3 ms = %4 %)")
                 .arg(note)
                 .arg(100 / r.ratio, 0, 'f', 0)
                 .arg(typicalMs, 0, 'f', 2)
                 .arg(100 * floorUs / 1000 / typicalMs, 0, 'f', 0);
    g_rows.append(r);
    QStringList rates;
    for (double v : runs)
        rates << QString::number(1000 / v, 'f', 0);
    out(QStringLiteral("  %1: runs [%2] Hz, floor %3 Hz")
            .arg(name, rates.join(QStringLiteral(", ")))
            .arg(1e6 / floorUs, 0, 'f', 0));
}

void benchModbusMonitor(int baud)
{
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = baud;
    // speed 0x00, torque 0x07, current 0x08: one request 0x00..0x08 is the shortest way.
    const double floorUs = modbusReadUs(9, baud, SimSerialDevice::DefaultLatencyUs)
        + WireTime::modbusSameDriveSilenceUs(baud);
    benchMonitor(QStringLiteral("monitor servo-modbus @ %1").arg(baud), o,
                 {QStringLiteral("speed"), QStringLiteral("torque"), QStringLiteral("current")}, floorUs,
                 QStringLiteral("speed, torque, current (no bus voltage register); 1 request of 9 registers"));
}

void benchCanMonitor()
{
    SimBenchOptions o;
    o.family = Family::ServoCan;
    o.can = QStringLiteral("virtualcan:auto");
    const double floorUs = canMonitorSampleUs(4, 1000000, SimCanDevice::DefaultLatencyUs);
    benchMonitor(
        QStringLiteral("monitor servo-can @ 1 Mbit/s"), o,
        {QStringLiteral("speed"), QStringLiteral("torque"), QStringLiteral("current"), QStringLiteral("bus-voltage")},
        floorUs, QStringLiteral("speed, torque, current, bus voltage: 4 pipelined reads"));
}

// A tuning capture (CaptureSession, as `capture` and the step tests take it: the trend's
// ChannelSampler at 1 ms ticks, pipelined) of 4 servo-can channels for 2 s; with `jogging`
// the simulated motor turns at 300 r/min meanwhile (the closed loop is integrated at
// 0.1 ms steps, as during a step test). The target: >= 95 % of the link's rate.
void benchCanCapture(bool jogging)
{
    const QString name = jogging ? QStringLiteral("capture servo-can @ 1 Mbit/s, jogging")
                                 : QStringLiteral("capture servo-can @ 1 Mbit/s");
    if (!wanted(name))
        return;
    SimBenchOptions o;
    o.family = Family::ServoCan;
    o.can = QStringLiteral("virtualcan:auto");
    const double floorUs = canMonitorSampleUs(4, 1000000, SimCanDevice::DefaultLatencyUs);
    auto s = standUp(o);
    if (s->error)
        return addFailure(name, QString(), 1 / 0.95, s->error);
    const QStringList channels = {QStringLiteral("speed"), QStringLiteral("speed-command"), QStringLiteral("torque"),
                                  QStringLiteral("current")};
    QTimer renew;
    QObject::connect(&renew, &QTimer::timeout, s->drive, &Drive::renewJogLease);
    if (jogging) {
        if (Error e = await(s->drive->jog(300), 2000))
            return addFailure(name, QString(), 1 / 0.95, e);
        renew.start(100);
    }
    QList<double> runs, each;
    int gaps = 0;
    for (int i = 0; i < g_runs; ++i) {
        CaptureSession session(s->drive);
        CaptureData data;
        Error failure;
        QObject::connect(&session, &CaptureSession::captured, &session, [&data](const CaptureData &c) { data = c; });
        QObject::connect(&session, &CaptureSession::failed, &session, [&failure](const Error &e) { failure = e; });
        CaptureSettings settings;
        settings.durationS = 2.0;
        session.start(settings, channels);
        waitForSignal(&session, &CaptureSession::captured, 5000);
        if (failure || data.time.size() < 3)
            return addFailure(name, QString(), 1 / 0.95,
                              failure ? failure : Error{ErrorCode::Timeout, QStringLiteral("no capture")});
        for (qsizetype k = 2; k < data.time.size(); ++k)
            each << (data.time.at(k) - data.time.at(k - 2)) * 1000 / 2;
        runs << (data.time.last() - data.time.first()) * 1000 / double(data.time.size() - 1);
        gaps += int(data.gaps.size());
    }
    if (jogging) {
        renew.stop();
        await(s->drive->stop(), 2000);
    }
    const Stats st = statsOf(runs);
    Row r;
    r.name = name;
    r.measured = QStringLiteral("%1 Hz (best %2)").arg(1000 / st.median, 0, 'f', 0).arg(1000 / st.min, 0, 'f', 0);
    r.floor = QStringLiteral("%1 Hz").arg(1e6 / floorUs, 0, 'f', 0);
    r.ratio = st.median / (floorUs / 1000);
    r.limit = 1 / 0.95;
    r.medianMs = st.median;
    const double typicalMs = statsOf(each).median;
    r.note = QStringLiteral("speed, speed command, torque, current; %1 % of the link's rate (typical sample %2 ms = "
                            "%3 %); %4 gap(s) in %5 captures of 2 s")
                 .arg(100 / r.ratio, 0, 'f', 0)
                 .arg(typicalMs, 0, 'f', 2)
                 .arg(100 * floorUs / 1000 / typicalMs, 0, 'f', 0)
                 .arg(gaps)
                 .arg(g_runs);
    g_rows.append(r);
    QStringList rates;
    for (double v : runs)
        rates << QString::number(1000 / v, 'f', 0);
    out(QStringLiteral("  %1: runs [%2] Hz, floor %3 Hz")
            .arg(name, rates.join(QStringLiteral(", ")))
            .arg(1e6 / floorUs, 0, 'f', 0));
}

// Shuoke steppers report speed but no torque, current or bus voltage.
void benchShuokeMonitor()
{
    const QStringList speed{QStringLiteral("speed")};
    const QString note = QStringLiteral("speed only (no torque, current or bus voltage on these drives)");
    {
        // RTU: query speed 0x36 = 5-byte request, 9-byte reply. The seed asks for at least
        // 50 ms between commands; the simulated drive ignores a command that arrives less
        // than 50 ms after the previous one, so commands 50 ms apart is the floor.
        SimBenchOptions o;
        o.family = Family::Shuoke;
        o.baud = 9600;
        o.framing = QStringLiteral("rtu");
        const double floorUs = std::max(50000.0,
                                        WireTime::serialBytesUs(5 + 9, 9600) + SimSerialDevice::DefaultLatencyUs);
        benchMonitor(QStringLiteral("monitor shuoke RTU @ 9600"), o, speed, floorUs,
                     note + QStringLiteral("; commands >= 50 ms apart"));
    }
    {
        SimBenchOptions o;
        o.family = Family::Shuoke;
        o.can = QStringLiteral("virtualcan:auto");
        o.framing = QStringLiteral("can");
        benchMonitor(QStringLiteral("monitor shuoke CAN @ 100 kbit/s"), o, speed,
                     canMonitorSampleUs(1, 100000, SimCanDevice::DefaultLatencyUs), note);
    }
}

} // namespace

int main(int argc, char **argv)
{
    dd::pinLocalTimeZone();           // before any thread: see localtimezone.h
    dd::preferPlainEventDispatcher(); // before the application object: see eventdispatcherchoice.h
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*=false\nqt.*=false"));
    const QStringList args = app.arguments();
    for (int i = 1; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (a == QLatin1String("--runs") && i + 1 < args.size())
            g_runs = std::max(1, args.at(++i).toInt());
        else if (a == QLatin1String("--scan-runs") && i + 1 < args.size())
            g_scanRuns = std::max(1, args.at(++i).toInt());
        else if (a == QLatin1String("--only") && i + 1 < args.size())
            g_only = args.at(++i);
        else if (a == QLatin1String("--same-thread"))
            g_ownThread = false;
        else if (a == QLatin1String("--gui-rates"))
            g_guiRates = true;
        else {
            out(QStringLiteral(
                "usage: bench_speed [--runs N] [--scan-runs N] [--only TEXT] [--same-thread] [--gui-rates]"));
            return 2;
        }
    }
    out(QStringLiteral("bench_speed: Qt %1, %2 CPUs, load average %3 (start), simulator %4, %5 runs (scans %6)")
            .arg(QLatin1String(qVersion()))
            .arg(QThread::idealThreadCount())
            .arg(loadAverage(),
                 g_ownThread ? QStringLiteral("in its own thread") : QStringLiteral("on the client's thread"))
            .arg(g_runs)
            .arg(g_scanRuns));
    out(QStringLiteral("drive latency: serial %1 us, CAN %2 us (simulator defaults)")
            .arg(SimSerialDevice::DefaultLatencyUs)
            .arg(SimCanDevice::DefaultLatencyUs));

    benchModbusBackup(115200);
    benchModbusBackup(9600);
    benchCanBackup();
    benchDeadProbes(115200);
    benchDeadProbes(9600);
    benchModbusScan(9600, 4500);
    benchModbusScan(115200, 1500);
    benchModbusMonitor(115200);
    benchModbusMonitor(9600);
    benchCanMonitor();
    benchCanCapture(false);
    benchCanCapture(true);
    benchShuokeMonitor();

    printTable();
    out(QStringLiteral("load average %1 (end)").arg(loadAverage()));
    bool allPassed = true;
    for (const Row &r : std::as_const(g_rows))
        allPassed = allPassed && (r.skipped || passed(r));
    return allPassed ? 0 : 1;
}
