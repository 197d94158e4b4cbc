// Fault injection against the servo-can host stack (ServoCanBackend: CanLink, station
// tracker, ServoCanDrive) and SimServoCanDrive on SimCanBus, over a private VirtualCanHub:
//  - 5-10 % dropped, corrupted and late frames (later than the 50 ms timeout): a full backup
//    of the 220 parameters either holds every value the drive really has, or fails with a
//    clear message and leaves no file (an older backup at the path stays byte for byte).
//    Corruption: a real CAN controller discards a damaged frame (CRC); the simulator's
//    corrupt fault models a faulty drive, which only confirmed reads catch
//    (option servo-can.confirmReads), so that row runs with them;
//  - the drive going silent mid-backup: failure, no file;
//  - the drive going silent mid-restore: the report names exactly the parameters verified,
//    which are exactly the ones the drive changed;
//  - the CAN bus going away mid-backup (the hub's process ends): LinkClosed at once; the
//    simulator's adapter leaving the bus: Timeout within the retries, no hang.
#include <QtTest>

#include "core/drive/servocan/servocanbackend.h"
#include "core/drive/servocan/servocandrive.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/link/canlink.h"
#include "core/protocol/servocan/servocan.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"
#include "tests/integration/faultcheck.h"
#include "tests/support/simcanconnect.h"

#include <QTemporaryDir>

#include <memory>
#include <random>

using namespace dd;
using namespace dd::faultcheck;
namespace sc = dd::servocan;

class TestFaultServoCan : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void backupUnderFaults_data();
    void backupUnderFaults();
    void silentMidBackup();
    void silentMidRestore();
    void busGoneMidBackup();
    void simulatorLeavesTheBusMidBackup();

private:
    bool openBackend(int retries);
    ServoCanDrive *drive() { return m_backend->servoDrive(1); }
    qint64 value(int p) const { return m_sim->parameter(p); }
    void scramble(std::mt19937 &rng);
    static bool isCommand(const CanFrameData &f, sc::Command c)
    {
        return f.data.size() == 8 && quint8(f.data.at(1)) == quint8(c);
    }

    QTemporaryDir m_dir;
    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    SimServoCanDrive *m_sim = nullptr;
    std::unique_ptr<ServoCanBackend> m_backend;
};

void TestFaultServoCan::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

void TestFaultServoCan::init()
{
    m_hub = std::make_unique<VirtualCanHub>();
    QVERIFY(m_hub->start());
    m_bus = std::make_unique<SimCanBus>();
    m_sim = static_cast<SimServoCanDrive *>(m_bus->addDevice(std::make_unique<SimServoCanDrive>(1)));
    const QString busError = test::connectSimCanBus(m_bus.get(), m_hub->interfaceName(0));
    QVERIFY2(busError.isEmpty(), qPrintable(busError));
    QVERIFY(openBackend(-1));
}

// The host side; retries -1: the default (2).
bool TestFaultServoCan::openBackend(int retries)
{
    m_backend.reset();
    ConnectionSettings cs;
    cs.family = Family::ServoCan;
    cs.can = QStringLiteral("virtualcan:") + m_hub->interfaceName(0); // timeout 50 ms
    cs.retries = retries;
    m_backend = std::make_unique<ServoCanBackend>();
    Error oe;
    if (!m_backend->open(cs, nullptr, &oe)) {
        qWarning() << oe.message;
        return false;
    }
    return waitUntil([this] { return m_backend->tracker()->isOnline(1); }, 3000);
}

void TestFaultServoCan::cleanup()
{
    m_backend.reset();
    m_bus.reset();
    m_hub.reset();
}

// Values within the dictionary's ranges (the backup file checks them), distinct enough that
// a value shifted to another parameter shows. P4, P74, P75 keep the drive in CAN mode.
void TestFaultServoCan::scramble(std::mt19937 &rng)
{
    for (const ParameterInfo &p : drive()->parameterDictionary().parameters()) {
        if (p.index == 4 || p.index == 74 || p.index == 75)
            continue;
        const qint64 span = qint64(p.max) - p.min + 1;
        m_sim->setParameter(p.index, qint16(p.min + qint64(rng() % quint32(span))));
    }
}

void TestFaultServoCan::backupUnderFaults_data()
{
    QTest::addColumn<QString>("faults");
    QTest::addColumn<bool>("confirmReads");
    QTest::addColumn<int>("rounds");
    QTest::addColumn<int>("retries");     // -1: the default, 2
    QTest::addColumn<int>("minComplete"); // measured on a loaded 2-core machine: docs/reliability.md
    // 10 % of the replies lost: with 2 retries a read is lost with p^3 = 1/1000, one
    // 220-read backup in five fails (measured 2-5 of 5); on such a bus the user raises the
    // retries (the message says so), as this row does: p^4, about one backup in fifty.
    QTest::newRow("drop 10%") << "drop=0.10,seed=31" << false << 5 << 3 << 4;
    QTest::newRow("corrupt 10%") << "corrupt=0.10,seed=32" << true << 4 << -1 << 3; // 4 of 4 in 6 runs
    // 0..55 ms extra: about one frame in eleven arrives after the 50 ms timeout.
    QTest::newRow("late 9%") << "jitter=55,seed=33" << false << 3 << -1 << 2;                        // 3 of 3 in 6 runs
    QTest::newRow("mixed 5%") << "drop=0.05,corrupt=0.05,jitter=52,seed=34" << true << 3 << -1 << 2; // 3 of 3
}

void TestFaultServoCan::backupUnderFaults()
{
    QFETCH(QString, faults);
    QFETCH(bool, confirmReads);
    QFETCH(int, rounds);
    QFETCH(int, retries);
    QFETCH(int, minComplete);
    if (retries >= 0)
        QVERIFY(openBackend(retries));
    drive()->setConfirmReads(confirmReads);
    m_sim->faults().setSettings(*FaultSettings::parse(faults));
    CanLink *link = m_backend->link();
    std::mt19937 rng(9);
    int ok = 0;
    qint64 slowest = 0;
    for (int round = 0; round < rounds; ++round) {
        scramble(rng);
        const QString path = m_dir.filePath(QStringLiteral("c-%1-%2.json").arg(QTest::currentDataTag()).arg(round));
        QByteArray old;
        if (round % 2) {
            old = "{\"an older backup\": true}\n";
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(old);
        }
        const BackupOutcome o = backupToFile(drive(), path);
        QVERIFY2(o.finished, "a backup must never hang");
        slowest = std::max(slowest, o.elapsedMs);
        if (o.error.isError()) {
            QVERIFY2(isClearError(o.error), qPrintable(o.error.message));
            if (old.isEmpty())
                QVERIFY2(!QFile::exists(path), "a failed backup leaves no file");
            else
                QCOMPARE(fileBytes(path), old);
            qInfo().noquote() << "failed backup:" << o.error.message;
            continue;
        }
        ++ok;
        BackupFile loaded;
        const Error le = loaded.load(path);
        QVERIFY2(!le.isError(), qPrintable(le.message));
        QCOMPARE(loaded.values().size(), 220);
        for (int p = 0; p < 220; ++p)
            QCOMPARE(*loaded.values().value(p), value(p));
    }
    const SimCanBusStats &s = m_bus->stats();
    qInfo("%s%s: %d of %d backups complete; %llu frames dropped, %llu corrupted; %llu timeouts, "
          "%llu retries; slowest backup %lld ms",
          qPrintable(faults), confirmReads ? " (confirmed reads)" : "", ok, rounds,
          static_cast<unsigned long long>(s.framesDropped), static_cast<unsigned long long>(s.framesCorrupted),
          static_cast<unsigned long long>(link->timeoutCount()), static_cast<unsigned long long>(link->retryCount()),
          static_cast<long long>(slowest));
    QVERIFY2(link->retryCount() > 0, "the faults were felt");
    // Every completed backup held exactly the drive's values (checked above: 0 wrong).
    QVERIFY2(ok >= minComplete, qPrintable(QStringLiteral("%1 of %2 backups complete").arg(ok).arg(rounds)));
}

void TestFaultServoCan::silentMidBackup()
{
    int replies = 0;
    connect(m_bus.get(), &SimCanBus::frameSent, this, [&](const CanFrameData &f) {
        if (isCommand(f, sc::Command::Read) && ++replies == 80)
            m_sim->faults().setSilent(true);
    });
    const QString path = m_dir.filePath(QStringLiteral("silent.json"));
    const BackupOutcome o = backupToFile(drive(), path);
    QVERIFY(o.finished);
    QCOMPARE(o.error.code, ErrorCode::Timeout);
    QVERIFY2(o.error.message.contains(QStringLiteral("Station 1")), qPrintable(o.error.message));
    QVERIFY2(o.error.message.contains(QStringLiteral("no heartbeat")), qPrintable(o.error.message));
    QVERIFY(!QFile::exists(path));
    qInfo("silent mid-backup: failed after %lld ms: %s", static_cast<long long>(o.elapsedMs),
          qPrintable(o.error.message));
}

void TestFaultServoCan::silentMidRestore()
{
    const BackupOutcome base = backupToFile(drive(), m_dir.filePath(QStringLiteral("base.json")));
    QVERIFY2(!base.error.isError(), qPrintable(base.error.message));
    BackupFile file = base.file;
    ParameterSet values = file.values();
    QMap<int, qint64> old;
    for (int p = 100; p < 120; p += 2) {
        old.insert(p, value(p));
        values.set(p, value(p) + 11);
    }
    file.setValues(values);
    int seen = 0;
    // Direct: the drive goes silent as the fifth write reaches the bus, before it hears it.
    connect(
        m_bus.get(), &SimCanBus::frameReceived, this,
        [&](const CanFrameData &f) {
            if (isCommand(f, sc::Command::Write) && ++seen == 5)
                m_sim->faults().setSilent(true);
        },
        Qt::DirectConnection);
    const RestoreOutcome o = restoreFrom(drive(), file);
    QVERIFY2(o.finished, "a restore must never hang");
    QVERIFY(isClearError(o.error));
    const RestoreReport &r = o.report;
    QCOMPARE(r.selected.size(), 10);
    const QString lie = dishonesty(
        r.results, [&](int p) { return value(p); }, [&](int p) { return old.value(p); });
    QVERIFY2(lie.isEmpty(), qPrintable(lie));
    QList<int> changed;
    for (const DiffEntry &e : r.selected)
        if (value(e.index) != old.value(e.index))
            changed << e.index;
    // Exactly the parameters the drive changed are reported verified (and written); the
    // others are unconfirmed: the protocol acknowledges no write, and no read-back came.
    QCOMPARE(r.indices(RestoreReport::Outcome::Verified), changed);
    QCOMPARE(r.written(), changed);
    QCOMPARE(changed.size(), 4);
    QCOMPARE(r.indices(RestoreReport::Outcome::Unconfirmed).size(), 6);
    qInfo("silent mid-restore: %s", qPrintable(describe(r)));
    qInfo("  %s", qPrintable(o.error.message));
}

void TestFaultServoCan::busGoneMidBackup()
{
    int reads = 0;
    connect(m_bus.get(), &SimCanBus::frameReceived, this, [&](const CanFrameData &f) {
        if (isCommand(f, sc::Command::Read) && ++reads == 60)
            QMetaObject::invokeMethod(
                this, [this] { m_hub.reset(); }, Qt::QueuedConnection);
    });
    const QString path = m_dir.filePath(QStringLiteral("busgone.json"));
    const BackupOutcome o = backupToFile(drive(), path, 3000);
    QVERIFY2(o.finished, "the backup must not hang when the bus goes");
    QCOMPARE(o.error.code, ErrorCode::LinkClosed);
    QVERIFY(isClearError(o.error));
    QVERIFY(!QFile::exists(path));
    QVERIFY2(o.elapsedMs < 1000, "LinkClosed is reported at once");
    qInfo("bus gone mid-backup: failed after %lld ms: %s", static_cast<long long>(o.elapsedMs),
          qPrintable(o.error.message));
}

void TestFaultServoCan::simulatorLeavesTheBusMidBackup()
{
    int reads = 0;
    connect(m_bus.get(), &SimCanBus::frameReceived, this, [&](const CanFrameData &f) {
        if (isCommand(f, sc::Command::Read) && ++reads == 60)
            QMetaObject::invokeMethod(
                this, [this] { m_bus->close(); }, Qt::QueuedConnection);
    });
    const QString path = m_dir.filePath(QStringLiteral("simgone.json"));
    const BackupOutcome o = backupToFile(drive(), path, 3000);
    QVERIFY2(o.finished, "the backup must not hang when the drives leave the bus");
    QCOMPARE(o.error.code, ErrorCode::Timeout);
    QVERIFY2(o.error.message.contains(QStringLiteral("no heartbeat")), qPrintable(o.error.message));
    QVERIFY(!QFile::exists(path));
    qInfo("simulator gone mid-backup: failed after %lld ms: %s", static_cast<long long>(o.elapsedMs),
          qPrintable(o.error.message));
}

QTEST_GUILESS_MAIN(TestFaultServoCan)
#include "tst_faultservocan.moc"
