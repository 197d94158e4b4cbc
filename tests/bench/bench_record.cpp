// The commissioning record's generation time and size (docs/performance.md, "Commissioning
// record"): 8 drives x 220 parameters with 4 tuning runs, JSON and PDF, A4 and Letter. The
// runs are run files (.ddrun) as a step test writes them — 4 channels, 1 ms samples, 0.5 s —
// loaded, drawn and attached as `report --runs` does it, inside the timed part. Real captures
// can be given instead: they must be of servo-can drives at addresses 1..drives.
// Run: QT_QPA_PLATFORM=offscreen build/tests/bench/bench_record [drives] [parameters] [runs] [RUN.ddrun ...]
#include "core/report/recordjson.h"
#include "core/report/recordrenderer.h"
#include "core/report/recordruns.h"
#include "tests/support/recordfixture.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QTemporaryDir>
#include <QTextStream>

#include <ctime>

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    const QStringList args = app.arguments();
    const int drives = args.size() > 1 ? args.at(1).toInt() : 8;
    const int parameters = args.size() > 2 ? args.at(2).toInt() : 220;
    const int runCount = args.size() > 3 ? args.at(3).toInt() : 4;
    QTextStream out(stdout);

    // The run files: given, or written here (fixtureRun: drive k + 1, a different gain each).
    QTemporaryDir dir;
    QStringList runPaths = args.mid(4);
    if (runPaths.isEmpty()) {
        for (int k = 0; k < runCount; ++k) {
            const QString path = dir.filePath(QStringLiteral("axis%1-step.ddrun").arg(k % drives + 1));
            if (dd::Error e = dd::test::fixtureRun(k % drives + 1, 500.0, 1.0, 30 + 5 * k).save(path)) {
                out << "failed: " << e.message << "\n";
                return 1;
            }
            runPaths << path;
        }
    }
    qint64 runBytes = 0;
    for (const QString &p : std::as_const(runPaths))
        runBytes += QFileInfo(p).size();
    out << "record: " << drives << " drives x " << parameters << " parameters, " << runPaths.size() << " run files ("
        << QString::number(runBytes / 1024.0, 'f', 0) << " KB)\n";

    // A warm-up (font database, first glyphs), then three timed runs per page size.
    const dd::CommissioningRecord base = dd::test::fixtureRecord(drives, parameters, 2);
    {
        dd::RecordRenderer warm(dd::test::fixtureRecord(1, 5), QString());
        QByteArray pdf;
        warm.renderPdf(&pdf);
    }
    for (QPageSize::PageSizeId size : {QPageSize::A4, QPageSize::Letter}) {
        qint64 best = -1, worst = 0, cpuBest = -1, runsBest = -1;
        QByteArray pdf;
        QByteArray json;
        int pages = 0;
        for (int run = 0; run < 3; ++run) {
            QElapsedTimer t;
            t.start();
            const std::clock_t cpu0 = std::clock();
            dd::CommissioningRecord record = base;
            QList<dd::RecordRunFile> files;
            for (const QString &p : std::as_const(runPaths)) {
                dd::RecordRunFile f;
                if (dd::Error e = dd::RecordRuns::load(p, &f)) {
                    out << "failed: " << e.message << "\n";
                    return 1;
                }
                files << f;
            }
            if (dd::Error e = dd::RecordRuns::attach(files, &record.drives, record.locale)) {
                out << "failed: " << e.message << "\n";
                return 1;
            }
            const qint64 runsMs = t.elapsed();
            json = dd::RecordJson::toJson(record);
            const QString sha = dd::RecordJson::sha256(json);
            dd::RecordRenderer renderer(record, sha);
            renderer.setPageSize(size);
            pdf.clear();
            if (dd::Error e = renderer.renderPdf(&pdf, &pages)) {
                out << "failed: " << e.message << "\n";
                return 1;
            }
            const qint64 ms = t.elapsed();
            const qint64 cpuMs = qint64((std::clock() - cpu0) * 1000.0 / CLOCKS_PER_SEC);
            cpuBest = cpuBest < 0 ? cpuMs : qMin(cpuBest, cpuMs);
            runsBest = runsBest < 0 ? runsMs : qMin(runsBest, runsMs);
            best = best < 0 ? ms : qMin(best, ms);
            worst = qMax(worst, ms);
        }
        out << (size == QPageSize::A4 ? "A4    " : "Letter") << ": runs + JSON + PDF in " << best
            << " ms (worst of 3: " << worst << " ms; CPU time " << cpuBest << " ms; loading and drawing the runs "
            << runsBest << " ms), " << pages << " pages, PDF " << QString::number(pdf.size() / 1024.0 / 1024.0, 'f', 2)
            << " MB, JSON " << QString::number(json.size() / 1024.0, 'f', 0) << " KB\n";
    }
    return 0;
}
