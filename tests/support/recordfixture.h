#pragma once

// A commissioning record made up for tests and the benchmark (header-only: only targets that
// link drivedesk_report include it).

#include "core/report/commissioningrecord.h"
#include "core/tuning/tuningrun.h"

#include <QPainter>
#include <QtMath>
#include <cmath>

namespace dd::test {

// Parameter i of a drive: key "P<i>", default 100 + i; every `changedEvery`-th one (from 3)
// holds 5000 + 7 * i + drive instead.
inline qint64 fixtureValue(int drive, int i, int changedEvery)
{
    return (i % changedEvery == 3) ? 5000 + 7 * i + drive : 100 + i;
}

inline QImage fixturePlot(int seed)
{
    QImage image(1200, 500, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(QColor(0xcc, 0xcc, 0xcc), 1));
    for (int x = 0; x < image.width(); x += 100)
        p.drawLine(x, 0, x, image.height());
    for (int y = 0; y < image.height(); y += 50)
        p.drawLine(0, y, image.width(), y);
    QPolygonF command, actual;
    for (int x = 0; x < image.width(); ++x) {
        const double t = x / 200.0;
        command << QPointF(x, x < 100 ? 400 : 100);
        actual << QPointF(x, x < 100 ? 400 : 100 + 300 * qExp(-(t - 0.5) * (1.5 + seed * 0.2)) * qCos(3 * t));
    }
    p.setPen(QPen(Qt::blue, 2));
    p.drawPolyline(command);
    p.setPen(QPen(Qt::red, 2));
    p.drawPolyline(actual);
    return image;
}

// A velocity-step run of the servo-can drive at `address` as a step test writes it: speed
// (r/min), current (A), torque (%) and position-error (pulses) sampled every `dtMs` from
// 50 ms before the step to 450 ms after; an underdamped response to `target` r/min (about
// 16 % overshoot), metrics computed, the speed-loop gains P60/P61 in the snapshot. Sample
// 100 of the current is missing (NaN), as a lost reply leaves it.
inline TuningRun fixtureRun(int address, double target = 500.0, double dtMs = 1.0, qint64 kp = 30)
{
    TuningRun run;
    run.created = QDateTime(QDate(2026, 11, 25), QTime(13, 40, 0), Qt::UTC);
    run.family = QStringLiteral("servo-can");
    run.address = address;
    run.model = QStringLiteral("SC-40%1").arg(address);
    run.firmware = QStringLiteral("V%1.07").arg(address);
    run.linkKind = QStringLiteral("can");
    run.linkDescription = QStringLiteral("virtualcan:can0 500000 bit/s");
    run.test = QStringLiteral("velocity-step");
    run.testParameters = {{QStringLiteral("speed"), target}, {QStringLiteral("duration"), 0.45}};
    TriggerSpec::parse(QStringLiteral("motion"), &run.settings.trigger);
    run.settings.prePercent = 10;
    run.settings.durationS = 0.5;
    run.capture.channels = {QStringLiteral("speed"), QStringLiteral("current"), QStringLiteral("torque"),
                            QStringLiteral("position-error")};
    run.units = {QStringLiteral("r/min"), QStringLiteral("A"), QStringLiteral("%"), QStringLiteral("pulses")};
    run.capture.columns.resize(4);
    const double zeta = 0.5, wn = 80.0, wd = wn * std::sqrt(1 - zeta * zeta);
    const double dt = dtMs / 1000.0;
    for (int i = -int(std::lround(0.05 / dt)); i * dt <= 0.45 + 1e-12; ++i) {
        const double t = i * dt;
        const double y = t < 0 ? 0.0
                               : target
                * (1
                   - std::exp(-zeta * wn * t)
                       * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
        const double dy = t < 0
            ? 0.0
            : target * wn / std::sqrt(1 - zeta * zeta) * std::exp(-zeta * wn * t) * std::sin(wd * t);
        run.capture.time.append(t);
        run.capture.columns[0].append(y);
        run.capture.columns[1].append(0.2 + dy / 4000.0);
        run.capture.columns[2].append(dy / 400.0);
        run.capture.columns[3].append((target - y) / 10.0 * (t >= 0));
        if (t < 0)
            ++run.capture.preTriggerSamples;
    }
    run.capture.columns[1][100] = NAN;
    run.capture.triggerSource = QStringLiteral("motion");
    run.capture.interval = IntervalStats::of(run.capture.time);
    run.capture.gaps = CaptureGap::of(run.capture.time);
    StepMetrics::Input in;
    in.target = target;
    run.metrics = StepMetrics::compute(run.capture, in);
    run.metricsChannel = QStringLiteral("speed");
    run.tuning = {{60, QStringLiteral("P60"), QStringLiteral("speed-kp"), kp},
                  {61, QStringLiteral("P61"), QStringLiteral("speed-ki"), 25}};
    return run;
}

// `drives` servo-can drives at addresses 1.., each with `parameters` parameters; drive
// `failedDrive` (1-based, 0: none) failed its last verification; `runs` tuning runs spread
// over the drives.
inline CommissioningRecord fixtureRecord(int drives, int parameters, int failedDrive = 0, int runs = 0,
                                         int changedEvery = 20)
{
    CommissioningRecord record;
    record.locale = QLocale(QLocale::English, QLocale::UnitedKingdom);
    record.header.machine = QStringLiteral("Press line 3");
    record.header.customer = QStringLiteral("ACME Stamping");
    record.header.site = QStringLiteral("Hall B");
    record.header.engineer = QStringLiteral("Li Wei");
    record.header.notes = QStringLiteral("Axis 2 retuned after the gearbox change.\nEEPROM saved on every drive.");
    record.header.created = QDateTime(QDate(2026, 11, 25), QTime(14, 30, 0), Qt::UTC);
    record.header.toolVersion = QStringLiteral("0.1.0");
    record.header.computer = QStringLiteral("bench-pc");
    for (int d = 1; d <= drives; ++d) {
        DriveRecord r;
        r.family = Family::ServoCan;
        r.address = d;
        r.firmware = QStringLiteral("V%1.07").arg(d);
        r.model = QStringLiteral("SC-%1").arg(400 + d);
        r.link = QStringLiteral("virtualcan:can0 @ 500000");
        r.linkSettings = {{QStringLiteral("can"), QStringLiteral("virtualcan:can0")},
                          {QStringLiteral("bitrate"), 500000}};
        for (int i = 0; i < parameters; ++i) {
            RecordParameter p;
            p.index = i;
            p.key = QStringLiteral("P%1").arg(i);
            p.name = QStringLiteral("Parameter %1").arg(i);
            p.unit = i % 3 == 0 ? QStringLiteral("r/min") : QString();
            p.defaultValue = 100 + i;
            p.value = fixtureValue(d, i, changedEvery);
            r.parameters.append(p);
        }
        r.verification.kind = QStringLiteral("restore");
        r.verification.when = QDateTime(QDate(2026, 11, 25), QTime(13, 0, 0), Qt::UTC);
        r.verification.sourceFile = QStringLiteral("/home/li/axis%1.ddbackup").arg(d);
        r.verification.sourceChecksum = QStringLiteral("sha256:") + QString(64, QLatin1Char('a' + d % 6));
        for (int i = 3; i < parameters; i += changedEvery) {
            RecordVerification::Entry e;
            e.index = i;
            e.key = QStringLiteral("P%1").arg(i);
            e.requested = fixtureValue(d, i, changedEvery);
            e.hasReadBack = true;
            e.readBack = e.requested;
            e.outcome = QStringLiteral("verified");
            if (d == failedDrive && i == 3) {
                e.readBack = e.requested - 1;
                e.outcome = QStringLiteral("mismatch");
                e.message = QStringLiteral("read back another value");
            }
            r.verification.entries.append(e);
        }
        r.backups.append(
            {QStringLiteral("restore"), r.verification.sourceFile, r.verification.sourceChecksum, r.verification.when});
        r.alarms.append({QDateTime(QDate(2026, 11, 25), QTime(12, 10, 0), Qt::UTC), 12, QStringLiteral("Overcurrent"),
                         QStringLiteral("session"), true});
        r.linkHealth = {true, QStringLiteral("this session"), 6000, 5995, 3, 1, 2, 2, 1.2, 1.9, 14.5, 1};
        record.drives.append(r);
    }
    for (int k = 0; k < runs && drives > 0; ++k) {
        RunRecord run;
        run.title = QStringLiteral("Step response %1").arg(k + 1);
        run.file = QStringLiteral("run%1.ddrun").arg(k + 1);
        run.when = QDateTime(QDate(2026, 11, 25), QTime(13, 30 + k, 0), Qt::UTC);
        run.test = QStringLiteral("velocity-step");
        run.checksum = QStringLiteral("sha256:") + QString(64, QLatin1Char('0' + k % 10));
        run.metrics = {{QStringLiteral("overshoot"), QStringLiteral("Overshoot"), 4.5 + k, QStringLiteral("%"), {}},
                       {QStringLiteral("settlingTime2"),
                        QStringLiteral("Settling time (±2 %)"),
                        38.0 + k,
                        QStringLiteral("ms"),
                        {}},
                       {QStringLiteral("peakFollowingError"), QStringLiteral("Peak following error"), std::nullopt,
                        QString(), QStringLiteral("channel position-error was not captured")}};
        run.snapshot = {{QStringLiteral("P10"), QStringLiteral("Speed gain"), 120 + k, QString()},
                        {QStringLiteral("P11"), QStringLiteral("Integral time"), 25, QStringLiteral("ms")}};
        run.plot = fixturePlot(k);
        record.drives[k % drives].runs.append(run);
    }
    return record;
}

} // namespace dd::test
