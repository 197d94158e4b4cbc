#include "core/params/parameterdictionary.h"
#include "core/tuning/capturerecorder.h"
#include "core/tuning/commandwatch.h"
#include "core/tuning/runcompatibility.h"
#include "core/tuning/runparameterapply.h"
#include "core/tuning/spectrum.h"
#include "core/tuning/steplimits.h"
#include "core/tuning/stepmetrics.h"
#include "core/tuning/stepplan.h"
#include "core/tuning/stepspec.h"
#include "core/tuning/tuningrun.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace dd;

namespace {
constexpr double Pi = 3.14159265358979323846;

CaptureSettings settings(const QString &trigger, double pre, double duration,
                         CaptureSettings::Mode mode = CaptureSettings::Mode::Single)
{
    CaptureSettings s;
    TriggerSpec::parse(trigger, &s.trigger);
    s.prePercent = pre;
    s.durationS = duration;
    s.mode = mode;
    return s;
}

// A capture of y(t) (t >= 0 after the step at 0, y = 0 before) sampled every dt.
CaptureData synthetic(const std::function<double(double)> &y, double dt, double pre, double post)
{
    CaptureData c;
    c.channels = {QStringLiteral("speed")};
    c.columns.resize(1);
    for (int i = -int(std::round(pre / dt)); i * dt <= post + 1e-12; ++i) {
        const double t = i * dt;
        c.time.append(t);
        c.columns[0].append(t < 0 ? 0.0 : y(t));
        if (t < 0)
            ++c.preTriggerSamples;
    }
    c.interval = IntervalStats::of(c.time);
    return c;
}

// The exact answer, found on a fine grid.
double firstTimeAt(const std::function<double(double)> &y, double level)
{
    for (double t = 0.0; t < 100.0; t += 1e-6)
        if (y(t) >= level)
            return t;
    return NAN;
}
double settleTime(const std::function<double(double)> &y, double band, double until)
{
    double last = 0.0;
    for (double t = 0.0; t < until; t += 1e-6)
        if (std::abs(y(t) - 1.0) > band)
            last = t;
    return last;
}

TuningRun sampleRun()
{
    TuningRun run;
    run.created = QDateTime::fromString(QStringLiteral("2026-11-25T21:00:00.000Z"), Qt::ISODateWithMs);
    run.family = QStringLiteral("servo-can");
    run.address = 1;
    run.linkKind = QStringLiteral("can");
    run.linkDescription = QStringLiteral("virtualcan:can0 1000000 bit/s");
    run.test = QStringLiteral("velocity-step");
    run.testParameters = {{QStringLiteral("speed"), 300}, {QStringLiteral("duration"), 0.2}};
    run.settings = settings(QStringLiteral("motion"), 20, 0.25);
    run.capture = synthetic([](double t) { return 300.0 * (1 - std::exp(-t / 0.01)); }, 0.001, 0.05, 0.2);
    run.capture.channels << QStringLiteral("current");
    run.capture.columns.append(QVector<double>(run.capture.time.size(), 1.25));
    run.capture.columns[1][3] = NAN; // a value not read
    run.capture.triggerSource = QStringLiteral("motion");
    run.units = {QStringLiteral("r/min"), QStringLiteral("A")};
    StepMetrics::Input in;
    in.target = 300.0;
    run.metrics = StepMetrics::compute(run.capture, in);
    run.metricsChannel = QStringLiteral("speed");
    run.tuning = {{60, QStringLiteral("P60"), QStringLiteral("speed-kp"), 30},
                  {61, QStringLiteral("P61"), QStringLiteral("speed-ki"), 30}};
    run.notes = QStringLiteral("first try, 轻载");
    return run;
}
} // namespace

class TestCapture : public QObject
{
    Q_OBJECT

private slots:
    void levelTriggerAtTheRightSampleWithExactPreTrigger()
    {
        // 1 kHz samples of a ramp crossing 500 at sample 700; 25 % of 0.2 s before it.
        CaptureRecorder r;
        r.arm(settings(QStringLiteral("rise:speed:500"), 25, 0.2), {QStringLiteral("speed")});
        bool done = false;
        int i = 0;
        for (; i < 2000 && !done; ++i)
            done = r.feed(i * 0.001, {double(i) - 200.0}); // crosses 500 at i = 700
        QVERIFY(done);
        const CaptureData d = r.take();
        QCOMPARE(d.preTriggerSamples, 50);    // exactly 0.05 s at 1 ms
        QCOMPARE(d.columns[0].at(50), 500.0); // the first sample at or above the level is time 0
        QCOMPARE(d.columns[0].at(49), 499.0);
        QCOMPARE(d.time.at(50), 0.0);
        QCOMPARE(d.time.size(), 50 + 151); // 0 .. 0.15 s inclusive
        QVERIFY(std::abs(d.time.first() + 0.05) < 1e-9);
        QVERIFY(std::abs(d.time.last() - 0.15) < 1e-9);
        QVERIFY(d.gaps.isEmpty());
        QCOMPARE(d.triggerSource, QStringLiteral("rise:speed:500"));
    }

    void triggerWaitsForThePreTriggerWindow()
    {
        // The level is already crossed while the window fills: only a later crossing counts.
        CaptureRecorder r;
        r.arm(settings(QStringLiteral("either:speed:0"), 50, 0.1), {QStringLiteral("speed")});
        bool done = false;
        for (int i = 0; i < 1000 && !done; ++i)
            done = r.feed(i * 0.001, {std::sin(2 * Pi * 20 * i * 0.001 + 0.1)}); // 20 Hz: crosses every 25 ms
        const CaptureData d = r.take();
        QCOMPARE(d.preTriggerSamples, 50);
        QVERIFY(d.time.first() >= -0.05 - 1e-9);
    }

    void externalAndTimeoutTriggers()
    {
        CaptureRecorder r;
        r.arm(settings(QStringLiteral("motion"), 10, 0.1), {QStringLiteral("speed")});
        for (int i = 0; i < 30; ++i)
            r.feed(i * 0.002, {0.0});
        r.trigger(0.0595, QStringLiteral("motion")); // between two samples
        bool done = false;
        for (int i = 30; i < 200 && !done; ++i)
            done = r.feed(i * 0.002, {1.0});
        const CaptureData d = r.take();
        QCOMPARE(d.preTriggerSamples, 5); // 0.05 .. 0.058: the samples in the 10 ms before 0.0595
        QVERIFY(d.time.at(5) > 0.0);
        QCOMPARE(d.triggerSource, QStringLiteral("motion"));

        CaptureRecorder a;
        a.arm(settings(QStringLiteral("rise:speed:5"), 0, 0.05, CaptureSettings::Mode::Auto),
              {QStringLiteral("speed")});
        done = false;
        for (int i = 0; i < 2000 && !done; ++i)
            done = a.feed(i * 0.001, {0.0});
        QVERIFY(done);
        QCOMPARE(a.take().triggerSource, QStringLiteral("timeout"));
    }

    void gapsAreRecorded()
    {
        CaptureRecorder r;
        r.arm(settings(QStringLiteral("now"), 0, 0.2), {QStringLiteral("speed")});
        bool done = false;
        for (int i = 0; i < 400 && !done; ++i)
            if (i < 50 || i > 80)
                done = r.feed(i * 0.001, {1.0});
        const CaptureData d = r.take();
        QCOMPARE(d.gaps.size(), 1);
        QVERIFY(std::abs(d.gaps.first().from - 0.049) < 1e-9);
        QVERIFY(std::abs(d.gaps.first().to - 0.081) < 1e-9);
    }

    void metricsOfAFirstOrderResponse()
    {
        const double tau = 0.02, dt = 0.001;
        auto y = [tau](double t) { return 1.0 - std::exp(-t / tau); };
        StepMetrics::Input in;
        in.target = 1.0;
        const StepMetrics m = StepMetrics::compute(synthetic(y, dt, 0.02, 0.3), in);
        QVERIFY(m.riseTime.value && m.settlingTime2.value && m.settlingTime5.value);
        QVERIFY(std::abs(*m.riseTime.value - tau * std::log(9.0)) <= dt);
        QVERIFY(std::abs(*m.settlingTime2.value - tau * std::log(50.0)) <= dt);
        QVERIFY(std::abs(*m.settlingTime5.value - tau * std::log(20.0)) <= dt);
        QCOMPARE(*m.overshoot.value, 0.0);
        QVERIFY(std::abs(*m.steadyStateError.value) < 1e-4);
        QVERIFY(std::abs(*m.sampleInterval.value - dt) < 1e-12);
        QCOMPARE(m.riseTime.resolution, dt);
        QVERIFY(!m.peakTorque.value);
        QVERIFY(m.peakTorque.reason.contains(QLatin1String("torque")));
    }

    void metricsOfASecondOrderResponse()
    {
        const double zeta = 0.3, wn = 2 * Pi * 10, dt = 0.001;
        const double wd = wn * std::sqrt(1 - zeta * zeta), phi = std::acos(zeta);
        auto y = [=](double t) {
            return 1.0 - std::exp(-zeta * wn * t) / std::sqrt(1 - zeta * zeta) * std::sin(wd * t + phi);
        };
        StepMetrics::Input in;
        in.target = 1.0;
        const StepMetrics m = StepMetrics::compute(synthetic(y, dt, 0.05, 1.0), in);
        const double rise = firstTimeAt(y, 0.9) - firstTimeAt(y, 0.1);
        const double overshoot = 100.0 * std::exp(-Pi * zeta / std::sqrt(1 - zeta * zeta));
        QVERIFY(std::abs(*m.riseTime.value - rise) <= dt);
        // The sampled peak is within the change over one interval of the true one.
        QVERIFY2(std::abs(*m.overshoot.value - overshoot) <= m.overshoot.resolution + 0.1,
                 qPrintable(QStringLiteral("%1 vs %2").arg(*m.overshoot.value).arg(overshoot)));
        QVERIFY(std::abs(*m.settlingTime2.value - settleTime(y, 0.02, 1.0)) <= dt);
        QVERIFY(std::abs(*m.settlingTime5.value - settleTime(y, 0.05, 1.0)) <= dt);
    }

    void aStallAfterTheRiseDoesNotHideIt()
    {
        // A 25 ms stall of the link long after the rise (a loaded host): the rise and the
        // settling rest on the 1 ms samples around them and are still measured.
        const double tau = 0.004, dt = 0.001;
        auto y = [tau](double t) { return 1.0 - std::exp(-t / tau); };
        CaptureData c = synthetic(y, dt, 0.02, 0.3);
        for (int i = c.time.size() - 1; i >= 0; --i)
            if (c.time.at(i) > 0.2 && c.time.at(i) < 0.225) {
                c.time.remove(i);
                c.columns[0].remove(i);
            }
        c.interval = IntervalStats::of(c.time);
        QVERIFY(c.interval.max > 0.02);
        StepMetrics::Input in;
        in.target = 1.0;
        const StepMetrics m = StepMetrics::compute(c, in);
        QVERIFY2(m.riseTime.value, qPrintable(m.riseTime.reason));
        QVERIFY(std::abs(*m.riseTime.value - tau * std::log(9.0)) <= dt);
        QVERIFY2(m.settlingTime2.value, qPrintable(m.settlingTime2.reason));
    }

    void slowSamplingSaysSoInsteadOfANumber()
    {
        // Shuoke over RTU samples at ~18 Hz: a 5 ms rise cannot be measured.
        auto y = [](double t) { return 1.0 - std::exp(-t / 0.002); };
        StepMetrics::Input in;
        in.target = 1.0;
        const StepMetrics m = StepMetrics::compute(synthetic(y, 1.0 / 18, 0.2, 2.0), in);
        QVERIFY(!m.riseTime.value);
        QVERIFY(!m.overshoot.value);
        QVERIFY(m.riseTime.reason.contains(QLatin1String("not resolvable")));
        QVERIFY(m.valuesJson().value(QStringLiteral("riseTime")).isNull());
        QVERIFY(m.notes().join(QLatin1Char('\n')).contains(QLatin1String("riseTime: ")));
        QVERIFY(m.sampleInterval.value);
    }

    void spectrumFindsASine()
    {
        QVector<double> t, v;
        for (int i = 0; i < 2000; ++i) { // 2 s at 800 Hz with a little jitter
            t.append(i / 800.0 + ((i * 7919) % 13 - 6) * 1e-5);
            v.append(3.0 + 2.0 * std::sin(2 * Pi * 80.0 * t.last()) + 0.3 * std::sin(2 * Pi * 230.0 * t.last()));
        }
        QString error;
        const Spectrum s = Spectrum::compute(t, v, 3, &error);
        QVERIFY2(!s.isEmpty(), qPrintable(error));
        QCOMPARE(s.window, QStringLiteral("Hann"));
        QVERIFY(std::abs(s.resolutionHz - 0.4) < 0.01);
        QVERIFY(s.peaks.size() >= 2);
        QVERIFY(std::abs(s.peaks.at(0).hz - 80.0) < s.resolutionHz);
        QVERIFY(std::abs(s.peaks.at(0).magnitude - 2.0) < 0.3);
        QVERIFY(std::abs(s.peaks.at(1).hz - 230.0) < s.resolutionHz);
        QVERIFY(Spectrum::compute(t.mid(0, 10), v.mid(0, 10), 3, &error).isEmpty());
    }

    // Issue 26, item 8: a 150 Hz resonance read at ~245 Hz (arrival-timed reads, their
    // intervals uneven) gives its top peak below the 122.5 Hz Nyquist frequency; the spectrum
    // says it may be an alias of ~150 Hz, and states the Nyquist frequency and usable band.
    // (It used to give such a peak with no note at all.)
    void spectrumSaysWhatItCannotSee()
    {
        quint32 seed = 12345;
        auto rnd = [&seed] {
            seed = seed * 1664525u + 1013904223u;
            return double(seed >> 8) / double(1u << 24);
        };
        auto sampled = [&rnd](double rateHz, double jitter, double sineHz, int n, QVector<double> *t,
                              QVector<double> *v) {
            double at = 0.0;
            for (int i = 0; i < n; ++i) {
                at += (1.0 + jitter * (2.0 * rnd() - 1.0)) / rateHz;
                t->append(at);
                v->append(50.0 * std::sin(2 * Pi * sineHz * at));
            }
        };
        QVector<double> t, v;
        sampled(245.0, 0.2, 150.0, 1500, &t, &v);
        QString error;
        Spectrum s = Spectrum::compute(t, v, 3, &error);
        QVERIFY2(!s.isEmpty(), qPrintable(error));
        QVERIFY(std::abs(s.nyquistHz - 122.5) < 2.0);
        QVERIFY(std::abs(s.usableToHz - 0.9 * s.nyquistHz) < 1e-9);
        QVERIFY(std::abs(s.usableFromHz - 2 * s.resolutionHz) < 1e-9);
        const Spectrum::Peak top = s.peaks.first();
        qInfo("150 Hz read at ~245 Hz: top peak %.1f Hz, marked as an alias of %.1f Hz", top.hz, top.aliasOfHz);
        QVERIFY(top.hz < s.nyquistHz);
        QVERIFY2(std::abs(top.aliasOfHz - 150.0) < 3.0, qPrintable(QString::number(top.aliasOfHz)));
        const QString notes = s.notes.join(QLatin1Char('\n'));
        QVERIFY2(notes.contains(QLatin1String("Nyquist frequency 122.")) && notes.contains(QLatin1String("usable band"))
                     && notes.contains(QLatin1String("may be an alias")),
                 qPrintable(notes));

        // Read fast enough, with the same unevenness, a 20 Hz sine is not suspect.
        t.clear();
        v.clear();
        sampled(1000.0, 0.2, 20.0, 2000, &t, &v);
        s = Spectrum::compute(t, v, 3, &error);
        QVERIFY(std::abs(s.peaks.first().hz - 20.0) < s.resolutionHz);
        QVERIFY(!s.peaks.first().isSuspect());
        QVERIFY2(!s.notes.join(' ').contains(QLatin1String("the peak at 20.")), qPrintable(s.notes.join('\n')));

        // A peak within 10 % of Nyquist is marked so.
        t.clear();
        v.clear();
        sampled(245.0, 0.02, 115.0, 1500, &t, &v);
        s = Spectrum::compute(t, v, 3, &error);
        QVERIFY(s.peaks.first().hz > 0.9 * s.nyquistHz);
        QVERIFY(s.peaks.first().nearNyquist);

        // The gaps note stays with a stretch (--between): the overload for a time window.
        CaptureData c;
        c.channels = {QStringLiteral("speed")};
        c.columns.resize(1);
        for (int i = 0; i < 400; ++i) {
            const double at = i * 1e-3 + (i >= 200 ? 0.05 : 0.0); // 50 ms missing after 0.2 s
            c.time << at;
            c.columns[0] << std::sin(2 * Pi * 30.0 * at);
        }
        c.gaps = CaptureGap::of(c.time);
        QCOMPARE(c.gaps.size(), 1);
        s = Spectrum::compute(c, QStringLiteral("speed"), 3, &error, 0.0, 0.1, 0.4);
        QVERIFY2(s.notes.join(' ').contains(QLatin1String("bridged by interpolation")), qPrintable(s.notes.join(' ')));
        s = Spectrum::compute(c, QStringLiteral("speed"), 3, &error, 0.0, 0.0, 0.19);
        QVERIFY(!s.notes.join(' ').contains(QLatin1String("bridged")));
    }

    void runFilesRoundTrip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.ddrun"));
        const TuningRun run = sampleRun();
        QVERIFY(!run.save(path));
        TuningRun back;
        const Error e = TuningRun::load(path, &back);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(back.toJson(), run.toJson());
        QCOMPARE(back.capture.preTriggerSamples, 50);
        QVERIFY(std::isnan(back.capture.columns[1][3]));
        QCOMPARE(back.tuning.at(0).role, QStringLiteral("speed-kp"));
        QCOMPARE(back.label, QStringLiteral("a"));
        QCOMPARE(*back.metrics.riseTime.value, *run.metrics.riseTime.value);
        QCOMPARE(back.notes, run.notes);
    }

    void badRunFilesRefused_data()
    {
        QTest::addColumn<QString>("pointer"); // field path "a.b" or "a.b[3]"
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("word");
        QTest::newRow("format") << "format" << QJsonValue("drivedesk-backup") << "not a DriveDesk run file";
        QTest::newRow("version") << "formatVersion" << QJsonValue(2) << "version 2";
        // A version as a string is not "another version" (issue 26 item 9).
        QTest::newRow("version as a string") << "formatVersion" << QJsonValue("1") << "formatVersion must be a number";
        QTest::newRow("result outcome") << "result" << QJsonValue(QJsonObject{{"outcome", "maybe"}}) << "maybe";
        QTest::newRow("family") << "drive.family" << QJsonValue("servo-x") << "servo-x";
        QTest::newRow("test type") << "test.type" << QJsonValue("bump") << "bump";
        QTest::newRow("trigger") << "trigger.expression" << QJsonValue("rise:speed") << "trigger.expression";
        QTest::newRow("pre") << "trigger.prePercent" << QJsonValue(150) << "prePercent";
        QTest::newRow("pre count") << "trigger.preTriggerSamples" << QJsonValue(7) << "preTriggerSamples";
        QTest::newRow("time back") << "samples.time[10]" << QJsonValue(-1.0) << "time[10]";
        QTest::newRow("value type") << "samples.speed[4]" << QJsonValue("fast") << "speed[4]";
        QTest::newRow("column length") << "samples.current" << QJsonValue(QJsonArray{1, 2}) << "samples.current";
        QTest::newRow("unknown column") << "samples.torque" << QJsonValue(QJsonArray{}) << "samples.torque";
        QTest::newRow("metric") << "metrics.riseTime" << QJsonValue("quick") << "riseTime";
        QTest::newRow("tuning role") << "tuning[0].role" << QJsonValue("speed-gain") << "speed-gain";
        QTest::newRow("tuning value") << "tuning[1].value" << QJsonValue(1.5) << "whole number";
        // A parameter listed twice (issue 26: the index check compared with -1 and passed).
        QTest::newRow("tuning index twice") << "tuning[1].index" << QJsonValue(60) << "twice";
        QTest::newRow("tuning key twice") << "tuning[1].key" << QJsonValue("p60") << "twice";
        QTest::newRow("unknown field") << "extra" << QJsonValue(1) << "extra";
        QTest::newRow("created") << "created" << QJsonValue("yesterday") << "yesterday";
    }

    void badRunFilesRefused()
    {
        QFETCH(QString, pointer);
        QFETCH(QJsonValue, value);
        QFETCH(QString, word);
        QJsonObject root = sampleRun().toJson();
        // Set root[pointer] = value (one or two levels, an optional [index] at the end).
        const QStringList parts = pointer.split(QLatin1Char('.'));
        std::function<void(QJsonObject &, int)> set = [&](QJsonObject &o, int level) {
            QString name = parts.at(level);
            int index = -1;
            if (name.endsWith(QLatin1Char(']'))) {
                index = name.section(QLatin1Char('['), 1).chopped(1).toInt();
                name = name.section(QLatin1Char('['), 0, 0);
            }
            if (level + 1 < parts.size()) {
                QJsonObject inner = o.value(name).toObject();
                set(inner, level + 1);
                o.insert(name, inner);
            } else if (index >= 0) {
                QJsonArray a = o.value(name).toArray();
                if (a.at(index).isObject()) {
                    QJsonObject e = a.at(index).toObject();
                    e.insert(parts.last().section(QLatin1Char('.'), -1), value);
                    a.replace(index, e);
                } else {
                    a.replace(index, value);
                }
                o.insert(name, a);
            } else {
                o.insert(name, value);
            }
        };
        if (pointer.startsWith(QLatin1String("tuning["))) {
            const int index = pointer.mid(7, 1).toInt();
            QJsonArray a = root.value(QStringLiteral("tuning")).toArray();
            QJsonObject e = a.at(index).toObject();
            e.insert(pointer.section(QLatin1Char('.'), 1), value);
            a.replace(index, e);
            root.insert(QStringLiteral("tuning"), a);
        } else {
            set(root, 0);
        }
        TuningRun out = sampleRun();
        out.notes = QStringLiteral("unchanged");
        const Error e = TuningRun::fromBytes(QJsonDocument(root).toJson(), QStringLiteral("bad.ddrun"), &out);
        QVERIFY(e.isError());
        QVERIFY2(e.message.contains(word), qPrintable(e.message));
        QVERIFY2(e.message.startsWith(QLatin1String("bad.ddrun")), qPrintable(e.message));
        QCOMPARE(out.notes, QStringLiteral("unchanged")); // nothing changed
        QVERIFY(
            TuningRun::fromBytes("{ not json", QStringLiteral("x.ddrun"), &out).message.contains(QLatin1String("JSON")));
    }

    void anAbortedRunKeepsItsOutcome()
    {
        TuningRun run = sampleRun();
        run.outcome = QStringLiteral("aborted");
        run.abortCause = QStringLiteral("external-stop");
        run.abortReason = QStringLiteral("Stopped by another master or at the drive");
        TuningRun back;
        const Error e = TuningRun::fromBytes(run.toBytes(), QStringLiteral("a.ddrun"), &back);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(back.outcome, QStringLiteral("aborted"));
        QCOMPARE(back.abortCause, QStringLiteral("external-stop"));
        QCOMPARE(back.abortReason, run.abortReason);
        QCOMPARE(back.toJson(), run.toJson());
    }

    void tooManySamplesAreRefusedWithTheCap()
    {
        // A run holds at most TuningRun::MaxSamples rows (docs/tuning.md): one more is
        // refused with the count and the cap, before its columns are read.
        QJsonObject root = sampleRun().toJson();
        const int n = TuningRun::MaxSamples + 1;
        QJsonArray time, speed, current;
        for (int i = 0; i < n; ++i) {
            time.append(i * 1e-3);
            speed.append(0);
            current.append(0);
        }
        QJsonObject samples{{"time", time}, {"speed", speed}, {"current", current}};
        root.insert(QStringLiteral("samples"), samples);
        QJsonObject trigger = root.value(QStringLiteral("trigger")).toObject();
        trigger.insert(QStringLiteral("preTriggerSamples"), 0);
        root.insert(QStringLiteral("trigger"), trigger);
        TuningRun out;
        const Error e = TuningRun::fromJson(root, QStringLiteral("big.ddrun"), &out);
        QCOMPARE(e.code, ErrorCode::Malformed);
        QVERIFY2(e.message.contains(QStringLiteral("1000001 samples")) && e.message.contains(QStringLiteral("1000000")),
                 qPrintable(e.message));
    }

    void thePlanPredictsTravelAndTimeWithTheStop()
    {
        // servo-can's r/min at 10000 counts/rev: 300 r/min = 50000 counts/s.
        const double k = StepPlan::countsPerSpeedUnit(QStringLiteral("r/min"), 0);
        QCOMPARE(k, 10000.0 / 60.0);
        QCOMPARE(StepPlan::countsPerSpeedUnit(QStringLiteral("r/min"), 131072), 131072.0 / 60.0);
        QCOMPARE(StepPlan::countsPerSpeedUnit(QStringLiteral("pulse/s"), 0), 1.0);
        QCOMPARE(StepPlan::countsPerSpeedUnit(QStringLiteral("furlong"), 0), 0.0);
        QCOMPARE(StepPlan::decelFromParameter(QStringLiteral("r/min/ms"), 6), 6000.0);
        QCOMPARE(StepPlan::decelFromParameter(QStringLiteral("ms"), 6), 0.0);
        StepSpec v;
        v.kind = StepSpec::Kind::Velocity;
        v.speed = 300;
        v.durationS = 2.0;
        StepLimits l;
        l.maxSpeed = 500;
        l.maxTravel = 1000;
        l.maxDurationS = 4;
        // The test: ~100,000 counts against a travel of 1000 — refused, even without
        // the stop.
        StepPlan p = StepPlan::predict(v, k);
        QCOMPARE(qRound(p.travel), 100000);
        Error e = p.check(l);
        QCOMPARE(e.code, ErrorCode::OutOfRange); // refused: nothing moved
        QVERIFY2(e.message.contains(QStringLiteral("beyond the maximum travel 1000")), qPrintable(e.message));
        // With the stop at 6000 r/min/s: 50 ms more, 1250 counts more.
        p = StepPlan::predict(v, k, 6000.0);
        QCOMPARE(qRound(p.travel), 101250);
        QCOMPARE(p.seconds, 2.05);
        l.maxTravel = 101000;
        QVERIFY(p.check(l).message.contains(QStringLiteral("including its stop")));
        l.maxTravel = 102000;
        QVERIFY(!p.check(l));
        l.maxDurationS = 2.04;
        QVERIFY(p.check(l).message.contains(QStringLiteral("maximum duration")));
        // A position step of 60000 counts at 300 r/min needs 1.2 s (+ the ramps): not in 0.5 s.
        StepSpec pos;
        pos.kind = StepSpec::Kind::Position;
        pos.speed = 300;
        pos.distance = -60000;
        p = StepPlan::predict(pos, k);
        QCOMPARE(p.seconds, 1.2);
        QCOMPARE(qRound(p.travel), 60000);
        l.maxTravel = 100000;
        l.maxDurationS = 0.5;
        QVERIFY(p.check(l).message.contains(QStringLiteral("maximum duration of 0.5 s")));
        p = StepPlan::predict(pos, k, 6000.0); // + 50 ms of ramp
        QVERIFY(std::abs(p.seconds - 1.25) < 1e-9);
        // Stopping distance: at 50000 counts/s and 300 r/min, 10 ms reaction + 25 ms braking.
        QVERIFY(std::abs(p.stoppingDistance(50000, 300, 0.01) - 1750.0) < 1e-6);
        // Still ramping up at 150 r/min (25000 counts/s): 10 ms more at up to 6000 r/min/s
        // (210 r/min, 35000 counts/s), then 35 ms of braking: 300 + 612.5 counts.
        QVERIFY(std::abs(p.stoppingDistance(25000, 150, 0.01, true, 300) - 912.5) < 1e-6);
    }

    void theWatchSeesTheDriveStopOrChangeCommand()
    {
        CommandWatch w;
        QMap<QString, double> sample{{"speed-command", 0}, {"speed", 0}};
        DriveStatus st;
        st.enabled = true;
        // Idle: nothing is watched.
        QVERIFY(w.feedSample(sample).isEmpty());
        w.expectSpeed(300, true);
        // The command not taken yet: still 0, no verdict.
        QVERIFY(w.feedSample(sample).isEmpty());
        QVERIFY(w.feedStatus(st).isEmpty());
        sample[QStringLiteral("speed-command")] = 300;
        QVERIFY(w.feedSample(sample).isEmpty());
        st.running = true;
        QVERIFY(w.feedStatus(st).isEmpty());
        // Someone else's STOP: the command falls to 0.
        sample[QStringLiteral("speed-command")] = 0;
        QVERIFY(w.feedSample(sample).contains(QStringLiteral("speed command changed from 300 to 0")));
        // Another master's speed.
        w.expectSpeed(300, true);
        sample[QStringLiteral("speed-command")] = 300;
        QVERIFY(w.feedSample(sample).isEmpty());
        sample[QStringLiteral("speed-command")] = 120;
        QVERIFY(!w.feedSample(sample).isEmpty());
        // At rest by the status once running; disabled.
        w.idle();
        w.expectSpeed(300, true);
        QVERIFY(w.feedStatus(st).isEmpty());
        st.running = false;
        QVERIFY(w.feedStatus(st).contains(QStringLiteral("at rest")));
        w.idle();
        st.running = true;
        w.expectSpeed(300, false); // a reversal's second segment: rest is on the way
        QVERIFY(w.feedStatus(st).isEmpty());
        st.running = false;
        QVERIFY(w.feedStatus(st).isEmpty());
        st.enabled = false;
        QVERIFY(w.feedStatus(st).contains(QStringLiteral("disabled")));
        // shuoke's status bits: running, then not.
        w.idle();
        w.expectSpeed(1000, true);
        QMap<QString, double> bits{{"status", double(StatusChannelBits::Running | StatusChannelBits::EnableInput)}};
        QVERIFY(w.feedSample(bits).isEmpty());
        bits[QStringLiteral("status")] = StatusChannelBits::EnableInput;
        QVERIFY(w.feedSample(bits).contains(QStringLiteral("stopped running")));
        // Idle after the test's own stop: nothing more is said.
        w.idle();
        QVERIFY(w.feedSample(bits).isEmpty());
    }

    // Issue 26, item 5: apply-run writes tuning parameters only, judged by the role the
    // dictionary in force gives each parameter, never by what the file claims.
    void applyRunWritesTuningParametersOnly()
    {
        const ParameterDictionary &sim = ParameterDictionary::bundledSimulator(Family::ServoCan);
        QVERIFY(!sim.tuning().isEmpty());
        QVERIFY(!RunParameterApply::check(sampleRun(), Family::ServoCan, sim));

        // Control mode and station number slipped into the tuning list: the whole run is
        // refused, naming both.
        TuningRun run = sampleRun();
        run.tuning.append({4, QStringLiteral("P4"), QString(), 0});
        run.tuning.append({75, QStringLiteral("P75"), QString(), 7});
        Error e = RunParameterApply::check(run, Family::ServoCan, sim);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY2(e.message.contains(QLatin1String("P4 ")) && e.message.contains(QLatin1String("P75 "))
                     && e.message.contains(QLatin1String("not tuning parameters"))
                     && e.message.contains(QLatin1String("nothing was written")),
                 qPrintable(e.message));
        // A role written into the file does not make a setting a gain.
        run = sampleRun();
        run.tuning.append({4, QStringLiteral("P4"), QStringLiteral("speed-kd"), 0});
        e = RunParameterApply::check(run, Family::ServoCan, sim);
        QVERIFY2(e.isError() && e.message.contains(QLatin1String("P4 ")), qPrintable(e.message));

        // A run recorded on the simulator (its dictionary names P60, P61) applied with a
        // dictionary that names no tuning parameters: refused with the reason.
        e = RunParameterApply::check(sampleRun(), Family::ServoCan, ParameterDictionary::bundled(Family::ServoCan));
        QVERIFY2(e.isError() && e.message.contains(QLatin1String("names no tuning parameters"))
                     && e.message.contains(QLatin1String("P60 = speed-kp"))
                     && e.message.contains(QLatin1String("simulator")),
                 qPrintable(e.message));
        // The GUI's roles in force (the tab's entries) are honoured the same way.
        const QVector<TuningEntry> onlyKp{{60, QStringLiteral("speed-kp")}};
        e = RunParameterApply::check(sampleRun(), Family::ServoCan, sim, &onlyKp);
        QVERIFY2(e.isError() && e.message.contains(QLatin1String("P61")), qPrintable(e.message));

        // Listed twice (a run made in memory; files are refused by the loader).
        run = sampleRun();
        run.tuning.append({60, QStringLiteral("P60"), QStringLiteral("speed-kp"), 31});
        e = RunParameterApply::check(run, Family::ServoCan, sim);
        QVERIFY2(e.isError() && e.message.contains(QLatin1String("twice")), qPrintable(e.message));
        // Another role than the dictionary's: recorded with another dictionary.
        run = sampleRun();
        run.tuning[0].role = QStringLiteral("position-kp");
        e = RunParameterApply::check(run, Family::ServoCan, sim);
        QVERIFY2(e.isError() && e.message.contains(QLatin1String("another dictionary")), qPrintable(e.message));
        // Another drive model.
        run = sampleRun();
        run.model = QStringLiteral("M6505");
        DriveIdentity id;
        id.family = Family::ServoCan;
        QVERIFY(!RunParameterApply::checkDrive(run, id)); // the drive's model unknown: nothing to compare
        id.model = QStringLiteral("M4505");
        e = RunParameterApply::checkDrive(run, id);
        QVERIFY2(e.isError() && e.message.contains(QLatin1String("M6505"))
                     && e.message.contains(QLatin1String("M4505")),
                 qPrintable(e.message));
        id.model = QStringLiteral("m6505");
        QVERIFY(!RunParameterApply::checkDrive(run, id));
    }

    // Comparing runs that are not like for like says why, instead of "no tuning parameter
    // differs".
    void runsThatDoNotCompareSaySo()
    {
        TuningRun a = sampleRun(), b = sampleRun();
        a.label = QStringLiteral("a");
        b.label = QStringLiteral("b");
        QVERIFY(RunCompatibility::differences(a, b).isEmpty());
        QCOMPARE(RunCompatibility::stepSize(a), QStringLiteral("300 r/min"));
        b.testParameters.insert(QStringLiteral("speed"), 500);
        QStringList why = RunCompatibility::differences(a, b);
        QVERIFY2(why.join(' ').contains(QLatin1String("different sizes (300 r/min, 500 r/min)")),
                 qPrintable(why.join(' ')));
        b = sampleRun();
        b.label = QStringLiteral("b");
        b.test = QStringLiteral("position-step");
        why = RunCompatibility::differences(a, b);
        QVERIFY2(why.join(' ').contains(QLatin1String("different tests")), qPrintable(why.join(' ')));
        b = sampleRun();
        b.label = QStringLiteral("b");
        b.family = QStringLiteral("shuoke");
        QVERIFY(RunCompatibility::differences(a, b).join(' ').contains(QLatin1String("shuoke drive")));
        b = sampleRun();
        b.label = QStringLiteral("b");
        a.model = QStringLiteral("M6505");
        b.model = QStringLiteral("M4505");
        QVERIFY(RunCompatibility::differences(a, b).join(' ').contains(QLatin1String("M4505")));
        a = sampleRun();
        a.label = QStringLiteral("a");
        b.model.clear();
        b.tuning[1].role = QStringLiteral("position-ki");
        why = RunCompatibility::differences(a, b);
        QVERIFY2(why.join(' ').contains(QLatin1String("different dictionaries")), qPrintable(why.join(' ')));
        b = sampleRun();
        b.tuning.append(b.tuning.first());
        QVERIFY(RunCompatibility::snapshotProblems(b).join(' ').contains(QLatin1String("twice")));
    }
};

QTEST_GUILESS_MAIN(TestCapture)
#include "tst_capture.moc"
