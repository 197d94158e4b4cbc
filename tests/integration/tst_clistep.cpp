#include "core/tuning/tuningrun.h"
#include "tests/support/clirun.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd;
using namespace dd::test;

// drivedesk-cli step against the built-in simulator (docs/tuning.md, docs/cli.md).
class TestCliStep : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void withoutLimitsExitsTwoAndSendsNothing_data()
    {
        QTest::addColumn<QStringList>("step");
        QTest::addColumn<QString>("message");
        QTest::newRow("no max-speed") << QStringList{"velocity", "300", "--duration", "0.2", "--max-travel", "5000"}
                                      << "--max-speed V is missing";
        QTest::newRow("no max-travel") << QStringList{"velocity", "300", "--duration", "0.2", "--max-speed", "500"}
                                       << "--max-travel N is missing";
        QTest::newRow("position, no max-travel")
            << QStringList{"position", "5000", "--speed", "300"} << "--max-travel N is missing";
        QTest::newRow("reversal, no max-speed")
            << QStringList{"reversal", "300", "--duration", "0.2", "--max-travel", "5000"}
            << "--max-speed V is missing";
        QTest::newRow("speed above the limit")
            << QStringList{"velocity", "600", "--duration", "0.2", "--max-speed", "500", "--max-travel", "5000"}
            << "above the maximum speed 500";
        QTest::newRow("distance beyond the travel")
            << QStringList{"position", "-6000", "--speed", "300", "--max-travel", "5000"}
            << "beyond the maximum travel 5000";
        QTest::newRow("no time to stop") << QStringList{"velocity",       "300", "--duration",   "2",
                                                        "--max-speed",    "500", "--max-travel", "5000",
                                                        "--max-duration", "2"}
                                         << "no time to stop";
        QTest::newRow("no duration") << QStringList{"velocity", "300", "--max-speed", "500", "--max-travel", "5000"}
                                     << "needs --duration";
        QTest::newRow("unknown test") << QStringList{"ramp", "300"} << "velocity, position or reversal";
    }
    void withoutLimitsExitsTwoAndSendsNothing()
    {
        QFETCH(QStringList, step);
        QFETCH(QString, message);
        const QString file = m_dir.filePath(QStringLiteral("refused.ddrun"));
        const CliRun r = runCli(QStringList{"--sim", "--family", "servo-can", "--trace", "step"} << step << "-o"
                                                                                                 << file);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.text().contains(message), qPrintable(r.text()));
        QCOMPARE(r.txFrames(), 0);
        QVERIFY(!QFile::exists(file));
    }

    void velocityStepPrintsTheMetricsAndSavesTheRun()
    {
        const QString file = m_dir.filePath(QStringLiteral("velocity.ddrun"));
        const CliRun r = runCli({"--sim", "--family", "servo-can", "--json", "step", "velocity", "300", "--duration",
                                 "0.2", "--max-speed", "500", "--max-travel", "100000", "-o", file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonObject j = r.json();
        QCOMPARE(j.value(QStringLiteral("test")).toString(), QStringLiteral("velocity-step"));
        QCOMPARE(j.value(QStringLiteral("outcome")).toString(), QStringLiteral("completed"));
        QVERIFY(j.value(QStringLiteral("returnedToStart")).toBool());
        const QJsonObject m = j.value(QStringLiteral("metrics")).toObject();
        for (const char *key : {"riseTime", "overshoot", "settlingTime2", "settlingTime5", "steadyStateError",
                                "peakFollowingError", "peakTorque", "peakCurrent", "sampleInterval"})
            QVERIFY2(m.contains(QLatin1String(key)), key);
        QVERIFY(m.value(QStringLiteral("riseTime")).toDouble() > 0.0);
        QVERIFY(m.value(QStringLiteral("peakTorque")).toDouble() > 0.0);
        // A metric without a value says why in `notes`.
        const QJsonArray notes = j.value(QStringLiteral("notes")).toArray();
        for (auto it = m.begin(); it != m.end(); ++it)
            if (it.value().isNull()) {
                bool said = false;
                for (const QJsonValue &n : notes)
                    said = said || n.toString().startsWith(it.key() + QLatin1Char(':'));
                QVERIFY2(said, qPrintable(it.key()));
            }
        TuningRun run;
        const Error e = TuningRun::load(file, &run);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(run.test, QStringLiteral("velocity-step"));
        QCOMPARE(run.capture.triggerSource, QStringLiteral("motion"));
        QCOMPARE(run.linkKind, QStringLiteral("can"));
        QCOMPARE(run.tuning.size(), 6);
        QCOMPARE(run.testParameters.value(QStringLiteral("speed")).toInt(), 300);
    }

    void positionAndReversalSteps()
    {
        CliRun r = runCli({"--sim", "--family", "servo-can", "--json", "step", "position", "5000", "--speed", "300",
                           "--max-travel", "6000"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(r.json().value(QStringLiteral("metricsChannel")).toString(), QStringLiteral("position"));
        QVERIFY(r.json().value(QStringLiteral("returnedToStart")).toBool());
        QVERIFY(
            r.json().value(QStringLiteral("metrics")).toObject().value(QStringLiteral("peakFollowingError")).toDouble()
            > 0.0);
        r = runCli({"--sim", "--family", "servo-can", "--json", "step", "reversal", "200", "--duration", "0.15",
                    "--max-speed", "300", "--max-travel", "100000", "--no-return"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(r.json().value(QStringLiteral("test")).toString(), QStringLiteral("reversal"));
        QVERIFY(!r.json().value(QStringLiteral("returnedToStart")).toBool());
        // +200 for 0.15 s then -200 for 0.15 s: back near the start, not on it.
        QVERIFY(r.json().value(QStringLiteral("metrics")).toObject().value(QStringLiteral("riseTime")).toDouble()
                > 0.0);
    }

    void aTravelLimitPassedAbortsWithTheAxisStopped()
    {
        const CliRun r = runCli({"--sim", "--family", "servo-can", "--json", "step", "velocity", "500", "--duration",
                                 "1", "--max-speed", "600", "--max-travel", "3000"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject j = r.json();
        QCOMPARE(j.value(QStringLiteral("outcome")).toString(), QStringLiteral("aborted"));
        QCOMPARE(j.value(QStringLiteral("abortCause")).toString(), QStringLiteral("travel-limit"));
        QVERIFY(j.value(QStringLiteral("stopConfirmed")).toBool());
        QCOMPARE(j.value(QStringLiteral("stoppedBy")).toString(), QStringLiteral("command"));
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestCliStep)
#include "tst_clistep.moc"
