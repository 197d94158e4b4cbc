#include "core/tuning/tuningrun.h"
#include "tests/support/clirun.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace dd;
using namespace dd::test;

// drivedesk-cli capture / runs / spectrum against the built-in simulator (docs/tuning.md).
class TestCliTuning : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void captureAtTheLinksRateWithTheTuningSnapshot()
    {
        const QString file = m_dir.filePath(QStringLiteral("free.ddrun"));
        const CliRun r = runCli({"--sim", "--family", "servo-can", "--json", "capture", "speed,current,torque,position",
                                 "--pre", "20%", "--duration", "0.5", "-o", file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        TuningRun run;
        const Error e = TuningRun::load(file, &run);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(run.family, QStringLiteral("servo-can"));
        QCOMPARE(run.capture.channels.size(), 4);
        // The trigger came only once the pre-trigger window was full: 0.1 s of samples.
        QVERIFY(run.capture.time.first() <= -0.1 + 2 * run.capture.interval.max);
        QVERIFY(run.capture.preTriggerSamples > 0);
        qInfo("servo-can capture, 4 channels: %d samples in 0.5 s, mean interval %.3f ms (%.0f Hz)",
              int(run.capture.time.size()), run.capture.interval.mean * 1e3, 1.0 / run.capture.interval.mean);
        // The snapshot is the simulator's gains as read from the drive, with their roles.
        QCOMPARE(run.tuning.size(), 6);
        QCOMPARE(run.tuning.at(0).key, QStringLiteral("P60"));
        QCOMPARE(run.tuning.at(0).role, QStringLiteral("speed-kp"));
        QCOMPARE(run.tuning.at(0).value, 30);
    }

    void runsShowParameterDifferences()
    {
        const QString a = m_dir.filePath(QStringLiteral("a.ddrun")), b = m_dir.filePath(QStringLiteral("b.ddrun"));
        const QString state = m_dir.filePath(QStringLiteral("bench.json"));
        CliRun r = runCli(
            {"--sim-state", state, "--family", "servo-can", "capture", "speed", "--duration", "0.1", "-o", a});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        r = runCli({"--sim-state", state, "--family", "servo-can", "set", "P60=45"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        r = runCli({"--sim-state", state, "--family", "servo-can", "capture", "speed", "--duration", "0.1", "-o", b});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        r = runCli({"runs", a, b});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QVERIFY2(r.text().contains(QStringLiteral("P60 30 → 45")), qPrintable(r.text()));
        r = runCli({"--json", "runs", a, b});
        const QJsonObject diff = r.json().value(QStringLiteral("differences")).toArray().at(0).toObject();
        const QJsonObject p = diff.value(QStringLiteral("parameters")).toArray().at(0).toObject();
        QCOMPARE(p.value(QStringLiteral("role")).toString(), QStringLiteral("speed-kp"));
        QCOMPARE(p.value(QStringLiteral("from")).toInt(), 30);
        QCOMPARE(p.value(QStringLiteral("to")).toInt(), 45);
        const QJsonObject metrics = r.json()
                                        .value(QStringLiteral("runs"))
                                        .toArray()
                                        .at(0)
                                        .toObject()
                                        .value(QStringLiteral("metrics"))
                                        .toObject();
        QVERIFY(metrics.contains(QStringLiteral("riseTime")) && metrics.contains(QStringLiteral("sampleInterval")));
    }

    void badInputExitsTwo()
    {
        const QString bad = m_dir.filePath(QStringLiteral("bad.ddrun"));
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"format\": \"drivedesk-run\", \"formatVersion\": 1}");
        f.close();
        CliRun r = runCli({"runs", bad});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.text().contains(QStringLiteral("bad.ddrun: created must be a string")), qPrintable(r.text()));
        r = runCli({"--sim", "--family", "servo-can", "capture", "speed", "--trigger", "rise:speed", "-o",
                    m_dir.filePath(QStringLiteral("x.ddrun"))});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.text().contains(QStringLiteral("needs a channel and a level")));
        r = runCli({"--sim", "--family", "servo-can", "capture", "speed", "--trigger", "rise:current:1", "-o",
                    m_dir.filePath(QStringLiteral("x.ddrun"))});
        QCOMPARE(r.exitCode, 2);
        r = runCli({"--sim", "--family", "servo-can", "capture", "speed", "--pre", "120%", "-o",
                    m_dir.filePath(QStringLiteral("x.ddrun"))});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("x.ddrun"))));
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestCliTuning)
#include "tst_clituning.moc"
