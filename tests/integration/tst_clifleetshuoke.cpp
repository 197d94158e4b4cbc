// drivedesk-cli on several shuoke drives (issue 13), lean: three simulated drives on one
// serial link (--sim-drives 1,2,3 with a --sim-state file, so the bench keeps its values
// between runs). backup --all finds and saves each drive to its own file; restore of one
// drive's file to the others writes only the differences and leaves the baud code (the
// communication setting) alone; restore DIR puts each drive back from its own file.
// (The family's 50 ms command spacing makes 8 drives slow; the fleet code is family-blind:
// tst_clifleet and tst_clifleetcan run 8.)
#include "tests/support/clirun.h"

#include "core/common/coreresources.h"
#include "core/params/backupfile.h"

#include <QDir>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd;
using namespace dd::test;

class TestCliFleetShuoke : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        ensureCoreResources();
        QVERIFY(m_dir.isValid());
    }

    void backupAllRestoreToOthersAndRestoreFolder()
    {
        // Drive 2 is the tuned axis.
        CliRun r = runCli(args({"--address", "2", "set", "start-speed=222", "max-speed=23456"}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        r = runCli(args({"--address", "3", "set", "acceleration=40000"}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));

        const QString dir = m_dir.filePath(QStringLiteral("machine"));
        r = runCli(args({"--json", "backup", "--all", "--from", "1", "--to", "3", "-o"}) << dir);
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(r.json().value("drives").toArray().size(), 3);
        BackupFile two, three;
        QVERIFY(!two.load(QDir(dir).filePath(QStringLiteral("shuoke-2.json"))));
        QVERIFY(!three.load(QDir(dir).filePath(QStringLiteral("shuoke-3.json"))));
        QCOMPARE(two.address(), 2);
        QCOMPARE(two.values().value(37), std::optional<qint64>(222)); // start speed, SET 0x25
        QCOMPARE(three.values().value(37), std::optional<qint64>(500));

        // Drive 2's settings to 1 and 3: only the differences, the baud code left alone.
        r = runCli(args({"--json", "--address", "1,3", "restore"})
                   << QDir(dir).filePath(QStringLiteral("shuoke-2.json")));
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonArray drives = r.json().value("drives").toArray();
        QCOMPARE(drives.size(), 2);
        QCOMPARE(drives.at(0).toObject().value("verified").toArray(), (QJsonArray{"start-speed", "max-speed"}));
        QCOMPARE(drives.at(1).toObject().value("verified").toArray(),
                 (QJsonArray{"start-speed", "max-speed", "acceleration"}));
        for (const QJsonValue &d : drives)
            for (const QJsonValue &key : d.toObject().value("selected").toArray())
                QVERIFY2(!key.toObject().value("key").toString().contains("baud"), "the baud code is never copied");
        QCOMPARE(get(3).value("start-speed"), 222);

        // The folder puts each drive back from its own file.
        r = runCli(args({"--json", "restore"}) << dir);
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(get(1).value("start-speed"), 500);
        QCOMPARE(get(2).value("start-speed"), 222);
        const QMap<QString, int> back3 = get(3);
        QCOMPARE(back3.value("start-speed"), 500);
        QCOMPARE(back3.value("acceleration"), 40000);
    }

private:
    QStringList args(std::initializer_list<const char *> words) const
    {
        QStringList l{QStringLiteral("--family"),     QStringLiteral("shuoke"),
                      QStringLiteral("--sim-drives"), QStringLiteral("1,2,3"),
                      QStringLiteral("--sim-state"),  m_dir.filePath(QStringLiteral("bench.json"))};
        for (const char *w : words)
            l << QString::fromUtf8(w);
        return l;
    }
    // Start speed and acceleration of the drive at `address`, by key.
    QMap<QString, int> get(int address)
    {
        const CliRun r = runCli(args({"--json", "--address"}) << QString::number(address) << "get"
                                                              << "start-speed"
                                                              << "acceleration");
        QMap<QString, int> values;
        for (const QJsonValue &p : r.json().value("parameters").toArray())
            values.insert(p.toObject().value("key").toString(), p.toObject().value("value").toInt(-1));
        return values;
    }

    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestCliFleetShuoke)
#include "tst_clifleetshuoke.moc"
