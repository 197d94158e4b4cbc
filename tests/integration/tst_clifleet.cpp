// drivedesk-cli on several drives at once, against a simulated bench of 8 servo-modbus drives
// (addresses 1-8, one RS485 link at 115200, SimBench in this process): backup --all finds
// and saves every drive, restore FILE --all / --address 1,2,5 writes only the differences
// and leaves the communication settings (PA51, the address) alone, the exit code is the
// worst drive's, diff A B in every combination (file/file, file/drive, drive/drive,
// defaults), changed-only files round-trip, and bad inputs exit 2 with nothing sent.
// (servo-can: tst_clifleetcan; faults: tst_faultfleet.)
#include "tests/support/clirun.h"

#include "core/common/coreresources.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd;
using namespace dd::test;

class TestCliFleet : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void backupAllSavesEveryDrive();
    void restoreAllWritesOnlyTheDifferences();
    void restoreAddressListTouchesOnlyThose();
    void worstDriveGivesTheExitCode();
    void diffCombinations();
    void changedOnlyRoundTrip();
    void restoreFolderPutsEachDriveBackFromItsOwnFile();
    void badInputsSendNothing();

private:
    QStringList args(std::initializer_list<const char *> words) const;
    SimServoModbusDrive *sim(int address) const;
    QString writeDictionaryWithDefaults();

    QTemporaryDir m_dir;
    SimBench m_bench;
    QString m_port;
    SimServoModbusDrive::ParameterArray m_factory{};
};

QStringList TestCliFleet::args(std::initializer_list<const char *> words) const
{
    QStringList l{QStringLiteral("--family"), QStringLiteral("servo-modbus"), QStringLiteral("--port"), m_port,
                  QStringLiteral("--baud"),   QStringLiteral("115200")};
    for (const char *w : words)
        l << QString::fromUtf8(w);
    return l;
}

SimServoModbusDrive *TestCliFleet::sim(int address) const
{
    return static_cast<SimServoModbusDrive *>(m_bench.serialBus()->device(address - 1));
}

void TestCliFleet::initTestCase()
{
    ensureCoreResources();
    QVERIFY(m_dir.isValid());
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = 115200;
    for (int a = 1; a <= 8; ++a)
        o.addresses << a;
    const Error e = m_bench.start(o);
    if (e)
        QSKIP(qPrintable(e.message));
    m_port = m_bench.clientSettings().port;
    m_factory = sim(1)->parameters();
}

void TestCliFleet::init()
{
    // Every drive back to the same values (its own address in PA51).
    for (int a = 1; a <= 8; ++a)
        for (int i = 0; i < int(m_factory.size()); ++i)
            if (i != 51)
                sim(a)->setParameter(i, m_factory[size_t(i)]);
}

void TestCliFleet::backupAllSavesEveryDrive()
{
    sim(4)->setParameter(20, 4444);
    const QString dir = m_dir.filePath(QStringLiteral("all"));
    const CliRun r = runCli(args({"--json", "--timeout", "100", "backup", "--all", "--to", "12", "-o"}) << dir);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    const QJsonArray drives = r.json().value("drives").toArray();
    QCOMPARE(drives.size(), 8);
    for (int a = 1; a <= 8; ++a) {
        const QString name = QStringLiteral("servo-modbus-%1.json").arg(a);
        QCOMPARE(drives.at(a - 1).toObject().value("file").toString(), name);
        BackupFile f;
        QVERIFY2(!f.load(QDir(dir).filePath(name)), qPrintable(name));
        QCOMPARE(f.address(), a);
        QCOMPARE(f.values().value(51), std::optional<qint64>(a));
        QCOMPARE(f.values().value(20), std::optional<qint64>(sim(a)->parameter(20)));
    }
    QFile index(QDir(dir).filePath(QStringLiteral("index.json")));
    QVERIFY(index.open(QIODevice::ReadOnly));
    const QJsonObject doc = QJsonDocument::fromJson(index.readAll()).object();
    QCOMPARE(doc.value("format").toString(), QStringLiteral("drivedesk-backup-index"));
    QCOMPARE(doc.value("drives").toArray().size(), 8);
    QCOMPARE(doc.value("drives").toArray().at(3).toObject().value("result").toString(), QStringLiteral("done"));
}

void TestCliFleet::restoreAllWritesOnlyTheDifferences()
{
    const QString file = m_dir.filePath(QStringLiteral("axis1.json"));
    sim(1)->setParameter(30, 3030);
    QCOMPARE(runCli(args({"--address", "1", "backup", "-o"}) << file).exitCode, 0);
    for (int a = 2; a <= 8; ++a) {
        sim(a)->setParameter(31, quint16(100 + a));
        sim(a)->setParameter(32, quint16(200 + a));
    }
    const CliRun r = runCli(args({"--json", "--timeout", "100", "restore", "--all", "--to", "12"}) << file);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    const QJsonArray drives = r.json().value("drives").toArray();
    QCOMPARE(drives.size(), 8);
    QCOMPARE(drives.at(0).toObject().value("selected").toArray().size(), 0); // the source itself
    for (int a = 2; a <= 8; ++a) {
        const QJsonObject d = drives.at(a - 1).toObject();
        QCOMPARE(d.value("address").toInt(), a);
        QCOMPARE(d.value("result").toString(), QStringLiteral("done"));
        QCOMPARE(d.value("verified").toArray(), (QJsonArray{"PA30", "PA31", "PA32"}));
        for (int i = 0; i < 60; ++i)
            if (i != 51)
                QCOMPARE(sim(a)->parameter(i), sim(1)->parameter(i));
        QCOMPARE(sim(a)->parameter(51), quint16(a)); // the address is left alone
    }
}

void TestCliFleet::restoreAddressListTouchesOnlyThose()
{
    const QString file = m_dir.filePath(QStringLiteral("list.json"));
    sim(1)->setParameter(40, 4040);
    QCOMPARE(runCli(args({"--address", "1", "backup", "-o"}) << file).exitCode, 0);
    const CliRun r = runCli(args({"--address", "2,5", "restore"}) << file);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(r.out.contains("drive 2"));
    QVERIFY(r.out.contains("drive 5"));
    for (int a = 2; a <= 8; ++a)
        QCOMPARE(sim(a)->parameter(40), (a == 2 || a == 5) ? quint16(4040) : m_factory[40]);
}

void TestCliFleet::worstDriveGivesTheExitCode()
{
    const QString file = m_dir.filePath(QStringLiteral("worst.json"));
    sim(1)->setParameter(41, 4141);
    QCOMPARE(runCli(args({"--address", "1", "backup", "-o"}) << file).exitCode, 0);
    // Nobody at 20: that drive fails; 3 is restored all the same.
    const CliRun r = runCli(args({"--json", "--address", "20,3", "--timeout", "60", "restore"}) << file);
    QCOMPARE(r.exitCode, 1);
    const QJsonArray drives = r.json().value("drives").toArray();
    QCOMPARE(drives.at(0).toObject().value("result").toString(), QStringLiteral("failed"));
    QCOMPARE(drives.at(0).toObject().value("stoppedAt").toString(), QStringLiteral("identify"));
    QCOMPARE(drives.at(1).toObject().value("result").toString(), QStringLiteral("done"));
    QCOMPARE(sim(3)->parameter(41), quint16(4141));
}

void TestCliFleet::diffCombinations()
{
    const QString a = m_dir.filePath(QStringLiteral("a.json"));
    const QString b = m_dir.filePath(QStringLiteral("b.json"));
    QCOMPARE(runCli(args({"--address", "1", "backup", "-o"}) << a).exitCode, 0);
    sim(1)->setParameter(25, 2525);
    QCOMPARE(runCli(args({"--address", "1", "backup", "-o"}) << b).exitCode, 0);

    // file / file: no link needed.
    CliRun r = runCli({"--json", "diff", a, a});
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("equal").toBool(), true);
    r = runCli({"--json", "diff", a, b});
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.json().value("different").toInt(), 1);
    QJsonObject pa25;
    for (const QJsonValue &v : r.json().value("parameters").toArray())
        if (v.toObject().value("key").toString() == QLatin1String("PA25"))
            pa25 = v.toObject();
    QCOMPARE(pa25.value("status").toString(), QStringLiteral("different"));
    QCOMPARE(pa25.value("b").toInt(), 2525);

    // file / drive, drive / file.
    r = runCli(args({"--address", "1", "diff", "drive"}) << b);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    r = runCli(args({"--json", "diff"}) << a << QStringLiteral("drive:1"));
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.json().value("a").toObject().value("kind").toString(), QStringLiteral("file"));
    QCOMPARE(r.json().value("b").toObject().value("source").toString(), QStringLiteral("drive:1"));

    // drive / drive: only the address (a communication setting) and PA25 differ.
    r = runCli(args({"--json", "diff", "drive:1", "drive:2"}));
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.json().value("different").toInt(), 2);
    r = runCli(args({"diff", "drive:2", "drive:3"}));
    QCOMPARE(r.exitCode, 1); // PA51
    QVERIFY(r.out.contains("communication setting"));

    // Today's diff FILE: the file against the drive at --address.
    r = runCli(args({"--address", "1", "diff"}) << b);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    r = runCli(args({"--address", "1", "diff"}) << a);
    QCOMPARE(r.exitCode, 1);

    // defaults: the bundled servo-modbus dictionary has none (the manual gives none), so
    // defaults against a file compares nothing: equal. With a dictionary that has some:
    r = runCli({"--json", "diff", "defaults", a});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.json().value("same").toInt(), 0);
    const QString dict = writeDictionaryWithDefaults();
    r = runCli(args({"--json", "--dictionary"}) << dict << "diff"
                                                << "defaults"
                                                << "drive:2");
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.json().value("different").toInt(), 1); // PA12's default is not the factory value
    QCOMPARE(r.json().value("same").toInt(), 9);
}

QString TestCliFleet::writeDictionaryWithDefaults()
{
    // The bundled dictionary with defaults for PA10..PA19: the simulated factory values,
    // except PA12 (one more).
    QFile f(QStringLiteral(":/drivedesk/dictionaries/servo-modbus.json"));
    if (!f.open(QIODevice::ReadOnly))
        f.setFileName(qEnvironmentVariable("DRIVEDESK_SOURCE_DIR")
                      + QStringLiteral("/resources/dictionaries/servo-modbus.json"));
    if (!f.isOpen() && !f.open(QIODevice::ReadOnly))
        return {};
    QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
    QJsonArray params = root.value("parameters").toArray();
    for (int i = 0; i < params.size(); ++i) {
        QJsonObject p = params.at(i).toObject();
        const int index = p.value("index").toInt();
        if (index >= 10 && index <= 19) {
            p.insert("default", int(m_factory[size_t(index)]) + (index == 12 ? 1 : 0));
            params[i] = p;
        }
    }
    root.insert("parameters", params);
    const QString path = m_dir.filePath(QStringLiteral("defaults-dictionary.json"));
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly))
        return {};
    out.write(QJsonDocument(root).toJson());
    return path;
}

void TestCliFleet::changedOnlyRoundTrip()
{
    const QString dict = writeDictionaryWithDefaults();
    QVERIFY(!dict.isEmpty());
    sim(1)->setParameter(15, 1515);
    const QString file = m_dir.filePath(QStringLiteral("changed.json"));
    CliRun r = runCli(args({"--json", "--address", "1", "--dictionary"}) << dict << "backup"
                                                                         << "--changed-only"
                                                                         << "-o" << file);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(r.json().value("changedOnly").toBool());
    BackupFile f;
    QVERIFY(!f.load(file, nullptr));
    QVERIFY(f.isChangedOnly());
    // PA10-19 have defaults: only PA12 (default differs) and PA15 (changed) are in; the
    // parameters without a default are all kept, read-only ones (PA2) left out.
    QVERIFY(f.values().isKnown(12));
    QCOMPARE(f.values().value(15), std::optional<qint64>(1515));
    for (int i : {10, 11, 13, 14, 16, 17, 18, 19})
        QVERIFY2(!f.values().isKnown(i), qPrintable(QString::number(i)));
    QVERIFY(!f.values().isKnown(2));
    QVERIFY(f.values().isKnown(30));

    // A restore of it to drive 6 touches only the parameters in it.
    sim(6)->setParameter(15, 1);
    sim(6)->setParameter(16, 1616); // not in the file: stays
    r = runCli(args({"--json", "--address", "6", "--dictionary"}) << dict << "restore" << file);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(sim(6)->parameter(15), quint16(1515));
    QCOMPARE(sim(6)->parameter(16), quint16(1616));
    QCOMPARE(r.json().value("verified").toArray(), QJsonArray{"PA15"});

    // Compared, the parameters it leaves out count as their default: PA16 differs.
    r = runCli(args({"--json", "--dictionary"}) << dict << "diff" << file << "drive:6");
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.json().value("a").toObject().value("changedOnly").toBool(), true);
    QStringList differing;
    for (const QJsonValue &v : r.json().value("parameters").toArray())
        if (v.toObject().value("status").toString() == QLatin1String("different"))
            differing << v.toObject().value("key").toString();
    QCOMPARE(differing, (QStringList{"PA16", "PA51"}));
}

void TestCliFleet::restoreFolderPutsEachDriveBackFromItsOwnFile()
{
    // A machine backed up drive by drive, each with its own setting.
    for (int a = 1; a <= 8; ++a)
        sim(a)->setParameter(20, quint16(1000 + a));
    const QString dir = m_dir.filePath(QStringLiteral("machine"));
    CliRun r = runCli(args({"--timeout", "100", "backup", "--all", "--to", "8", "-o"}) << dir);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    for (int a = 1; a <= 8; ++a) {
        sim(a)->setParameter(20, 7);
        sim(a)->setParameter(21, quint16(2000 + a));
    }
    const quint16 pa21 = m_factory[21];
    // --address: only those drives, each from its own file.
    r = runCli(args({"--json", "--address", "2,3", "restore"}) << dir);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("drives").toArray().at(1).toObject().value("file").toString(),
             QStringLiteral("servo-modbus-3.json"));
    QCOMPARE(sim(3)->parameter(20), quint16(1003));
    QCOMPARE(sim(4)->parameter(20), quint16(7));
    // The whole folder: every drive of the index back to its own values, addresses left alone.
    r = runCli(args({"--json", "restore"}) << dir);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    const QJsonArray drives = r.json().value("drives").toArray();
    QCOMPARE(drives.size(), 8);
    for (int a = 1; a <= 8; ++a) {
        QCOMPARE(sim(a)->parameter(20), quint16(1000 + a));
        QCOMPARE(sim(a)->parameter(21), pa21);
        QCOMPARE(sim(a)->parameter(51), quint16(a));
        QCOMPARE(drives.at(a - 1).toObject().value("result").toString(), QStringLiteral("done"));
    }
    QCOMPARE(drives.at(1).toObject().value("verified").toArray(), QJsonArray()); // put back above already
    QCOMPARE(drives.at(3).toObject().value("verified").toArray(), (QJsonArray{"PA20", "PA21"}));

    // Refused before anything is sent: a drive not in the index, a file the index gives to
    // another address, a folder without an index, --from/--to.
    const quint64 before = m_bench.serialBus()->stats().bytesIn;
    r = runCli(args({"--trace", "--address", "2,9", "restore"}) << dir);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.text().contains("drive 9 is not in the folder's index"), qPrintable(r.text()));
    QCOMPARE(r.txFrames(), 0);
    QFile::rename(QDir(dir).filePath("servo-modbus-3.json"), QDir(dir).filePath("three.json"));
    QFile::copy(QDir(dir).filePath("servo-modbus-4.json"), QDir(dir).filePath("servo-modbus-3.json"));
    r = runCli(args({"--trace", "restore"}) << dir);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.text().contains("servo-modbus-3.json is the backup of the drive at address 4, but the index gives it "
                               "to address 3"),
             qPrintable(r.text()));
    QCOMPARE(r.txFrames(), 0);
    r = runCli(args({"--trace", "restore", "--all", "--to", "4"}) << dir);
    QCOMPARE(r.exitCode, 2);
    QDir(dir).remove("index.json");
    r = runCli(args({"--trace", "restore"}) << dir);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.text().contains("has no index.json"), qPrintable(r.text()));
    QTest::qWait(20);
    QCOMPARE(m_bench.serialBus()->stats().bytesIn, before);
}

void TestCliFleet::badInputsSendNothing()
{
    const QString file = m_dir.filePath(QStringLiteral("bad.json"));
    QCOMPARE(runCli(args({"--address", "1", "backup", "-o"}) << file).exitCode, 0);
    // A servo-can backup file.
    BackupFile can;
    can.setFamily(Family::ServoCan);
    can.setAddress(1);
    ParameterSet v;
    v.set(10, 5);
    can.setValues(v);
    const QString canFile = m_dir.filePath(QStringLiteral("can.json"));
    QVERIFY(!can.save(canFile));

    const quint64 before = m_bench.serialBus()->stats().bytesIn;
    const QList<QStringList> bad = {
        args({"--trace", "--address", "2,300", "restore"}) << file, // outside 1..247
        args({"--trace", "--address", "2,x", "restore"}) << file,
        args({"--trace", "--address", "2,2", "restore"}) << file,    // twice
        args({"--trace", "--address", "1,2", "restore"}) << canFile, // another family
        args({"--trace", "restore", "--all"}) << canFile,
        args({"--trace", "--address", "1,2", "info"}), // one drive only
        args({"--trace", "--address", "1", "restore", "--all"}) << file,
        args({"--trace", "diff", "drive:1"}) << canFile,
        args({"--trace", "diff", "drive:999", "defaults"}),
        {QStringLiteral("diff"), file, canFile}, // families differ
        args({"--trace", "diff", "drive:1", "nosuchfile.json"}),
    };
    for (const QStringList &a : bad) {
        const CliRun r = runCli(a);
        QVERIFY2(r.exitCode == 2, qPrintable(a.join(' ') + QLatin1String(": ") + r.text()));
        QCOMPARE(r.txFrames(), 0);
    }
    QTest::qWait(20);
    QCOMPARE(m_bench.serialBus()->stats().bytesIn, before);
}

QTEST_GUILESS_MAIN(TestCliFleet)
#include "tst_clifleet.moc"
