// The Tuning tab (issue 12): free captures on the simulated bench become runs, runs overlay
// with metrics and parameter differences, gains edited in the tab reach the Parameters
// tab's shared values, bad run files are refused, Run needs limits, the layout fits
// 1280 x 720 in English and Chinese, and a live language switch reaches the tab.
#include <QtTest>

#include "core/drive/drive.h"
#include "core/drive/driveresult.h"
#include "core/params/parameterdictionary.h"
#include "tests/gui/journaldatahome.h"
#include "tests/gui/panelrig.h"
#include "ui/panels/parameters/parameterspanel.h"
#include "ui/panels/trend/trendplot.h"
#include "ui/panels/tuning/capturecontrols.h"
#include "ui/panels/tuning/captureplot.h"
#include "ui/panels/tuning/runcomparison.h"
#include "ui/panels/tuning/runlist.h"
#include "ui/panels/tuning/spectrumview.h"
#include "ui/panels/tuning/steptestcontrols.h"
#include "ui/panels/tuning/tuningpanel.h"
#include "ui/panels/tuning/tuningparameterseditor.h"
#include "ui/report/recordgatherer.h"
#include "ui/report/recordsession.h"
#include "ui/shell/languagemanager.h"
#include "ui/workspace/driveparameters.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <cmath>

using namespace dd;

namespace {
// Arms a capture that only Force fires (a level the speed never reaches), 50 % before it.
bool captureOnce(TuningPanel *tuning, QString *why)
{
    const int before = tuning->runList()->count();
    CaptureSettings s;
    s.trigger.kind = TriggerSpec::Kind::Rise;
    s.trigger.channel = QStringLiteral("speed");
    s.trigger.level = 1e6;
    s.prePercent = 50.0;
    s.durationS = 0.2;
    tuning->captureControls()->setSettings(s);
    tuning->captureControls()->armButton()->click();
    if (!tuning->isCapturing()) {
        *why = QStringLiteral("not capturing after Arm");
        return false;
    }
    // Force once the pre-trigger window is full (the recorder watches the trigger then).
    if (!waitUntil([&] { return tuning->captureControls()->stateText().startsWith(QStringLiteral("Armed")); }, 5000)) {
        *why = QStringLiteral("never armed: ") + tuning->captureControls()->stateText();
        return false;
    }
    tuning->captureControls()->forceButton()->click();
    if (!waitUntil([&] { return tuning->runList()->count() == before + 1; }, 5000)) {
        *why = QStringLiteral("no run after Force: ") + tuning->captureControls()->stateText();
        return false;
    }
    return true;
}

// The last verification the journal holds for the rig's drive, as the record gathers it.
DriveRecord tuningRecordOf(PanelRig &rig)
{
    RecordSession session(rig.hub.get(), rig.directory.get());
    RecordGatherer gatherer(rig.directory.get(), &session);
    QList<DriveRecord> records;
    bool finished = false;
    QObject::connect(&gatherer, &RecordGatherer::finished, [&](const QList<DriveRecord> &r, const QStringList &) {
        records = r;
        finished = true;
    });
    gatherer.gather({{rig.id, 1}});
    if (!waitUntil([&] { return finished; }, 20000) || records.size() != 1)
        return {};
    return records.first();
}

// "PA5=60" per entry of the drive's last verification.
QStringList tuningWritesOf(const DriveRecord &record)
{
    QStringList w;
    for (const RecordVerification::Entry &e : record.verification.entries)
        w << QStringLiteral("%1=%2").arg(e.key).arg(e.requested);
    return w;
}

bool dictionaryLoaded(TuningPanel *tuning)
{
    return waitUntil([&] { return !tuning->parametersEditor()->entries().isEmpty(); }, 5000);
}
} // namespace

class TstTuningPanel : public QObject
{
    Q_OBJECT

private slots:
    void armAndForceMakeARun()
    {
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QVERIFY(dictionaryLoaded(tuning));
        QVERIFY(tuning->parametersEditor()->usesSimulatorGains()); // the family dictionary names none
        QVERIFY2(captureOnce(tuning, &why), qPrintable(why));
        const TuningRun &run = tuning->runList()->run(0);
        QCOMPARE(run.capture.triggerSource, QStringLiteral("manual"));
        QVERIFY(run.capture.channels.contains(QStringLiteral("speed")));
        QVERIFY(run.capture.preTriggerSamples > 0);
        QVERIFY(run.capture.time.size() > run.capture.preTriggerSamples);
        QVERIFY(run.capture.time.first() < 0.0); // times relative to the trigger
        QCOMPARE(run.family, QStringLiteral("servo-modbus"));
        // The snapshot was read from the drive: PA5 (the simulator's speed-kp) at its default.
        bool found = false;
        for (const TuningSnapshotEntry &e : run.tuning)
            if (e.key == QLatin1String("PA5")) {
                found = true;
                QCOMPARE(e.role, QStringLiteral("speed-kp"));
                QCOMPARE(e.value, qint64(40));
            }
        QVERIFY(found);
        // Shown: one curve, the metrics column, the spectrum of the selected run.
        QCOMPARE(tuning->capturePlot()->curves().size(), 1);
        QCOMPARE(tuning->comparison()->table()->columnCount(), 1);
        // The spectrum view follows the selected run (too short a capture says why).
        QVERIFY(!tuning->spectrumView()->spectrum().isEmpty()
                || tuning->spectrumView()->peaksText().startsWith(QStringLiteral("No spectrum: ")));
        // Cursors: Δt between A and B.
        tuning->capturePlot()->setMarker(0, -0.05);
        tuning->capturePlot()->setMarker(1, 0.05);
        QVERIFY2(tuning->capturePlot()->markerReadout().contains(QStringLiteral("Δt: 100.0 ms")),
                 qPrintable(tuning->capturePlot()->markerReadout()));
        QVERIFY(tuning->capturePlot()->markerReadout().contains(QStringLiteral("Δvalue")));
    }

    void editGainThenCompareTwoRuns()
    {
        test::JournalDataHome data; // the verification journal of this test only
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QVERIFY(dictionaryLoaded(tuning));
        QVERIFY2(captureOnce(tuning, &why), qPrintable(why));

        TuningParametersEditor *editor = tuning->parametersEditor();
        const int pa5 = ParameterDictionary::bundled(Family::ServoModbus).byKey(QStringLiteral("PA5"))->index;
        // A bad value is refused and nothing is edited.
        QVERIFY(editor->setEdited(pa5, 1000000).isError());
        QVERIFY(!editor->hasEdits());
        QVERIFY(!editor->setEdited(pa5, 60).isError());
        editor->writeEdited();
        QVERIFY(waitUntil([&] { return !editor->isBusy() && !editor->hasEdits(); }, 5000));
        QVERIFY2(editor->message().contains(QStringLiteral("1 written and read back")), qPrintable(editor->message()));
        // The gain edit is in the drive's journal and so in its record (issue 27: it was not).
        QCOMPARE(tuningWritesOf(tuningRecordOf(rig)), QStringList{QStringLiteral("PA5=60")});
        // The Parameters tab's shared values follow.
        DrivePanel *parametersTab = nullptr;
        for (DrivePanel *p : rig.workspace->panelsFor(rig.id, 1))
            if (qobject_cast<ParametersPanel *>(p))
                parametersTab = p;
        QVERIFY(parametersTab);
        QCOMPARE(parametersTab->parameters(), tuning->parameters());
        QCOMPARE(parametersTab->parameters()->value(pa5).value, qint64(60));

        QVERIFY2(captureOnce(tuning, &why), qPrintable(why));
        QCOMPARE(tuning->capturePlot()->curves().size(), 2);
        QCOMPARE(tuning->comparison()->table()->columnCount(), 2);
        QCOMPARE(tuning->comparison()->table()->rowCount(), int(StepMetrics::keys().size()));
        QVERIFY2(tuning->comparison()->differencesText().contains(QStringLiteral("PA5 40 → 60")),
                 qPrintable(tuning->comparison()->differencesText()));
        QVERIFY(tuning->comparison()->differencesText().contains(QStringLiteral("overshoot")));
        // Unticking a run takes it out of the overlay and the table.
        tuning->runList()->setOverlaid(0, false);
        QCOMPARE(tuning->capturePlot()->curves().size(), 1);
        QCOMPARE(tuning->comparison()->table()->columnCount(), 1);

        // Apply the first run's parameters: PA5 back to 40, written because it differs.
        tuning->runList()->select(0);
        QVERIFY(tuning->applyButton()->isEnabled());
        tuning->applyButton()->click();
        QVERIFY(
            waitUntil([&] { return parametersTab->parameters()->value(pa5).value == 40 && !editor->isBusy(); }, 5000));
        QVERIFY2(editor->message().contains(QStringLiteral("1 written and read back")), qPrintable(editor->message()));
        const DriveRecord applied = tuningRecordOf(rig); // the applied run too
        QCOMPARE(tuningWritesOf(applied), QStringList{QStringLiteral("PA5=40")});
        QVERIFY(applied.verification.passed());
        QVERIFY2(applied.identification.contains(QStringLiteral("servo-modbus address 1 on ")),
                 qPrintable(applied.identification));

        // Saved and opened again, a run round-trips into the list.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("first.ddrun"));
        QVERIFY(!tuning->runList()->saveSelected(path).isError());
        QVERIFY(tuning->openFile(path));
        QCOMPARE(tuning->runList()->count(), 3);
        QCOMPARE(tuning->runList()->run(2).tuning.size(), tuning->runList()->run(0).tuning.size());
    }

    void badRunFileIsRefused()
    {
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.ddrun"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "drivedesk-run", "formatVersion": 99})");
        f.close();
        TuningRun expected;
        const Error e = TuningRun::load(path, &expected);
        QVERIFY(e.isError());
        QVERIFY(tuning->openFile(path));
        QCOMPARE(tuning->runList()->count(), 0);
        QVERIFY(tuning->capturePlot()->curves().isEmpty());
        QVERIFY2(tuning->runList()->message().contains(e.message), qPrintable(tuning->runList()->message()));
        // The message line follows a live language switch.
        LanguageManager language;
        QVERIFY(language.apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents();
        QVERIFY2(tuning->runList()->message().startsWith(QStringLiteral("未打开")),
                 qPrintable(tuning->runList()->message()));
        QVERIFY(language.apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
    }

    void runNeedsLimits()
    {
        StepTestControls controls;
        QVERIFY(!controls.runButton()->isEnabled());
        QVERIFY(controls.blockedReason().contains(QStringLiteral("maximum speed")));
        controls.setAvailable(true, QString());
        QVERIFY(!controls.runButton()->isEnabled());
        StepTestControls::Request r = controls.request();
        r.maxSpeed = 1000;
        r.maxTravel = 100000;
        r.maxDuration = 2;
        r.speed = 300;
        r.duration = 0.3;
        controls.setRequest(r);
        QVERIFY2(controls.runButton()->isEnabled(), qPrintable(controls.blockedReason()));
        r.speed = 1500; // above the maximum speed
        controls.setRequest(r);
        QVERIFY(!controls.runButton()->isEnabled());
        QVERIFY(controls.blockedReason().contains(QStringLiteral("maximum speed")));
        r.speed = 300;
        r.test = StepTestControls::Test::Reversal;
        r.duration = 1.5; // 3 s in all
        controls.setRequest(r);
        QVERIFY(!controls.runButton()->isEnabled());
        controls.setAvailable(false, QStringLiteral("not here"));
        r.duration = 0.5;
        controls.setRequest(r);
        QCOMPARE(controls.blockedReason(), QStringLiteral("not here"));
    }

    // Issue #26: a step on a disabled servo-can drive would switch its power stage on (its
    // motion commands enable it): refused, with the reason, nothing started.
    void aStepOnADisabledDriveIsRefused()
    {
        PanelRig rig;
        QString why;
        SimBenchOptions o;
        o.family = Family::ServoCan;
        o.can = QStringLiteral("virtualcan:auto");
        QVERIFY2(rig.start(o, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QVERIFY(!tuning->driveInfo().status.enabled);
        StepTestControls *controls = tuning->stepControls();
        StepTestControls::Request r;
        r.test = StepTestControls::Test::Velocity;
        r.speed = 200;
        r.duration = 0.3;
        r.maxSpeed = 400;
        r.maxTravel = 1000000;
        r.maxDuration = 3;
        controls->setRequest(r);
        QVERIFY2(controls->runButton()->isEnabled(), qPrintable(controls->blockedReason()));
        controls->runButton()->click();
        QVERIFY(!tuning->isStepRunning());
        QVERIFY2(tuning->message().contains(QLatin1String("power stage is off")), qPrintable(tuning->message()));
        QTest::qWait(300);
        QVERIFY(!tuning->driveInfo().status.enabled);
    }

    void velocityStepMakesARun()
    {
        PanelRig rig;
        QString why;
        SimBenchOptions o; // servo-modbus has no motion commands: servo-can
        o.family = Family::ServoCan;
        o.can = QStringLiteral("virtualcan:auto");
        QVERIFY2(rig.start(o, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QVERIFY(dictionaryLoaded(tuning));
        // A simulated drive powers up disabled.
        bool enabled = false;
        rig.hub->run(
            rig.id, 1, [](Drive &d) { return d.setEnabled(true); }, [&](const DriveResult &r) { enabled = r.ok(); });
        QVERIFY(waitUntil([&] { return enabled; }, 5000));
        StepTestControls *controls = tuning->stepControls();
        QVERIFY(!controls->runButton()->isEnabled()); // no limits yet
        StepTestControls::Request r;
        r.test = StepTestControls::Test::Velocity;
        r.speed = 200;
        r.duration = 0.3;
        r.maxSpeed = 400;
        r.maxTravel = 1000000;
        r.maxDuration = 3;
        controls->setRequest(r);
        QVERIFY2(controls->runButton()->isEnabled(), qPrintable(controls->blockedReason()));
        controls->runButton()->click();
        QVERIFY(tuning->isStepRunning());
        QCOMPARE(controls->runButton()->text(), QStringLiteral("Stop the test"));
        QVERIFY2(waitUntil([&] { return !tuning->isStepRunning(); }, 15000), qPrintable(tuning->message()));
        // The run joins the list once its tuning parameters are read.
        QVERIFY2(waitUntil([&] { return tuning->runList()->count() == 1; }, 5000), qPrintable(tuning->message()));
        const TuningRun &run = tuning->runList()->run(0);
        QCOMPARE(run.test, QStringLiteral("velocity-step"));
        QCOMPARE(run.capture.triggerSource, QStringLiteral("motion"));
        QVERIFY(!run.tuning.isEmpty()); // the simulator's gains, read from the drive
        QVERIFY2(tuning->message().contains(QStringLiteral("Step test done")), qPrintable(tuning->message()));
        QVERIFY(tuning->comparison()->table()->columnCount() == 1);
        QCOMPARE(controls->runButton()->text(), QStringLiteral("Run"));

        // A free capture on the same drive, for the record: the rate the hub reads give.
        QVERIFY2(captureOnce(tuning, &why), qPrintable(why));
        const IntervalStats &s = tuning->runList()->run(1).capture.interval;
        qInfo("servo-can free capture of %s: %d samples, mean interval %.3f ms (%.0f Hz)",
              qPrintable(tuning->runList()->run(1).capture.channels.join(QLatin1Char(','))),
              int(tuning->runList()->run(1).capture.time.size()), s.mean * 1000.0, s.mean > 0 ? 1.0 / s.mean : 0.0);
    }

    void aStopAtTheDriveEndsTheStepAndNothingMovesAfter()
    {
        // Issue 26: the Tuning tab runs the same engine as the CLI; a stop from outside
        // DriveDesk (the drive's panel, another master) ends the test with that cause, the
        // axis is not driven back, and the record so far joins the runs, marked aborted.
        PanelRig rig;
        QString why;
        SimBenchOptions o;
        o.family = Family::ServoCan;
        o.can = QStringLiteral("virtualcan:auto");
        QVERIFY2(rig.start(o, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QVERIFY(dictionaryLoaded(tuning));
        bool enabled = false;
        rig.hub->run(
            rig.id, 1, [](Drive &d) { return d.setEnabled(true); }, [&](const DriveResult &r) { enabled = r.ok(); });
        QVERIFY(waitUntil([&] { return enabled; }, 5000));
        StepTestControls::Request r;
        r.test = StepTestControls::Test::Velocity;
        r.speed = 200;
        r.duration = 2.0;
        r.maxSpeed = 400;
        r.maxTravel = 1000000;
        r.maxDuration = 5;
        tuning->stepControls()->setRequest(r);
        tuning->stepControls()->runButton()->click();
        QVERIFY(tuning->isStepRunning());
        auto speed = [&] { return rig.sim.call([&] { return rig.sim.canDrive()->motor().speedRpm(); }); };
        QVERIFY2(waitUntil([&] { return speed() > 150; }, 10000), qPrintable(tuning->message()));
        QTest::qWait(200);
        rig.sim.call([&] { rig.sim.canDrive()->motor().stop(); });
        QVERIFY2(waitUntil([&] { return !tuning->isStepRunning(); }, 15000), qPrintable(tuning->message()));
        QVERIFY2(tuning->message().contains(QStringLiteral("another master or at the drive")),
                 qPrintable(tuning->message()));
        auto position = [&] { return rig.sim.call([&] { return rig.sim.canDrive()->motor().position(); }); };
        const qint64 at = position();
        QVERIFY2(waitUntil([&] { return tuning->runList()->count() == 1; }, 5000), qPrintable(tuning->message()));
        QCOMPARE(tuning->runList()->run(0).outcome, QStringLiteral("aborted"));
        QVERIFY2(tuning->runList()->run(0).label.contains(QStringLiteral("aborted")),
                 qPrintable(tuning->runList()->run(0).label));
        QTest::qWait(700);
        QCOMPARE(position(), at); // not driven back
    }

    void unresolvableMetricsSayWhy()
    {
        // Too few samples for any metric: "not resolvable" with the reason, a few note lines.
        QList<TuningRun> runs;
        for (int k = 0; k < 3; ++k) {
            TuningRun run;
            run.label = QStringLiteral("r%1").arg(k);
            run.capture.channels = {QStringLiteral("speed")};
            run.capture.columns = {{0.0}};
            run.capture.time = {0.0};
            run.metricsChannel = QStringLiteral("speed");
            run.metrics = StepMetrics::compute(run.capture, StepMetrics::Input{});
            runs << run;
        }
        RunComparison comparison;
        comparison.setRuns(runs);
        QTableWidgetItem *rise = comparison.table()->item(0, 0);
        QCOMPARE(rise->text(), QStringLiteral("not resolvable"));
        QVERIFY(!rise->toolTip().isEmpty());
        QCOMPARE(rise->toolTip(), runs.at(0).metrics.riseTime.reason);
        const QStringList lines = comparison.notesText().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 5);
        QVERIFY(lines.last().contains(QStringLiteral("more")));
    }

    void overlayDecimationKeepsPeaks()
    {
        QVector<double> t, v;
        for (int i = 0; i < 10000; ++i) {
            t << i * 1e-4;
            v << (i == 5001 ? 100.0 : i == 7003 ? -50.0 : 0.0);
        }
        const QList<QPointF> points = CapturePlot::decimate(t, v, 0.0, 1.0, 200);
        QVERIFY(points.size() <= 2 * 200 + 2);
        bool high = false, low = false;
        for (const QPointF &p : points) {
            high = high || p.y() == 100.0;
            low = low || p.y() == -50.0;
        }
        QVERIFY(high && low);
        QCOMPARE(*CapturePlot::valueAt(t, v, 0.50005), 50.0); // halfway up to the peak
    }

    // Issue 26, item 5, in the GUI: "Apply this run's parameters" writes tuning parameters
    // only; a run that also lists P4 (control mode) and P75 (station) is refused as a whole,
    // by name, and nothing reaches the drive; the clean run is applied.
    void applyRunRefusesWhatIsNotATuningParameter()
    {
        PanelRig rig;
        QString why;
        SimBenchOptions o;
        o.family = Family::ServoCan;
        o.can = QStringLiteral("virtualcan:auto");
        QVERIFY2(rig.start(o, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QVERIFY(dictionaryLoaded(tuning));
        TuningParametersEditor *editor = tuning->parametersEditor();
        auto onDrive = [&rig](int index) {
            return rig.sim.call([&rig, index] { return int(rig.sim.canDrive()->parameter(index)); });
        };
        QCOMPARE(onDrive(60), 30);
        TuningRun run;
        run.label = QStringLiteral("edited");
        run.family = QStringLiteral("servo-can");
        run.address = 1;
        run.tuning = {{60, QStringLiteral("P60"), QStringLiteral("speed-kp"), 45},
                      {4, QStringLiteral("P4"), QString(), 0},
                      {75, QStringLiteral("P75"), QString(), 7}};
        editor->applyRun(run, tuning->driveInfo().identity);
        QVERIFY2(editor->message().contains(QStringLiteral("not tuning parameters"))
                     && editor->message().contains(QStringLiteral("P4 "))
                     && editor->message().contains(QStringLiteral("P75 ")),
                 qPrintable(editor->message()));
        QVERIFY(!editor->isBusy()); // nothing was started
        QTest::qWait(200);
        QCOMPARE(onDrive(4), 8);
        QCOMPARE(onDrive(60), 30);
        QCOMPARE(onDrive(75), 1);
        // Only the gain: applied, verified on the drive.
        run.tuning = {{60, QStringLiteral("P60"), QStringLiteral("speed-kp"), 45}};
        editor->applyRun(run, tuning->driveInfo().identity);
        QVERIFY(waitUntil([&] { return onDrive(60) == 45 && !editor->isBusy(); }, 5000));

        // Issue 26: a run taken on another model is refused as the CLI's apply-run refuses
        // it (servo-can reports no model: the drive's identity is given one here).
        DriveIdentity other = tuning->driveInfo().identity;
        other.model = QStringLiteral("M-200");
        run.model = QStringLiteral("M-100");
        run.tuning = {{60, QStringLiteral("P60"), QStringLiteral("speed-kp"), 50}};
        editor->applyRun(run, other);
        QVERIFY2(editor->message().contains(QStringLiteral("M-100"))
                     && editor->message().contains(QStringLiteral("M-200")),
                 qPrintable(editor->message()));
        QVERIFY(!editor->isBusy());
        QTest::qWait(200);
        QCOMPARE(onDrive(60), 45);
    }

    void spectrumOfARunListsItsPeak()
    {
        TuningRun run;
        run.label = QStringLiteral("sine");
        run.capture.channels = {QStringLiteral("speed")};
        run.capture.columns.resize(1);
        for (int i = 0; i < 2000; ++i) {
            run.capture.time << i * 1e-3;
            run.capture.columns[0] << 10.0 * std::sin(2 * M_PI * 80.0 * i * 1e-3);
        }
        SpectrumView view;
        view.setRun(&run);
        QVERIFY(!view.spectrum().isEmpty());
        QVERIFY(qAbs(view.spectrum().peaks.first().hz - 80.0) < 1.0);
        QVERIFY2(view.peaksText().contains(QStringLiteral("80.0 Hz")), qPrintable(view.peaksText()));
        QVERIFY(view.plot()->timeTitle().contains(QStringLiteral("Hann")));
        QVERIFY(view.plot()->timeTitle().contains(QStringLiteral("resolution 0.5 Hz")));
        // What it cannot see (issue 26): the Nyquist frequency on the axis, the band above
        // the usable one (90 % of Nyquist) greyed.
        QVERIFY2(view.plot()->timeTitle().contains(QStringLiteral("Nyquist 500.0 Hz")),
                 qPrintable(view.plot()->timeTitle()));
        QVERIFY(view.plot()->greyedFrom().has_value());
        QVERIFY(qAbs(*view.plot()->greyedFrom() - 450.0) < 1e-6);
        QVERIFY2(view.peaksText().contains(QStringLiteral("Nyquist frequency 500.0 Hz")), qPrintable(view.peaksText()));
        view.setRun(nullptr);
        QVERIFY(!view.plot()->greyedFrom().has_value());
        QVERIFY(view.spectrum().isEmpty());
    }

    void noOverflowAt1280_data()
    {
        QTest::addColumn<bool>("chinese");
        QTest::newRow("en") << false;
        QTest::newRow("zh") << true;
    }
    void noOverflowAt1280()
    {
        QFETCH(bool, chinese);
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        LanguageManager language;
        if (chinese) {
            QVERIFY(language.apply(LanguageManager::Language::Chinese));
            QCoreApplication::sendPostedEvents();
        }
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QVERIFY(dictionaryLoaded(tuning));
        // The workspace beside the bus tree of a 1280 x 720 window.
        const int width = 1280 - 380;
        rig.workspace->resize(width, 620);
        QCoreApplication::processEvents();
        tuning->resize(width - 8, 560);
        QCoreApplication::processEvents();
        QVERIFY2(
            tuning->minimumSizeHint().width() <= tuning->width(),
            qPrintable(
                QStringLiteral("needs %1 px, has %2").arg(tuning->minimumSizeHint().width()).arg(tuning->width())));
        for (QScrollBar *bar : tuning->findChildren<QScrollBar *>())
            if (bar->orientation() == Qt::Horizontal && bar->parentWidget()
                && bar->parentWidget()->objectName() != QLatin1String("qt_scrollarea_hcontainer"))
                QVERIFY(!bar->isVisible());
        for (QWidget *w : tuning->findChildren<QWidget *>()) {
            if (!w->isVisibleTo(tuning) || w->inherits("QScrollBar") || !w->parentWidget()
                || w->parentWidget()->inherits("QAbstractScrollArea"))
                continue;
            const QRect r(w->mapTo(tuning, QPoint(0, 0)), w->size());
            QVERIFY2(r.right() < tuning->width() + 1,
                     qPrintable(w->metaObject()->className() + QStringLiteral(" ") + w->objectName()));
            if (w->inherits("QAbstractButton"))
                QVERIFY2(w->width() >= w->minimumSizeHint().width(), qPrintable(w->objectName()));
        }
        // The side column (a vertical scroll area) shows its content whole: never cut, never
        // scrolled sideways.
        QScrollArea *side = tuning->sidePanel();
        QVERIFY2(side->widget()->width() <= side->viewport()->width(),
                 qPrintable(QStringLiteral("%1 > %2").arg(side->widget()->width()).arg(side->viewport()->width())));
        QVERIFY(side->widget()->minimumSizeHint().width() <= side->viewport()->width());
        // Every form field has its label.
        int fields = 0;
        for (QFormLayout *form : side->widget()->findChildren<QFormLayout *>())
            for (int row = 0; row < form->rowCount(); ++row) {
                auto *label = qobject_cast<QLabel *>(form->itemAt(row, QFormLayout::LabelRole)
                                                         ? form->itemAt(row, QFormLayout::LabelRole)->widget()
                                                         : nullptr);
                QVERIFY(label);
                QVERIFY(!label->text().isEmpty());
                ++fields;
            }
        QVERIFY(fields >= 14);
        if (chinese)
            language.apply(LanguageManager::Language::English);
    }

    // A run made by the CLI in English, shown in Chinese: a metric it could not measure
    // because a channel was not captured says so in Chinese (the file keeps English).
    void aMissingChannelIsSaidInTheUiLanguage()
    {
        TuningRun run;
        run.label = QStringLiteral("velocity-step");
        run.capture.channels = {QStringLiteral("speed")};
        run.capture.columns = {{}};
        for (int i = 0; i <= 500; ++i) { // a clean first-order step: every speed metric resolves
            const double t = i * 0.001;
            run.capture.time << t;
            run.capture.columns[0] << (t < 0.0 ? 0.0 : 100.0 * (1.0 - std::exp(-t / 0.02)));
        }
        run.capture.interval = IntervalStats::of(run.capture.time);
        run.metricsChannel = QStringLiteral("speed");
        run.metrics = StepMetrics::compute(run.capture, StepMetrics::Input{});
        const QString english = run.metrics.peakFollowingError.reason;
        QVERIFY(english.contains(QStringLiteral("position-error was not captured")));
        LanguageManager language;
        QVERIFY(language.apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents();
        const QString chinese = StepMetrics::tr("channel %1 was not captured").arg(QStringLiteral("position-error"));
        QVERIFY(chinese != english);
        RunComparison comparison;
        comparison.setRuns({run});
        QVERIFY2(!comparison.notesText().contains(QStringLiteral("was not captured")),
                 qPrintable(comparison.notesText()));
        QVERIFY2(comparison.notesText().contains(chinese), qPrintable(comparison.notesText()));
        QVERIFY(language.apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        QVERIFY(comparison.notesText().contains(english)); // and back, live
    }

    void followsALiveLanguageSwitch()
    {
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TuningPanel *tuning = rig.show<TuningPanel>(&why);
        QVERIFY2(tuning, qPrintable(why));
        QCOMPARE(tuning->title(), QStringLiteral("Tuning"));
        QVERIFY(dictionaryLoaded(tuning));
        QVERIFY2(captureOnce(tuning, &why), qPrintable(why));
        const QString channelName = tuning->plotChannel()->currentText();
        QCOMPARE(tuning->plotChannel()->currentData().toString(), QStringLiteral("speed"));
        const QString arm = tuning->captureControls()->armButton()->text();
        const QString reason = tuning->stepControls()->blockedReason();
        LanguageManager language;
        QVERIFY(language.apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents();
        QVERIFY(tuning->title() != QStringLiteral("Tuning"));
        QVERIFY(tuning->captureControls()->armButton()->text() != arm);
        QVERIFY(tuning->stepControls()->blockedReason() != reason);
        // The drive's channel names (read again in the new language) reach the plot's list.
        QVERIFY(waitUntil([&] { return tuning->plotChannel()->currentText() != channelName; }, 5000));
        QCOMPARE(tuning->plotChannel()->currentData().toString(), QStringLiteral("speed"));
        QVERIFY(tuning->comparison()->table()->verticalHeaderItem(0) == nullptr
                || tuning->comparison()->table()->verticalHeaderItem(0)->text()
                    != QStringLiteral("Rise time (10–90 %)"));
        QVERIFY(language.apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        QCOMPARE(tuning->captureControls()->armButton()->text(), arm);
    }
};

QTEST_MAIN(TstTuningPanel)
#include "tst_tuningpanel.moc"
