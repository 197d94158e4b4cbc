// drivedesk-cli on 8 simulated servo-can stations (1-8) on one CAN bus at 1 Mbit/s (SimBench
// in this process, a private virtualcan hub): backup --all, restore --all with the station
// number (P75) left alone, --stop-on-failure, diff drive:A drive:B.
#include "tests/support/clirun.h"

#include "core/common/coreresources.h"
#include "core/params/backupfile.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simcanbus.h"
#include "sim/servocan/simservocandrive.h"

#include <QDir>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd;
using namespace dd::test;

class TestCliFleetCan : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void backupAllAndRestoreAll();
    void stopOnFailure();
    void diffTwoStations();

private:
    QStringList args(std::initializer_list<const char *> words) const;
    SimServoCanDrive *sim(int station) const;

    QTemporaryDir m_dir;
    SimBench m_bench;
    QString m_can;
};

QStringList TestCliFleetCan::args(std::initializer_list<const char *> words) const
{
    // A generous timeout: the simulator shares this process with the waiting test, and CI
    // runs the suite on a loaded machine (and under ASan).
    QStringList l{QStringLiteral("--family"),  QStringLiteral("servo-can"), QStringLiteral("--can"), m_can,
                  QStringLiteral("--timeout"), QStringLiteral("300")};
    for (const char *w : words)
        l << QString::fromUtf8(w);
    return l;
}

SimServoCanDrive *TestCliFleetCan::sim(int station) const
{
    return static_cast<SimServoCanDrive *>(m_bench.canBus()->device(station - 1));
}

void TestCliFleetCan::initTestCase()
{
    ensureCoreResources();
    QVERIFY(m_dir.isValid());
    SimBenchOptions o;
    o.family = Family::ServoCan;
    o.can = QStringLiteral("virtualcan:auto");
    for (int a = 1; a <= 8; ++a)
        o.addresses << a;
    const Error e = m_bench.start(o);
    if (e)
        QSKIP(qPrintable(e.message));
    m_can = m_bench.clientSettings().can;
}

void TestCliFleetCan::backupAllAndRestoreAll()
{
    const QString dir = m_dir.filePath(QStringLiteral("all"));
    sim(3)->setParameter(100, 333);
    CliRun r = runCli(args({"--json", "backup", "--all", "-o"}) << dir);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("drives").toArray().size(), 8);
    BackupFile three;
    QVERIFY(!three.load(QDir(dir).filePath(QStringLiteral("servo-can-3.json"))));
    QCOMPARE(three.values().value(100), std::optional<qint64>(333));
    QCOMPARE(three.values().value(75), std::optional<qint64>(3));

    for (int a = 1; a <= 8; ++a)
        if (a != 3)
            sim(a)->setParameter(101, qint16(a));
    r = runCli(args({"--json", "restore", "--all"}) << QDir(dir).filePath(QStringLiteral("servo-can-3.json")));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    const QJsonArray drives = r.json().value("drives").toArray();
    QCOMPARE(drives.size(), 8);
    for (int a = 1; a <= 8; ++a) {
        QCOMPARE(sim(a)->parameter(100), qint16(333));
        QCOMPARE(sim(a)->parameter(101), sim(3)->parameter(101));
        QCOMPARE(sim(a)->parameter(75), qint16(a)); // the station number is left alone
        if (a != 3)
            QCOMPARE(drives.at(a - 1).toObject().value("verified").toArray(), (QJsonArray{"P100", "P101"}));
    }
}

void TestCliFleetCan::stopOnFailure()
{
    const QString file = m_dir.filePath(QStringLiteral("one.json"));
    sim(1)->setParameter(120, 1200);
    QCOMPARE(runCli(args({"--address", "1", "backup", "-o"}) << file).exitCode, 0);
    sim(3)->setWriteProtected(120, true);
    const CliRun r = runCli(args({"--json", "--address", "2,3,4,5", "restore", "--stop-on-failure"}) << file);
    sim(3)->setWriteProtected(120, false);
    QCOMPARE(r.exitCode, 1);
    const QJsonArray drives = r.json().value("drives").toArray();
    QCOMPARE(drives.at(0).toObject().value("result").toString(), QStringLiteral("done"));
    QCOMPARE(drives.at(1).toObject().value("result").toString(), QStringLiteral("failed"));
    QCOMPARE(drives.at(1).toObject().value("stoppedAt").toString(), QStringLiteral("write"));
    QCOMPARE(drives.at(1).toObject().value("mismatch").toArray(), QJsonArray{"P120"});
    QCOMPARE(drives.at(2).toObject().value("result").toString(), QStringLiteral("not-attempted"));
    QCOMPARE(drives.at(3).toObject().value("result").toString(), QStringLiteral("not-attempted"));
    QCOMPARE(sim(2)->parameter(120), qint16(1200));
    QVERIFY(sim(4)->parameter(120) != 1200);
    QVERIFY(sim(5)->parameter(120) != 1200);
}

void TestCliFleetCan::diffTwoStations()
{
    sim(6)->setParameter(150, qint16(sim(7)->parameter(150) + 1));
    const CliRun r = runCli(args({"--json", "diff", "drive:6", "drive:7"}));
    QCOMPARE(r.exitCode, 1);
    QStringList differing;
    for (const QJsonValue &v : r.json().value("parameters").toArray())
        if (v.toObject().value("status").toString() == QLatin1String("different"))
            differing << v.toObject().value("key").toString();
    QCOMPARE(differing, (QStringList{"P75", "P150"}));
}

QTEST_GUILESS_MAIN(TestCliFleetCan)
#include "tst_clifleetcan.moc"
