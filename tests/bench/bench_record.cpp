// The commissioning record's generation time and size (docs/performance.md, "Commissioning
// record"): 8 drives x 220 parameters with 4 tuning-run plots, JSON and PDF, A4 and Letter.
// Run: QT_QPA_PLATFORM=offscreen build/tests/bench/bench_record [drives] [parameters] [plots]
#include "core/report/recordjson.h"
#include "core/report/recordrenderer.h"
#include "tests/support/recordfixture.h"

#include <QElapsedTimer>
#include <QGuiApplication>
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
    const int plots = args.size() > 3 ? args.at(3).toInt() : 4;
    QTextStream out(stdout);
    out << "record: " << drives << " drives x " << parameters << " parameters, " << plots << " plots\n";

    // A warm-up (font database, first glyphs), then three timed runs per page size.
    const dd::CommissioningRecord record = dd::test::fixtureRecord(drives, parameters, 2, plots);
    {
        dd::RecordRenderer warm(dd::test::fixtureRecord(1, 5), QString());
        QByteArray pdf;
        warm.renderPdf(&pdf);
    }
    for (QPageSize::PageSizeId size : {QPageSize::A4, QPageSize::Letter}) {
        qint64 best = -1, worst = 0, cpuBest = -1;
        QByteArray pdf;
        QByteArray json;
        int pages = 0;
        for (int run = 0; run < 3; ++run) {
            QElapsedTimer t;
            t.start();
            const std::clock_t cpu0 = std::clock();
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
            best = best < 0 ? ms : qMin(best, ms);
            worst = qMax(worst, ms);
        }
        out << (size == QPageSize::A4 ? "A4    " : "Letter") << ": JSON + PDF in " << best
            << " ms (worst of 3: " << worst << " ms; CPU time " << cpuBest << " ms), " << pages << " pages, PDF "
            << QString::number(pdf.size() / 1024.0 / 1024.0, 'f', 2) << " MB, JSON "
            << QString::number(json.size() / 1024.0, 'f', 0) << " KB\n";
    }
    return 0;
}
