#include "core/tuning/tuningrun.h"
#include "tests/support/clirun.h"

#include <QJsonArray>
#include <QJsonDocument>
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

    // Issue 26, item 5: a run whose tuning list was edited to hold P4 (control mode) and P75
    // (station) is refused by name, whole file, nothing written, exit 2 (it used to write
    // "P4 Control mode 8 -> 0 verified / P75 Station number 1 -> 7 verified", exit 0).
    void applyRunRefusesWhatIsNotATuningParameter()
    {
        const QString state = m_dir.filePath(QStringLiteral("apply-only-tuning.json"));
        const QStringList sim{"--sim-state", state, "--family", "servo-can"};
        const QString run = m_dir.filePath(QStringLiteral("gains.ddrun"));
        CliRun r = runCli(QStringList(sim) << "capture"
                                           << "speed"
                                           << "--duration"
                                           << "0.1"
                                           << "-o" << run);
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        r = runCli(QStringList(sim) << "set"
                                    << "P60=45");
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QJsonObject root = readJson(run);
        QJsonArray tuning = root.value(QStringLiteral("tuning")).toArray();
        QCOMPARE(tuning.size(), 6);
        tuning.append(QJsonObject{{"index", 75}, {"key", "P75"}, {"role", ""}, {"value", 7}});
        tuning.append(QJsonObject{{"index", 4}, {"key", "P4"}, {"role", "speed-kd"}, {"value", 0}});
        root.insert(QStringLiteral("tuning"), tuning);
        const QString edited = m_dir.filePath(QStringLiteral("edited.ddrun"));
        writeJson(edited, root);

        r = runCli(QStringList(sim) << "--trace"
                                    << "apply-run" << edited);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.text().contains(QStringLiteral("P4 ")) && r.text().contains(QStringLiteral("P75 "))
                     && r.text().contains(QStringLiteral("not tuning parameters")),
                 qPrintable(r.text()));
        QCOMPARE(r.txFrames(), 0); // refused before anything was sent
        // Nothing was written: not the gain that differs either.
        r = runCli(QStringList(sim) << "--json"
                                    << "get"
                                    << "P4"
                                    << "P60"
                                    << "P75");
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonArray values = r.json().value(QStringLiteral("parameters")).toArray();
        QCOMPARE(values.size(), 3);
        QCOMPARE(values.at(0).toObject().value(QStringLiteral("value")).toInt(), 8);
        QCOMPARE(values.at(1).toObject().value(QStringLiteral("value")).toInt(), 45);
        QCOMPARE(values.at(2).toObject().value(QStringLiteral("value")).toInt(), 1);

        // The same run file with the dictionary of a real servo-can drive (no tuning roles):
        // refused with the reason, nothing sent.
        const QString bundled = qEnvironmentVariable("DRIVEDESK_SOURCE_DIR")
            + QStringLiteral("/resources/dictionaries/servo-can.json");
        QVERIFY(QFile::exists(bundled));
        r = runCli(QStringList(sim) << "--dictionary" << bundled << "--trace"
                                    << "apply-run" << run);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.text().contains(QStringLiteral("names no tuning parameters"))
                     && r.text().contains(QStringLiteral("simulator")),
                 qPrintable(r.text()));
        QCOMPARE(r.txFrames(), 0);

        // A file that lists a parameter twice is refused by the loader (apply-run and runs).
        root = readJson(run);
        tuning = root.value(QStringLiteral("tuning")).toArray();
        QJsonObject again = tuning.at(0).toObject();
        again.insert(QStringLiteral("value"), 50);
        tuning.append(again);
        root.insert(QStringLiteral("tuning"), tuning);
        const QString twice = m_dir.filePath(QStringLiteral("twice.ddrun"));
        writeJson(twice, root);
        r = runCli(QStringList(sim) << "apply-run" << twice);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.text().contains(QStringLiteral("twice")), qPrintable(r.text()));
        r = runCli({"runs", run, twice});
        QCOMPARE(r.exitCode, 2);

        // The untouched run applies: the one gain that differs, written and verified.
        r = runCli(QStringList(sim) << "--json"
                                    << "apply-run" << run);
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(r.json().value(QStringLiteral("verified")).toArray().size(), 1);
    }

    // `runs` says when runs do not compare (another test, step size, drive, dictionary)
    // instead of "no tuning parameter differs".
    void runsSayWhenRunsDoNotCompare()
    {
        const QString a = m_dir.filePath(QStringLiteral("cmp-a.ddrun"));
        CliRun r = runCli({"--sim", "--family", "servo-can", "capture", "speed", "--duration", "0.1", "-o", a});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QJsonObject root = readJson(a);
        auto variant = [&](const QString &name, const std::function<void(QJsonObject &)> &change) {
            QJsonObject o = root;
            change(o);
            const QString path = m_dir.filePath(name);
            writeJson(path, o);
            return path;
        };
        auto setTest = [](const QString &type, double speed) {
            return [type, speed](QJsonObject &o) {
                o.insert(QStringLiteral("test"),
                         QJsonObject{{"type", type}, {"parameters", QJsonObject{{"speed", speed}, {"duration", 0.1}}}});
            };
        };
        const QString v300 = variant(QStringLiteral("v300.ddrun"), setTest(QStringLiteral("velocity-step"), 300));
        const QString v500 = variant(QStringLiteral("v500.ddrun"), setTest(QStringLiteral("velocity-step"), 500));
        const QString rev = variant(QStringLiteral("rev.ddrun"), setTest(QStringLiteral("reversal"), 300));
        r = runCli({"runs", v300, v500});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QVERIFY2(r.text().contains(QStringLiteral("not comparable")) && r.text().contains(QStringLiteral("sizes")),
                 qPrintable(r.text()));
        QVERIFY(!r.text().contains(QStringLiteral("no tuning parameter differs")));
        r = runCli({"--json", "runs", v300, rev});
        const QJsonObject diff = r.json().value(QStringLiteral("differences")).toArray().at(0).toObject();
        QCOMPARE(diff.value(QStringLiteral("comparable")).toBool(true), false);
        QVERIFY(
            diff.value(QStringLiteral("reasons")).toArray().at(0).toString().contains(QLatin1String("different tests")));
        r = runCli({"runs", a, a});
        QVERIFY2(r.text().contains(QStringLiteral("no tuning parameter differs")), qPrintable(r.text()));
    }

    // Issue 26, item 8: the spectrum states its Nyquist frequency and usable band, and the
    // note about gaps bridged by interpolation stays with --between (it was dropped).
    void spectrumStatesNyquistAndKeepsTheGapNoteWithBetween()
    {
        const QString file = m_dir.filePath(QStringLiteral("gap.ddrun"));
        CliRun r = runCli({"--sim", "--family", "servo-can", "capture", "speed", "--duration", "0.4", "-o", file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QJsonObject root = readJson(file);
        QJsonObject samples = root.value(QStringLiteral("samples")).toObject();
        QJsonArray time = samples.value(QStringLiteral("time")).toArray();
        QVERIFY(time.size() > 100);
        const int half = int(time.size()) / 2;
        for (int i = half; i < time.size(); ++i) // 50 ms of samples missing from the middle on
            time.replace(i, time.at(i).toDouble() + 0.05);
        samples.insert(QStringLiteral("time"), time);
        root.insert(QStringLiteral("samples"), samples);
        writeJson(file, root);
        const double mid = time.at(half).toDouble();
        const QString between = QStringLiteral("%1:%2").arg(mid - 0.08, 0, 'f', 4).arg(mid + 0.1, 0, 'f', 4);
        r = runCli({"--json", "spectrum", file, "speed", "--between", between});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonObject j = r.json();
        QVERIFY(j.value(QStringLiteral("nyquistHz")).toDouble() > 0.0);
        QCOMPARE(j.value(QStringLiteral("nyquistHz")).toDouble(), j.value(QStringLiteral("sampleRate")).toDouble() / 2);
        QCOMPARE(j.value(QStringLiteral("usableBandHz")).toArray().size(), 2);
        const QString notes = QString::fromUtf8(QJsonDocument(j.value(QStringLiteral("notes")).toArray()).toJson());
        QVERIFY2(notes.contains(QStringLiteral("bridged by interpolation")), qPrintable(notes));
        QVERIFY2(notes.contains(QStringLiteral("Nyquist frequency")), qPrintable(notes));
    }

private:
    static QJsonObject readJson(const QString &path)
    {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            return {};
        return QJsonDocument::fromJson(f.readAll()).object();
    }
    static void writeJson(const QString &path, const QJsonObject &o)
    {
        QFile f(path);
        if (f.open(QIODevice::WriteOnly | QIODevice::Truncate))
            f.write(QJsonDocument(o).toJson());
    }

    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestCliTuning)
#include "tst_clituning.moc"
