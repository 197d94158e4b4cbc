// Several drives at once under faults (FleetTransfer, as the CLI's --all and the GUI's
// multi-drive apply run it), on 8 simulated servo-modbus drives on one RS485 link at 115200:
//  - 10 % of the replies dropped or corrupted on every drive: each drive's backup holds
//    exactly the drive's values or the drive is reported failed; each drive's restore is
//    exact or reported failed, never a wrong value written or reported verified, and the
//    report names exactly the parameters each drive took;
//  - one drive going silent in the middle: the others complete, its report says where it
//    stopped (and which parameters it took before);
//  - the link vanishing (the adapter's pty closed): no hang, every drive failed or not
//    attempted with the reason.
#include <QtTest>

#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h"
#include "core/fleet/fleettransfer.h"
#include "core/params/backupfile.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/integration/faultcheck.h"

#include <memory>

using namespace dd;
using namespace dd::faultcheck;

class TestFaultFleet : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void backupUnderFaults();
    void restoreUnderFaults();
    void silentDriveMidRestore();
    void linkVanishesMidRestore();

private:
    SimServoModbusDrive *sim(int address) const
    {
        return static_cast<SimServoModbusDrive *>(m_bench->serialBus()->device(address - 1));
    }
    QList<Drive *> drives();
    bool run(FleetTransfer &t, const std::function<void()> &start, int hangMs = 20000);
    // The file every restore writes: drive 1's values with 10 differences to all others.
    BackupFile target();
    void differ(); // the drives get 10 values different from the target
    // The 10 parameters that differ: not adjacent, so that each is a write of its own.
    static QList<int> differing() { return {10, 13, 16, 19, 22, 25, 28, 31, 34, 37}; }

    std::unique_ptr<SimBench> m_bench;
    std::unique_ptr<DriveConnection> m_connection;
};

void TestFaultFleet::init()
{
    m_bench = std::make_unique<SimBench>();
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = 115200;
    for (int a = 1; a <= 8; ++a)
        o.addresses << a;
    const Error e = m_bench->start(o);
    if (e)
        QSKIP(qPrintable(e.message));
    m_connection = std::make_unique<DriveConnection>();
    Error oe;
    ConnectionSettings cs = m_bench->clientSettings();
    cs.timeoutMs = 40; // a silent drive costs its timeouts: keep them short
    QVERIFY2(m_connection->open(cs, &oe), qPrintable(oe.message));
}

void TestFaultFleet::cleanup()
{
    m_connection.reset();
    m_bench.reset();
}

QList<Drive *> TestFaultFleet::drives()
{
    QList<Drive *> list;
    for (int a = 1; a <= 8; ++a)
        list << m_connection->drive(a);
    return list;
}

bool TestFaultFleet::run(FleetTransfer &t, const std::function<void()> &start, int hangMs)
{
    QSignalSpy spy(&t, &FleetTransfer::finished);
    start();
    return spy.count() > 0 || spy.wait(hangMs);
}

BackupFile TestFaultFleet::target()
{
    BackupFile f;
    f.setFamily(Family::ServoModbus);
    f.setFirmware(QStringLiteral("7051"));
    f.setAddress(1);
    ParameterSet v;
    for (int i = 0; i < 60; ++i)
        v.set(i, sim(1)->parameter(i));
    for (int i : differing())
        v.set(i, 1000 + i);
    f.setValues(v);
    return f;
}

void TestFaultFleet::differ()
{
    for (int a = 1; a <= 8; ++a)
        for (int i : differing())
            sim(a)->setParameter(i, quint16(a * 10 + i));
}

void TestFaultFleet::backupUnderFaults()
{
    for (int a = 1; a <= 8; ++a) {
        sim(a)->setParameter(30, quint16(3000 + a));
        FaultSettings f;
        f.dropRate = 0.05;
        f.corruptRate = 0.05;
        f.seed = quint32(40 + a);
        sim(a)->faults().setSettings(f);
    }
    FleetTransfer t(drives());
    QVERIFY2(run(t, [&] { t.backup(); }), "the backup of 8 drives hangs");
    int done = 0;
    for (int a = 1; a <= 8; ++a) {
        const FleetDriveResult &r = t.results().at(a - 1);
        QCOMPARE(r.address, a);
        if (r.state == FleetDriveResult::State::Failed) {
            QVERIFY(r.error.isError());
            QVERIFY(!r.stoppedAt.isEmpty());
            continue;
        }
        QCOMPARE(r.state, FleetDriveResult::State::Done);
        ++done;
        QCOMPARE(r.backup.values().size(), 60);
        for (int i = 0; i < 60; ++i)
            QCOMPARE(r.backup.values().value(i), std::optional<qint64>(sim(a)->parameter(i)));
    }
    qInfo("%d of 8 backups complete under 10 %% faults", done);
    QVERIFY(done >= 4); // retries make most of them complete
}

void TestFaultFleet::restoreUnderFaults()
{
    differ();
    const BackupFile file = target();
    QMap<int, SimServoModbusDrive::ParameterArray> before;
    for (int a = 1; a <= 8; ++a) {
        before.insert(a, sim(a)->parameters());
        FaultSettings f;
        f.dropRate = 0.05;
        f.corruptRate = 0.05;
        f.seed = quint32(70 + a);
        sim(a)->faults().setSettings(f);
    }
    FleetTransfer t(drives());
    QVERIFY2(run(t, [&] { t.restore(file, {}); }), "the restore to 8 drives hangs");
    int exact = 0;
    for (int a = 1; a <= 8; ++a) {
        const FleetDriveResult &r = t.results().at(a - 1);
        const RestoreReport &rep = r.report;
        // Never a wrong value: a parameter is either unchanged or holds the file's value.
        QSet<int> changed;
        for (int i = 0; i < 60; ++i) {
            const quint16 now = sim(a)->parameter(i);
            if (now != before[a][size_t(i)]) {
                changed.insert(i);
                QCOMPARE(std::optional<qint64>(now), file.values().value(i));
            }
        }
        // Verified means the drive holds the value.
        for (int i : rep.indices(RestoreReport::Outcome::Verified))
            QCOMPARE(std::optional<qint64>(sim(a)->parameter(i)), file.values().value(i));
        // The report names exactly the parameters the drive took (an unconfirmed one may
        // or may not have been taken: it says so).
        const QList<int> unconfirmed = rep.indices(RestoreReport::Outcome::Unconfirmed);
        const QList<int> written = rep.written();
        QSet<int> reported(written.begin(), written.end());
        QSet<int> changedKnown = changed;
        for (int i : unconfirmed)
            changedKnown.remove(i);
        QCOMPARE(changedKnown, reported);
        if (r.state == FleetDriveResult::State::Done) {
            ++exact;
            QVERIFY(rep.isComplete());
            for (int i : differing())
                QCOMPARE(std::optional<qint64>(sim(a)->parameter(i)), file.values().value(i));
        } else {
            QCOMPARE(r.state, FleetDriveResult::State::Failed);
            QVERIFY(r.error.isError());
        }
        QCOMPARE(sim(a)->parameter(51), quint16(a)); // the address is never copied
    }
    qInfo("%d of 8 restores complete under 10 %% faults", exact);
    QVERIFY(exact >= 4);
}

void TestFaultFleet::silentDriveMidRestore()
{
    differ();
    const BackupFile file = target();
    const auto before = sim(5)->parameters();
    // Drive 5 loses power after its 8th reply: identify (1) and reads (3) are done, some of
    // the 10 writes too.
    int replies = 0;
    connect(m_bench->serialBus(), &SimSerialBus::replyWritten, this, [&](const QByteArray &, qint64, int device) {
        if (device == 4 && ++replies == 8)
            sim(5)->faults().setSilent(true);
    });
    FleetTransfer t(drives());
    QVERIFY2(run(t, [&] { t.restore(file, {}); }), "the restore hangs");
    for (int a = 1; a <= 8; ++a) {
        const FleetDriveResult &r = t.results().at(a - 1);
        if (a != 5) {
            QCOMPARE(r.state, FleetDriveResult::State::Done);
            for (int i : differing())
                QCOMPARE(std::optional<qint64>(sim(a)->parameter(i)), file.values().value(i));
            continue;
        }
        QCOMPARE(r.state, FleetDriveResult::State::Failed);
        QCOMPARE(r.stoppedAt, QStringLiteral("write"));
        QCOMPARE(r.error.code, ErrorCode::Timeout);
        // Where it stopped: the parameters reported written are exactly those it took.
        QSet<int> changed;
        for (int i = 0; i < 60; ++i)
            if (sim(5)->parameter(i) != before[size_t(i)])
                changed.insert(i);
        // (Written, or written with no answer to the read-back: "written, not verified".)
        QSet<int> took;
        for (int i : r.report.written())
            took.insert(i);
        for (int i : r.report.indices(RestoreReport::Outcome::Unconfirmed))
            if (r.report.result(i)->written)
                took.insert(i);
        QCOMPARE(changed, took);
        QVERIFY(took.size() < differing().size());
        // The rest: not written, or unknown (no answer to the write) — never "verified".
        for (int i : differing()) {
            if (took.contains(i))
                continue;
            const RestoreReport::Outcome o = r.report.outcome(i);
            QVERIFY2(o == RestoreReport::Outcome::Failed || o == RestoreReport::Outcome::NotAttempted
                         || o == RestoreReport::Outcome::Unconfirmed,
                     qPrintable(QString::number(i)));
        }
    }
}

void TestFaultFleet::linkVanishesMidRestore()
{
    differ();
    const BackupFile file = target();
    FleetTransfer t(drives());
    connect(m_connection.get(), &DriveConnection::linkLost, &t, &FleetTransfer::abort);
    int replies = 0;
    connect(m_bench->serialBus(), &SimSerialBus::replyWritten, this, [&](const QByteArray &, qint64, int) {
        if (++replies == 12)
            QMetaObject::invokeMethod(
                m_bench.get(), [this] { m_bench->stop(); }, Qt::QueuedConnection);
    });
    QElapsedTimer timer;
    timer.start();
    QVERIFY2(run(
                 t, [&] { t.restore(file, {}); }, 15000),
             "the restore hangs when the link vanishes");
    qInfo("all 8 drives reported %lld ms after the start", timer.elapsed());
    int failed = 0;
    for (const FleetDriveResult &r : t.results()) {
        QVERIFY(r.isFinished());
        if (r.state != FleetDriveResult::State::Done) {
            ++failed;
            QVERIFY2(r.error.isError(), qPrintable(QString::number(r.address)));
            QVERIFY(!r.error.message.isEmpty());
        }
    }
    QVERIFY(failed > 0);
}

QTEST_GUILESS_MAIN(TestFaultFleet)
#include "tst_faultfleet.moc"
