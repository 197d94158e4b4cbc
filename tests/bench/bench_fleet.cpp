// Several drives on one link (docs/performance.md, "Several drives"): the CLI's backup --all
// and restore --all as FleetTransfer runs them, against SimBench (the simulator's wire-timing
// model and default drive latency) in a thread of its own, DriveConnection as the client.
// For each case it prints the runs, the wire floor, the ratio median / floor, the target and
// PASS / MISS.
//
//   build/tests/bench/bench_fleet [--runs N] [--only TEXT]
//
// Floors. The floor is computed from the frames the job put on the wire in the run (its
// TrafficTap): with no faults there are no retries, so these are the transactions the job
// needs — per drive its identification (the backup file records the firmware; a restore
// checks it) and its parameter reads, for a restore also its writes and their read-backs.
// The transaction count per drive is printed beside it.
//  - Serial (Modbus RTU): every request and reply byte at 10 bits per character, plus the
//    drive's latency (end of request -> start of reply) per transaction, plus the silence
//    between the end of a reply and the next request: 3.5 characters when it goes to the
//    same drive, the full t3.5 (1.75 ms above 19200 baud) when to another.
//  - CAN: n requests and their n replies, each at its worst-case stuffed length (8 data
//    bytes, as SimCanBus paces them), back to back on the bus: 2n frames; nor sooner than n
//    requests + the latency + one reply. Heartbeats are left out.
// "restore" also prints the floor of its writes plus their read-backs alone (what the issue
// names): a restore must read the drive first to know what differs, so it also pays for
// the identification and the 60 / 220 reads of each drive.

#include "core/common/eventdispatcherchoice.h"
#include "core/common/localtimezone.h"
#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h"
#include "core/fleet/fleettransfer.h"
#include "core/link/traffictap.h"
#include "core/link/wiretime.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/simcandevice.h"
#include "sim/bus/simserialbus.h"
#include "sim/bus/simserialdevice.h"
#include "sim/servocan/simservocandrive.h"
#include "sim/servomodbus/simservomodbusdrive.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QSignalSpy>
#include <QThread>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>

using namespace dd;

namespace {

int g_runs = 5;
QString g_only;
int g_misses = 0;

void out(const QString &line)
{
    std::fputs(qPrintable(line + QLatin1Char('\n')), stdout);
    std::fflush(stdout);
}

QString ms(double v)
{
    return QString::number(v, 'f', 1) + QStringLiteral(" ms");
}

// The simulator in a thread of its own (as drivedesk-sim in its own process would be).
class SimHost
{
public:
    SimHost()
    {
        m_thread.setObjectName(QStringLiteral("simulator"));
        m_thread.start();
    }
    ~SimHost()
    {
        run([this] { delete m_bench; });
        m_thread.quit();
        m_thread.wait();
    }
    Error start(const SimBenchOptions &o)
    {
        Error e;
        run([&] {
            m_bench = new SimBench;
            e = m_bench->start(o);
        });
        return e;
    }
    // Runs f in the simulator's thread and waits for it.
    void run(const std::function<void()> &f)
    {
        QObject context;
        context.moveToThread(&m_thread);
        QMetaObject::invokeMethod(&context, f, Qt::BlockingQueuedConnection);
    }
    SimBench *bench() const { return m_bench; }

private:
    QThread m_thread;
    SimBench *m_bench = nullptr;
};

struct Frames
{
    QList<int> tx, rx;    // bytes (serial) or data length (CAN) per frame
    QList<int> txPeer;    // serial: the address each request went to
    QList<qint64> gapsUs; // serial: from each reply's arrival to the next request's hand-over
    qint64 lastRxUs = -1;
    void clear()
    {
        tx.clear();
        txPeer.clear();
        rx.clear();
        gapsUs.clear();
        lastRxUs = -1;
    }
    QString gapText() const
    {
        if (gapsUs.isEmpty())
            return {};
        QList<qint64> g = gapsUs;
        std::sort(g.begin(), g.end());
        return QStringLiteral("reply -> next request (client side): median %1 us, 90th percentile %2 us")
            .arg(g.at(g.size() / 2))
            .arg(g.at(g.size() * 9 / 10));
    }
};

double serialFloorUs(const Frames &f, int baud, qint64 latencyUs)
{
    double us = 0;
    for (int b : f.tx)
        us += WireTime::serialBytesUs(b, baud) + double(latencyUs);
    for (int b : f.rx)
        us += WireTime::serialBytesUs(b, baud);
    for (qsizetype i = 1; i < f.txPeer.size(); ++i)
        us += f.txPeer.at(i) == f.txPeer.at(i - 1) ? WireTime::modbusSameDriveSilenceUs(baud)
                                                   : WireTime::modbusSilenceUs(baud);
    return us;
}

double canFloorUs(int requests, int bitrate, qint64 latencyUs)
{
    const double frame = WireTime::canFrameUs(8, false, bitrate, CanStuffing::WorstCase);
    return std::max(2 * requests * frame, (requests + 1) * frame + double(latencyUs));
}

double median(QList<double> v)
{
    std::sort(v.begin(), v.end());
    const qsizetype n = v.size();
    return n % 2 ? v.at(n / 2) : (v.at(n / 2 - 1) + v.at(n / 2)) / 2;
}

void report(const QString &name, const QList<double> &runs, double floorMs, double limit, const QString &note)
{
    QStringList each;
    for (double r : runs)
        each << QString::number(r, 'f', 1);
    const double m = median(runs);
    const double ratio = m / floorMs;
    const bool pass = ratio <= limit;
    g_misses += pass ? 0 : 1;
    out(QStringLiteral("%1\n  runs [%2] ms\n  median %3 (min %4), floor %5, ratio %6, target <= %7x: %8\n  %9")
            .arg(name, each.join(QStringLiteral(", ")), ms(m), ms(*std::min_element(runs.begin(), runs.end())),
                 ms(floorMs), QString::number(ratio, 'f', 3), QString::number(limit, 'f', 2),
                 pass ? QStringLiteral("PASS") : QStringLiteral("MISS"), note));
}

struct Client
{
    std::unique_ptr<DriveConnection> connection;
    QList<Drive *> drives;
    Frames frames;
    Error error;
};

std::unique_ptr<Client> connectTo(const ConnectionSettings &settings, int drives)
{
    auto c = std::make_unique<Client>();
    c->connection = std::make_unique<DriveConnection>();
    if (!c->connection->open(settings, &c->error))
        return c;
    QObject::connect(c->connection->tap(), &TrafficTap::frameRecorded, c->connection.get(),
                     [f = &c->frames](const TrafficRecord &r) {
                         if (r.direction == TrafficRecord::Direction::Tx) {
                             f->tx << int(r.bytes.size());
                             f->txPeer << (r.bytes.isEmpty() ? -1 : int(quint8(r.bytes.at(0))));
                             if (f->lastRxUs >= 0 && !r.isCan)
                                 f->gapsUs << r.timestampUs - f->lastRxUs;
                         } else if (r.direction == TrafficRecord::Direction::Rx
                                    && !(r.isCan && (r.canId & 0x780) == 0x700)) {
                             f->rx << int(r.bytes.size());
                             f->lastRxUs = r.timestampUs;
                         }
                     });
    for (int a = 1; a <= drives; ++a)
        c->drives << c->connection->drive(a);
    // A CAN bus connects asynchronously: wait until every drive has answered once, one after
    // the other (what the timed runs measure is the fleet job, not the first contact).
    for (Drive *d : std::as_const(c->drives)) {
        for (int attempt = 0; attempt < 20; ++attempt) {
            DriveReply *r = d->refreshIdentity();
            QSignalSpy spy(r, &DriveReply::finished);
            if (!r->isFinished())
                spy.wait(3000);
            c->error = r->error();
            r->deleteLater();
            if (!c->error)
                break;
        }
        if (c->error)
            break;
    }
    return c;
}

// Runs one fleet job; the elapsed time in ms, or -1 when a drive failed.
double runJob(Client &c, const std::function<void(FleetTransfer &)> &start, QString *why)
{
    FleetTransfer t(c.drives);
    QSignalSpy spy(&t, &FleetTransfer::finished);
    c.frames.clear();
    QElapsedTimer timer;
    timer.start();
    start(t);
    if (spy.isEmpty() && !spy.wait(60000)) {
        *why = QStringLiteral("the job hangs");
        return -1;
    }
    const double elapsed = double(timer.nsecsElapsed()) / 1e6;
    for (const FleetDriveResult &r : t.results()) {
        if (r.state != FleetDriveResult::State::Done) {
            *why = QStringLiteral("drive %1: %2").arg(r.address).arg(r.error.message);
            return -1;
        }
    }
    return elapsed;
}

void benchModbusBackup()
{
    const QString name = QStringLiteral("backup 8 servo-modbus drives PA0-PA59 @ 115200");
    if (!g_only.isEmpty() && !name.contains(g_only))
        return;
    SimHost host;
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = 115200;
    for (int a = 1; a <= 8; ++a)
        o.addresses << a;
    if (Error e = host.start(o))
        return out(name + QStringLiteral(": FAILED: ") + e.message);
    ConnectionSettings cs;
    host.run([&] { cs = host.bench()->clientSettings(); });
    auto c = connectTo(cs, 8);
    if (c->error)
        return out(name + QStringLiteral(": FAILED: ") + c->error.message);
    QList<double> runs;
    double floorUs = 0;
    for (int i = 0; i < g_runs; ++i) {
        QString why;
        const double t = runJob(
            *c, [](FleetTransfer &f) { f.backup(); }, &why);
        if (t < 0)
            return out(name + QStringLiteral(": FAILED: ") + why);
        runs << t;
        floorUs = serialFloorUs(c->frames, 115200, SimSerialDevice::DefaultLatencyUs);
    }
    report(name, runs, floorUs / 1000, 1.15,
           QStringLiteral("%1 transactions per drive (identification + reads of 20 registers); the floor is "
                          "the sum of the 8 drives' wire floors; %2")
               .arg(c->frames.tx.size() / 8.0)
               .arg(c->frames.gapText()));
}

void benchCanBackup()
{
    const QString name = QStringLiteral("backup 8 servo-can drives x 220 parameters @ 1 Mbit/s");
    if (!g_only.isEmpty() && !name.contains(g_only))
        return;
    SimHost host;
    SimBenchOptions o;
    o.family = Family::ServoCan;
    o.can = QStringLiteral("virtualcan:auto");
    for (int a = 1; a <= 8; ++a)
        o.addresses << a;
    if (Error e = host.start(o))
        return out(name + QStringLiteral(": FAILED: ") + e.message);
    ConnectionSettings cs;
    host.run([&] { cs = host.bench()->clientSettings(); });
    auto c = connectTo(cs, 8);
    if (c->error)
        return out(name + QStringLiteral(": FAILED: ") + c->error.message);
    QList<double> runs;
    double floorUs = 0;
    for (int i = 0; i < g_runs; ++i) {
        QString why;
        const double t = runJob(
            *c, [](FleetTransfer &f) { f.backup(); }, &why);
        if (t < 0)
            return out(name + QStringLiteral(": FAILED: ") + why);
        runs << t;
        floorUs = canFloorUs(int(c->frames.tx.size()), cs.bitrate ? cs.bitrate : 1000000,
                             SimCanDevice::DefaultLatencyUs);
    }
    report(name, runs, floorUs / 1000, 1.2,
           QStringLiteral("%1 requests per drive, the reads of the 8 stations pipelined together")
               .arg(c->frames.tx.size() / 8.0));
}

void benchModbusRestore()
{
    const QString name = QStringLiteral("restore 1 file to 8 servo-modbus drives, 10 differences each @ 115200");
    if (!g_only.isEmpty() && !name.contains(g_only))
        return;
    SimHost host;
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = 115200;
    for (int a = 1; a <= 8; ++a)
        o.addresses << a;
    if (Error e = host.start(o))
        return out(name + QStringLiteral(": FAILED: ") + e.message);
    ConnectionSettings cs;
    host.run([&] { cs = host.bench()->clientSettings(); });
    auto c = connectTo(cs, 8);
    if (c->error)
        return out(name + QStringLiteral(": FAILED: ") + c->error.message);
    // The file: 10 values (not adjacent: 10 writes of their own) that no drive holds; before
    // each run the drives get their old values back.
    const QList<int> differing = {10, 13, 16, 19, 22, 25, 28, 31, 34, 37};
    BackupFile file;
    file.setFamily(Family::ServoModbus);
    file.setFirmware(QStringLiteral("7051"));
    ParameterSet values;
    host.run([&] {
        auto *d = static_cast<SimServoModbusDrive *>(host.bench()->serialBus()->device(0));
        for (int i = 0; i < 60; ++i)
            values.set(i, d->parameter(i));
    });
    for (int i : differing)
        values.set(i, 2000 + i);
    file.setValues(values);
    // The identification alone (each drive once, as the restore does first).
    c->frames.clear();
    for (Drive *d : std::as_const(c->drives)) {
        DriveReply *r = d->refreshIdentity();
        QSignalSpy spy(r, &DriveReply::finished);
        if (!r->isFinished())
            spy.wait(3000);
        r->deleteLater();
    }
    const double identUs = serialFloorUs(c->frames, 115200, SimSerialDevice::DefaultLatencyUs);
    // The reads that find the differences cost what a backup's do: measured on the wire.
    QString why;
    if (runJob(
            *c, [](FleetTransfer &f) { f.backup(); }, &why)
        < 0)
        return out(name + QStringLiteral(": FAILED: ") + why);
    const double readsUs = serialFloorUs(c->frames, 115200, SimSerialDevice::DefaultLatencyUs);
    QList<double> runs;
    double floorUs = 0;
    for (int i = 0; i < g_runs; ++i) {
        host.run([&] {
            for (int a = 0; a < 8; ++a) {
                auto *d = static_cast<SimServoModbusDrive *>(host.bench()->serialBus()->device(a));
                for (int p : differing)
                    d->setParameter(p, quint16(100 + p));
            }
        });
        const double t = runJob(
            *c, [&](FleetTransfer &f) { f.restore(file, {}); }, &why);
        if (t < 0)
            return out(name + QStringLiteral(": FAILED: ") + why);
        runs << t;
        floorUs = serialFloorUs(c->frames, 115200, SimSerialDevice::DefaultLatencyUs);
    }
    const double writesUs = floorUs - readsUs;
    report(name, runs, floorUs / 1000, 1.3,
           QStringLiteral("%1 transactions per drive: identification, 3 reads to find the differences, 10 "
                          "writes, their read-backs. The writes and read-backs alone: floor %2, ratio %3 "
                          "(the reads that find the differences: %4, of which the identification %5). "
                          "Best any restore that reads first can do against the writes and read-backs: "
                          "%6x (%7x without the identification); %8")
               .arg(c->frames.tx.size() / 8.0)
               .arg(ms(writesUs / 1000), QString::number(median(runs) / (writesUs / 1000), 'f', 3), ms(readsUs / 1000),
                    ms(identUs / 1000), QString::number(floorUs / writesUs, 'f', 3),
                    QString::number((floorUs - identUs) / writesUs, 'f', 3), c->frames.gapText()));
}

} // namespace

int main(int argc, char **argv)
{
    dd::pinLocalTimeZone();           // before any thread: see localtimezone.h
    dd::preferPlainEventDispatcher(); // before the application object: see eventdispatcherchoice.h
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false\ndrivedesk.*.info=false\n"
                                                    "qt.canbus.*.warning=false\nqt.canbus.*.debug=false\n"));
    const QStringList args = app.arguments();
    for (int i = 1; i < args.size(); ++i) {
        if (args.at(i) == QLatin1String("--runs") && i + 1 < args.size())
            g_runs = std::max(1, args.at(++i).toInt());
        else if (args.at(i) == QLatin1String("--only") && i + 1 < args.size())
            g_only = args.at(++i);
    }
    benchModbusBackup();
    benchCanBackup();
    benchModbusRestore();
    return g_misses ? 1 : 0;
}
