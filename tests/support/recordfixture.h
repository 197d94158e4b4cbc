#pragma once

// A commissioning record made up for tests and the benchmark (header-only: only targets that
// link drivedesk_report include it).

#include "core/report/commissioningrecord.h"

#include <QPainter>
#include <QtMath>

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
        r.linkHealth = {true, QStringLiteral("this session"), 12000, 11990, 3, 2, 1};
        record.drives.append(r);
    }
    for (int k = 0; k < runs && drives > 0; ++k) {
        RunRecord run;
        run.title = QStringLiteral("Step response %1").arg(k + 1);
        run.file = QStringLiteral("run%1.ddrun").arg(k + 1);
        run.when = QDateTime(QDate(2026, 11, 25), QTime(13, 30 + k, 0), Qt::UTC);
        run.metrics = {{QStringLiteral("overshoot"), 4.5 + k, QStringLiteral("%")},
                       {QStringLiteral("settling time"), 38.0 + k, QStringLiteral("ms")}};
        run.snapshot = {{QStringLiteral("P10"), QStringLiteral("Speed gain"), 120 + k, QString()},
                        {QStringLiteral("P11"), QStringLiteral("Integral time"), 25, QStringLiteral("ms")}};
        run.plot = fixturePlot(k);
        record.drives[k % drives].runs.append(run);
    }
    return record;
}

} // namespace dd::test
