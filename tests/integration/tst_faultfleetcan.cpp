// Several servo-can drives at once under faults (FleetTransfer, as the CLI's --all runs it):
// 8 simulated stations on one virtual CAN bus, 5 % of every station's replies dropped and 5 %
// corrupted (a bit flipped: a faulty drive, which only confirmed reads catch — the
// servo-can.confirmReads option is on, as docs/reliability.md advises for such a bus).
//  - backup: each station's values exactly as the drive holds them, or the station is
//    reported failed with where it stopped;
//  - restore of one file with 10 differences to all 8: never a wrong value written, a
//    verified parameter is one the drive holds, and the report names exactly the
//    parameters each drive took (an unconfirmed one says it may or may not have).
#include <QtTest>

#include "core/common/coreresources.h"
#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h"
#include "core/fleet/fleettransfer.h"
#include "core/params/backupfile.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simcanbus.h"
#include "sim/servocan/simservocandrive.h"
#include "tests/integration/faultcheck.h"

#include <memory>

using namespace dd;

class TestFaultFleetCan : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void backupUnderFaults();
    void restoreUnderFaults();

private:
    static constexpr int Stations = 8;
    SimServoCanDrive *sim(int station) const
    {
        return static_cast<SimServoCanDrive *>(m_bench->canBus()->device(station - 1));
    }
    QList<Drive *> drives();
    bool run(FleetTransfer &t, const std::function<void()> &start);
    void setFaults(quint32 seed);
    // Not adjacent, no communication or control-mode setting (P4, P74, P75), no loop gain.
    static QList<int> differing() { return {10, 13, 16, 19, 22, 25, 28, 31, 34, 37}; }

    std::unique_ptr<SimBench> m_bench;
    std::unique_ptr<DriveConnection> m_connection;
};

void TestFaultFleetCan::initTestCase()
{
    ensureCoreResources();
    m_bench = std::make_unique<SimBench>();
    SimBenchOptions o;
    o.family = Family::ServoCan;
    o.can = QStringLiteral("virtualcan:auto");
    for (int a = 1; a <= Stations; ++a)
        o.addresses << a;
    const Error e = m_bench->start(o);
    if (e)
        QSKIP(qPrintable(e.message));
    m_connection = std::make_unique<DriveConnection>();
    ConnectionSettings cs = m_bench->clientSettings();
    cs.retries = 3;
    cs.options.insert(QStringLiteral("servo-can.confirmReads"), true);
    Error oe;
    QVERIFY2(m_connection->open(cs, &oe), qPrintable(oe.message));
}

void TestFaultFleetCan::cleanupTestCase()
{
    m_connection.reset();
    m_bench.reset();
}

QList<Drive *> TestFaultFleetCan::drives()
{
    QList<Drive *> list;
    for (int a = 1; a <= Stations; ++a)
        list << m_connection->drive(a);
    return list;
}

bool TestFaultFleetCan::run(FleetTransfer &t, const std::function<void()> &start)
{
    QSignalSpy spy(&t, &FleetTransfer::finished);
    start();
    return spy.count() > 0 || spy.wait(60000);
}

void TestFaultFleetCan::setFaults(quint32 seed)
{
    for (int a = 1; a <= Stations; ++a) {
        FaultSettings f;
        f.dropRate = 0.05;
        f.corruptRate = 0.05;
        f.seed = seed + quint32(a);
        sim(a)->faults().setSettings(f);
    }
}

void TestFaultFleetCan::backupUnderFaults()
{
    for (int a = 1; a <= Stations; ++a)
        sim(a)->setParameter(30, qint16(3000 + a)); // each station its own value
    setFaults(40);
    FleetTransfer t(drives());
    QVERIFY2(run(t, [&] { t.backup(); }), "the backup of 8 stations hangs");
    int done = 0;
    for (int a = 1; a <= Stations; ++a) {
        const FleetDriveResult &r = t.results().at(a - 1);
        QCOMPARE(r.address, a);
        if (r.state == FleetDriveResult::State::Failed) {
            QVERIFY(r.error.isError());
            QVERIFY(!r.stoppedAt.isEmpty());
            continue;
        }
        QCOMPARE(r.state, FleetDriveResult::State::Done);
        ++done;
        QCOMPARE(r.backup.values().size(), 220);
        for (int i = 0; i < 220; ++i)
            QCOMPARE(r.backup.values().value(i), std::optional<qint64>(sim(a)->parameter(i)));
    }
    const SimCanBusStats &s = m_bench->canBus()->stats();
    qInfo("%d of %d servo-can backups complete under 10 %% faults (%llu frames dropped, %llu corrupted so far)", done,
          Stations, static_cast<unsigned long long>(s.framesDropped),
          static_cast<unsigned long long>(s.framesCorrupted));
    QVERIFY2(s.framesDropped > 20 && s.framesCorrupted > 20, "the faults were felt");
    QVERIFY(done >= Stations / 2); // confirmed reads and retries make most of them complete
}

void TestFaultFleetCan::restoreUnderFaults()
{
    for (int a = 1; a <= Stations; ++a)
        sim(a)->faults().setSettings({});
    BackupFile file;
    file.setFamily(Family::ServoCan);
    file.setAddress(1);
    ParameterSet v;
    for (int i = 0; i < 220; ++i)
        v.set(i, sim(1)->parameter(i));
    for (int i : differing())
        v.set(i, 1000 + i);
    file.setValues(v);
    QMap<int, SimServoCanDrive::Parameters> before;
    for (int a = 1; a <= Stations; ++a) {
        for (int i : differing())
            sim(a)->setParameter(i, qint16(a * 10 + i));
        sim(a)->setParameter(30, sim(1)->parameter(30)); // only the 10 differ from the file
        before.insert(a, sim(a)->parameters());
    }
    setFaults(70);
    const quint64 faultsBefore = m_bench->canBus()->stats().framesDropped + m_bench->canBus()->stats().framesCorrupted;
    FleetTransfer t(drives());
    QVERIFY2(run(t, [&] { t.restore(file, {}); }), "the restore to 8 stations hangs");
    QVERIFY2(m_bench->canBus()->stats().framesDropped + m_bench->canBus()->stats().framesCorrupted > faultsBefore + 10,
             "the faults were felt");
    int exact = 0;
    for (int a = 1; a <= Stations; ++a) {
        const FleetDriveResult &r = t.results().at(a - 1);
        const RestoreReport &rep = r.report;
        QSet<int> changed;
        for (int i = 0; i < 220; ++i) {
            const qint16 now = sim(a)->parameter(i);
            if (now != before[a][size_t(i)]) {
                changed.insert(i);
                QCOMPARE(std::optional<qint64>(now), file.values().value(i)); // never a wrong value
            }
        }
        for (int i : rep.indices(RestoreReport::Outcome::Verified))
            QCOMPARE(std::optional<qint64>(sim(a)->parameter(i)), file.values().value(i));
        const QList<int> written = rep.written();
        QSet<int> reported(written.begin(), written.end());
        for (int i : rep.indices(RestoreReport::Outcome::Unconfirmed))
            changed.remove(i);
        QCOMPARE(changed, reported);
        if (r.state == FleetDriveResult::State::Done) {
            ++exact;
            QVERIFY(rep.isComplete());
            for (int i : differing())
                QCOMPARE(std::optional<qint64>(sim(a)->parameter(i)), file.values().value(i));
        } else {
            QCOMPARE(r.state, FleetDriveResult::State::Failed);
            QVERIFY(r.error.isError());
        }
        QCOMPARE(int(sim(a)->parameter(75)), int(before[a][75])); // the station number is never copied
    }
    qInfo("%d of %d servo-can restores complete under 10 %% faults", exact, Stations);
    QVERIFY(exact >= Stations / 2);
}

QTEST_GUILESS_MAIN(TestFaultFleetCan)
#include "tst_faultfleetcan.moc"
