#include "core/report/recordrenderer.h"

#include "core/drive/drivetypes.h"
#include "core/protocol/familytraits.h"
#include "core/report/recordfont.h"
#include "core/report/recordruns.h"

#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>
#include <algorithm>
#include <functional>

namespace dd {

namespace {

constexpr qreal BodyPointSize = 8.5;
constexpr int PlotWidthPx = 620; // CSS pixels (1/96 in): QTextDocument scales them to the device
const QMarginsF PageMarginsMm(15, 14, 15, 12);

QString esc(const QString &text)
{
    return text.toHtmlEscaped();
}

QString cell(const QString &text, const char *attributes = nullptr)
{
    return attributes ? QStringLiteral("<td %1>%2</td>").arg(QLatin1String(attributes), text)
                      : QStringLiteral("<td>%1</td>").arg(text);
}

QString numberText(const std::optional<qint64> &v)
{
    return v ? QString::number(*v) : QStringLiteral("—");
}

QString orDash(const QString &text)
{
    return text.isEmpty() ? QStringLiteral("—") : esc(text);
}

// A table whose first row is a <thead>: QTextDocument repeats it on every page it spans.
QString tableStart(const QStringList &headers)
{
    QString html = QStringLiteral(
        "<table class=\"grid\" width=\"100%\" cellspacing=\"0\" cellpadding=\"3\"><thead><tr>");
    for (const QString &h : headers)
        html += QStringLiteral("<th>%1</th>").arg(esc(h));
    return html + QStringLiteral("</tr></thead>");
}

// A long table as consecutive tables of at most ChunkRows rows, each with the header row and
// the same column widths (percent), so that they read as one. QTextDocument lays a table
// out in time that grows much faster than its rows (8 x 220 rows in one table each: ~5 s;
// in chunks: a fraction); a chunk that runs over a page break still repeats its header.
constexpr int ChunkRows = 30;

QString chunkedTable(const QStringList &headers, const QList<int> &widthsPercent, const QStringList &rows)
{
    QString head = QStringLiteral("<thead><tr>");
    for (int c = 0; c < headers.size(); ++c)
        head += QStringLiteral("<th width=\"%1%\">%2</th>").arg(widthsPercent.value(c)).arg(esc(headers.at(c)));
    head += QStringLiteral("</tr></thead>");
    QString html;
    for (int start = 0; start < rows.size(); start += ChunkRows) {
        html += QStringLiteral("<table class=\"grid\" width=\"100%\" cellspacing=\"0\" cellpadding=\"3\" "
                               "style=\"margin-top: 0px; margin-bottom: 0px\">")
            + head;
        for (int r = start; r < qMin(start + ChunkRows, int(rows.size())); ++r)
            html += rows.at(r);
        html += QStringLiteral("</table>");
    }
    return html;
}

const char *StyleSheet = "body { } h1 { font-size: 17pt; margin-bottom: 4px; } h2 { font-size: 13pt; margin-top: 0px; }"
                         " h3 { font-size: 10pt; margin-top: 12px; margin-bottom: 4px; }"
                         " table.grid { border-color: #888888; border-style: solid; border-width: 1px; }"
                         " table.grid th { background-color: #e4e8ee; text-align: left; }"
                         " table.form td { padding: 2px; } .label { color: #444444; }"
                         " .fail { color: #b00000; font-weight: bold; } .ok { color: #006000; font-weight: bold; }"
                         " .mono { font-family: 'DejaVu Sans Mono', monospace; } .note { color: #444444; }";

} // namespace

RecordRenderer::RecordRenderer(const CommissioningRecord &record, const QString &jsonSha256)
    : m_record(record)
    , m_sha256(jsonSha256)
{
}

QPageSize::PageSizeId RecordRenderer::defaultPageSize(const QLocale &locale)
{
    switch (locale.territory()) {
    case QLocale::UnitedStates:
    case QLocale::Canada:
    case QLocale::Mexico:
    case QLocale::Philippines:
    case QLocale::Chile:
    case QLocale::Colombia:
    case QLocale::Venezuela: return QPageSize::Letter;
    default: return QPageSize::A4;
    }
}

QString RecordRenderer::timeText(const QDateTime &t) const
{
    if (!t.isValid())
        return QStringLiteral("—");
    const QDateTime local = t.toLocalTime();
    return local.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) + QLatin1Char(' ')
        + (local.offsetFromUtc() == 0 ? QStringLiteral("UTC") : local.toString(QStringLiteral("t")));
}

QString RecordRenderer::driveTitle(const DriveRecord &drive) const
{
    return tr("%1 at address %2").arg(familyTraits(drive.family).displayName()).arg(drive.address);
}

QString RecordRenderer::verificationWarning(const DriveRecord &drive) const
{
    const RecordVerification &v = drive.verification;
    if (v.isEmpty() || v.passed())
        return QString();
    const QString what = v.kind == QLatin1String("restore") ? tr("restore") : tr("parameter write");
    return tr("VERIFICATION FAILED: %1 — the last %2 (%3): %4 of %5 parameter(s) not verified.")
        .arg(esc(driveTitle(drive)), what, timeText(v.when))
        .arg(v.failedCount())
        .arg(v.entries.size());
}

QString RecordRenderer::headerSection() const
{
    const RecordHeader &h = m_record.header;
    QString html = QStringLiteral("<h1>%1</h1>").arg(esc(tr("Commissioning record")));
    html += QStringLiteral("<table class=\"form\" cellspacing=\"0\" cellpadding=\"2\">");
    auto row = [&html](const QString &label, const QString &value) {
        html += QStringLiteral("<tr><td class=\"label\" width=\"190\">%1</td><td>%2</td></tr>").arg(esc(label), value);
    };
    row(tr("Machine / project"), orDash(h.machine));
    row(tr("Customer"), orDash(h.customer));
    row(tr("Site"), orDash(h.site));
    row(tr("Engineer"), orDash(h.engineer));
    row(tr("Date and time"), timeText(h.created));
    row(tr("DriveDesk version"), orDash(h.toolVersion));
    row(tr("Computer"), orDash(h.computer));
    row(tr("Record file (JSON) SHA-256"), QStringLiteral("<span class=\"mono\">%1</span>").arg(esc(m_sha256)));
    html += QStringLiteral("</table>");
    if (!h.notes.isEmpty())
        html += QStringLiteral("<p><span class=\"label\">%1</span><br/>%2</p>")
                    .arg(esc(tr("Notes")), esc(h.notes).replace(QLatin1Char('\n'), QLatin1String("<br/>")));
    return html;
}

QString RecordRenderer::summarySection() const
{
    QString html = QStringLiteral("<h3>%1</h3>").arg(esc(tr("Drives (%n)", nullptr, int(m_record.drives.size()))));
    if (m_record.drives.isEmpty())
        return html + QStringLiteral("<p>%1</p>").arg(esc(tr("No drive is in this record.")));
    for (const DriveRecord &d : m_record.drives) {
        const QString warning = verificationWarning(d);
        if (!warning.isEmpty())
            html += QStringLiteral("<p class=\"fail\">%1</p>").arg(warning);
    }
    html += tableStart(
        {tr("Drive"), tr("Firmware"), tr("Model"), tr("Link"), tr("Changed"), tr("Verification"), tr("Alarms")});
    for (const DriveRecord &d : m_record.drives) {
        QString verification;
        if (d.verification.isEmpty())
            verification = esc(tr("none recorded"));
        else if (d.verification.passed())
            verification = QStringLiteral("<span class=\"ok\">%1</span>").arg(esc(tr("verified")));
        else
            verification = QStringLiteral("<span class=\"fail\">%1</span>")
                               .arg(esc(tr("FAILED (%1)").arg(d.verification.failedCount())));
        html += QStringLiteral("<tr>") + cell(esc(driveTitle(d))) + cell(orDash(d.firmware)) + cell(orDash(d.model))
            + cell(orDash(d.link))
            + cell(d.withoutDefault() > 0
                       ? esc(tr("%1 (%2 not compared)").arg(d.nonDefault().size()).arg(d.withoutDefault()))
                       : QString::number(d.nonDefault().size()))
            + cell(verification) + cell(QString::number(d.alarms.size())) + QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</table>");
}

QString RecordRenderer::driveSection(const DriveRecord &d, int number) const
{
    QString html = QStringLiteral("<h2 style=\"page-break-before: always\">%1</h2>")
                       .arg(esc(tr("Drive %1 of %2: %3").arg(number).arg(m_record.drives.size()).arg(driveTitle(d))));
    const QString warning = verificationWarning(d);
    if (!warning.isEmpty())
        html += QStringLiteral("<p class=\"fail\">%1</p>").arg(warning);

    // Identity and link.
    QStringList settings;
    for (auto it = d.linkSettings.begin(); it != d.linkSettings.end(); ++it)
        settings << QStringLiteral("%1 = %2").arg(it.key(), it.value().toVariant().toString());
    html += QStringLiteral("<table class=\"form\" cellspacing=\"0\" cellpadding=\"2\">");
    auto row = [&html](const QString &label, const QString &value) {
        html += QStringLiteral("<tr><td class=\"label\" width=\"190\">%1</td><td>%2</td></tr>").arg(esc(label), value);
    };
    row(tr("Family"), esc(QStringLiteral("%1 (%2)").arg(familyTraits(d.family).displayName(), familyId(d.family))));
    row(tr("Address"), QString::number(d.address));
    row(tr("Firmware"), orDash(d.firmware));
    row(tr("Model"), orDash(d.model));
    row(tr("Link"), orDash(d.link));
    row(tr("Link settings"), orDash(settings.join(QLatin1String(", "))));
    row(tr("Journal identity"), orDash(d.identification));
    html += QStringLiteral("</table>");
    if (!d.journalError.isEmpty())
        html += QStringLiteral("<p class=\"fail\">%1</p>").arg(esc(d.journalError));
    if (!d.readError.isEmpty())
        html += QStringLiteral("<p class=\"fail\">%1</p>")
                    .arg(esc(tr("Parameters not (all) read: %1").arg(d.readError)));

    // Parameters that differ from the defaults.
    const QList<RecordParameter> changed = d.nonDefault();
    html += QStringLiteral("<h3>%1</h3>")
                .arg(esc(tr("Parameters that differ from the defaults (%n)", nullptr, int(changed.size()))));
    const int notCompared = d.withoutDefault();
    const int read = int(std::count_if(d.parameters.cbegin(), d.parameters.cend(),
                                       [](const RecordParameter &p) { return p.value.has_value(); }));
    if (changed.isEmpty() && read > 0 && notCompared == read) {
        html += QStringLiteral("<p class=\"fail\">%1</p>")
                    .arg(esc(tr("Not compared: the dictionary gives no factory default for any of the %n parameter(s) "
                                "read, so this record cannot say which of them were changed.",
                                nullptr, read)));
    } else if (changed.isEmpty()) {
        html += QStringLiteral("<p>%1</p>").arg(esc(tr("No parameter read differs from its default.")));
    } else {
        QStringList rows;
        for (const RecordParameter &p : changed)
            rows << QStringLiteral("<tr>") + cell(QString::number(p.index)) + cell(esc(p.key)) + cell(esc(p.name))
                    + cell(QStringLiteral("<b>%1</b>").arg(numberText(p.value))) + cell(numberText(p.defaultValue))
                    + cell(esc(p.unit)) + QStringLiteral("</tr>");
        html += chunkedTable({tr("Index"), tr("Parameter"), tr("Name"), tr("Value"), tr("Default"), tr("Unit")},
                             {8, 12, 42, 13, 13, 12}, rows);
    }
    if (notCompared > 0 && notCompared < read)
        html += QStringLiteral("<p class=\"note\">%1</p>")
                    .arg(esc(tr("%n parameter(s) not compared: the dictionary gives no factory default for them "
                                "(shown as “—” in the Default column of the appendix).",
                                nullptr, notCompared)));
    if (notCompared > 0)
        html += QStringLiteral("<p class=\"note\">%1</p>")
                    .arg(esc(tr("The protocol documents of this drive family list no factory defaults for these "
                                "parameters. A dictionary with the drive's factory settings (drivedesk-cli "
                                "--dictionary, or the user dictionary of the family) makes the comparison complete.")));
    html += QStringLiteral("<p class=\"note\">%1</p>")
                .arg(esc(tr("Every parameter with its value and default is listed in the appendix.")));

    // The last verification.
    html += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Last verification")));
    const RecordVerification &v = d.verification;
    if (v.isEmpty()) {
        html += QStringLiteral("<p>%1</p>").arg(esc(tr("No restore or parameter write of this drive is recorded.")));
    } else {
        const QString kind = v.kind == QLatin1String("restore") ? tr("Restore") : tr("Parameter write");
        QString line = tr("%1 on %2: ").arg(kind, timeText(v.when));
        // Write-only parameters are written, never read back: not "verified" (issue 27).
        const int notReadBack = int(std::count_if(v.entries.cbegin(), v.entries.cend(), [](const auto &e) {
            return e.outcome == QLatin1String("written-only");
        }));
        const QString passed = notReadBack == 0
            ? tr("%n parameter(s) written and verified.", nullptr, int(v.entries.size()))
            : tr("%1 parameter(s) written and verified, %2 written (not read back: write-only).")
                  .arg(v.entries.size() - notReadBack)
                  .arg(notReadBack);
        line = esc(line)
            + (v.passed()
                   ? QStringLiteral("<span class=\"ok\">%1</span>").arg(esc(passed))
                   : QStringLiteral("<span class=\"fail\">%1</span>")
                         .arg(esc(
                             tr("%1 of %2 parameter(s) NOT verified.").arg(v.failedCount()).arg(v.entries.size()))));
        html += QStringLiteral("<p>%1</p>").arg(line);
        if (!v.sourceFile.isEmpty())
            html += QStringLiteral("<p>%1 <span class=\"mono\">%2</span></p>")
                        .arg(esc(tr("From the backup file %1, checksum").arg(v.sourceFile)), esc(v.sourceChecksum));
        if (!v.entries.isEmpty()) {
            html += tableStart({tr("Parameter"), tr("Written"), tr("Read back"), tr("Result")});
            for (const RecordVerification::Entry &e : v.entries) {
                const QString result = e.isVerified()
                    ? QStringLiteral("<span class=\"ok\">%1</span>")
                          .arg(esc(e.outcome == QLatin1String("verified") ? tr("verified")
                                                                          : tr("written (not read back: write-only)")))
                    : QStringLiteral("<span class=\"fail\">%1</span> %2")
                          .arg(esc(tr("FAILED (%1)").arg(e.outcome)), esc(e.message));
                html += QStringLiteral("<tr>") + cell(esc(e.key)) + cell(QString::number(e.requested))
                    + cell(e.hasReadBack ? QString::number(e.readBack) : QStringLiteral("—")) + cell(result)
                    + QStringLiteral("</tr>");
            }
            html += QStringLiteral("</table>");
        }
    }

    const RecordEeOperation &ee = d.eeOperation;
    if (!ee.isEmpty())
        html += QStringLiteral("<p>%1 <span class=\"%2\">%3</span></p>")
                    .arg(esc(tr("Last EEPROM operation: %1 on %2:").arg(ee.operation, timeText(ee.when))),
                         ee.ok ? QStringLiteral("ok") : QStringLiteral("fail"),
                         esc(ee.ok ? tr("done.") : tr("FAILED: %1").arg(ee.message)));

    // Alarms.
    html += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Alarms")));
    if (d.alarms.isEmpty()) {
        html += QStringLiteral("<p>%1</p>").arg(esc(tr("No alarm was recorded.")));
    } else {
        html += tableStart({tr("Time"), tr("Code"), tr("Alarm"), tr("Seen")});
        for (const RecordAlarm &a : d.alarms) {
            const QString seen = a.source == QLatin1String("drive")
                ? tr("active when the record was made")
                : (a.cleared ? tr("cleared") : tr("in the session"));
            html += QStringLiteral("<tr>") + cell(timeText(a.when)) + cell(QString::number(a.code))
                + cell(orDash(a.text)) + cell(esc(seen)) + QStringLiteral("</tr>");
        }
        html += QStringLiteral("</table>");
    }

    // Link health.
    html += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Link health")));
    const RecordLinkHealth &h = d.linkHealth;
    if (!h.measured) {
        html += QStringLiteral("<p>%1</p>").arg(esc(tr("Not measured.")));
    } else {
        const QString turnaround = h.answered > 0
            ? tr("turnaround %1 / %2 / %3 ms (min / median / max)")
                  .arg(QString::number(h.turnaroundMinMs, 'f', 1), QString::number(h.turnaroundMedianMs, 'f', 1),
                       QString::number(h.turnaroundMaxMs, 'f', 1))
            : tr("no reply");
        html += QStringLiteral("<p>%1</p>")
                    .arg(esc(tr("%1: %2 request(s), %3 answered, %4; %5 timeout(s), %6 checksum error(s), %7 late or "
                                "duplicated reply(ies), %8 retries, %9 failed operation(s).")
                                 .arg(h.scope)
                                 .arg(h.requests)
                                 .arg(h.answered)
                                 .arg(turnaround)
                                 .arg(h.timeouts)
                                 .arg(h.checksumErrors)
                                 .arg(h.lateReplies)
                                 .arg(h.retries)
                                 .arg(h.errors)));
        if (h.busyLineSends > 0)
            html += QStringLiteral("<p>%1</p>")
                        .arg(esc(tr("%n request(s) went out on a line that was never quiet: another master on the bus, "
                                    "or a drive sending on its own.",
                                    nullptr, h.busyLineSends)));
    }

    // Tuning runs.
    if (!d.runs.isEmpty()) {
        html += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Tuning runs (%n)", nullptr, int(d.runs.size()))));
        for (int r = 0; r < d.runs.size(); ++r) {
            const RunRecord &run = d.runs.at(r);
            html += QStringLiteral("<p><b>%1</b> — %2, %3</p>")
                        .arg(esc(run.title), esc(RecordRuns::testName(run.test)), esc(timeText(run.when)));
            QString sampling = tr("%n sample(s), one every %1 ms on average", nullptr, run.samples)
                                   .arg(QString::number(run.meanIntervalMs, 'f', 2));
            if (run.gaps > 0)
                sampling += QStringLiteral("; ")
                    + tr("%n gap(s) in the sampling, the longest %1 ms (the plot breaks its lines at those it can "
                         "show)",
                         nullptr, run.gaps)
                          .arg(QString::number(run.longestGapMs, 'f', 1));
            html += QStringLiteral("<p class=\"note\">%1</p>").arg(esc(sampling));
            if (!run.file.isEmpty())
                html += QStringLiteral("<p class=\"note\">%1 <span class=\"mono\">%2</span></p>")
                            .arg(esc(tr("Run file %1, checksum").arg(run.file)), esc(run.checksum));
            if (!run.plot.isNull())
                html += QStringLiteral("<p><img src=\"run:%1/%2\" width=\"%3\" height=\"%4\"/></p>")
                            .arg(number)
                            .arg(r)
                            .arg(PlotWidthPx)
                            .arg(qRound(PlotWidthPx * double(run.plot.height()) / double(qMax(1, run.plot.width()))));
            if (!run.metrics.isEmpty()) {
                html += tableStart({tr("Metric"), tr("Value"), tr("Unit")});
                for (const RunRecord::Metric &m : run.metrics)
                    html += QStringLiteral("<tr>") + cell(esc(m.name))
                        + cell(m.value ? QString::number(*m.value, 'g', 4)
                                       : QStringLiteral("— <span class=\"note\">%1</span>")
                                             .arg(esc(tr("not measured: %1").arg(m.note))))
                        + cell(esc(channelUnitText(m.unit))) + QStringLiteral("</tr>");
                html += QStringLiteral("</table>");
            }
            if (!run.snapshot.isEmpty()) {
                html += QStringLiteral("<p class=\"note\">%1</p>").arg(esc(tr("Parameters during the run")));
                html += tableStart({tr("Parameter"), tr("Name"), tr("Value"), tr("Unit")});
                for (const RunRecord::SnapshotValue &s : run.snapshot)
                    html += QStringLiteral("<tr>") + cell(esc(s.key)) + cell(esc(s.name))
                        + cell(QString::number(s.value)) + cell(esc(s.unit)) + QStringLiteral("</tr>");
                html += QStringLiteral("</table>");
            }
        }
    }

    // Backup files.
    html += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Backup files")));
    if (d.backups.isEmpty()) {
        html += QStringLiteral("<p>%1</p>").arg(esc(tr("No backup file of this drive is recorded.")));
    } else {
        html += tableStart({tr("Role"), tr("File"), tr("Checksum"), tr("Time")});
        for (const BackupReference &b : d.backups)
            html += QStringLiteral("<tr>")
                + cell(esc(b.role == QLatin1String("restore") ? tr("restored onto the drive")
                                                              : tr("saved from the drive")))
                + cell(esc(b.path)) + cell(QStringLiteral("<span class=\"mono\">%1</span>").arg(esc(b.checksum)))
                + cell(timeText(b.when)) + QStringLiteral("</tr>");
        html += QStringLiteral("</table>");
    }
    return html;
}

QString RecordRenderer::appendixSection() const
{
    QString html;
    for (int i = 0; i < m_record.drives.size(); ++i) {
        const DriveRecord &d = m_record.drives.at(i);
        html += QStringLiteral("<h2 style=\"page-break-before: always\">%1</h2>")
                    .arg(esc(tr("Appendix %1: every parameter of %2").arg(i + 1).arg(driveTitle(d))));
        if (d.parameters.isEmpty()) {
            html += QStringLiteral("<p>%1</p>").arg(esc(tr("No parameter was read.")));
            continue;
        }
        QStringList rows;
        rows.reserve(d.parameters.size());
        for (const RecordParameter &p : d.parameters)
            rows << QStringLiteral("<tr>") + cell(QString::number(p.index)) + cell(esc(p.key)) + cell(esc(p.name))
                    + cell(numberText(p.value)) + cell(numberText(p.defaultValue)) + cell(esc(p.unit))
                    + cell(p.differsFromDefault() ? QStringLiteral("<b>*</b>") : QString()) + QStringLiteral("</tr>");
        html += chunkedTable(
            {tr("Index"), tr("Parameter"), tr("Name"), tr("Value"), tr("Default"), tr("Unit"), tr("Changed")},
            {8, 12, 38, 12, 12, 10, 8}, rows);
    }
    return html;
}

QString RecordRenderer::html() const
{
    QString html = QStringLiteral("<html><body>") + headerSection() + summarySection();
    for (int i = 0; i < m_record.drives.size(); ++i)
        html += driveSection(m_record.drives.at(i), i + 1);
    html += appendixSection();
    return html + QStringLiteral("</body></html>");
}

void RecordRenderer::fillDocument(QTextDocument *doc) const
{
    doc->setDefaultFont(RecordFont::font(m_record.locale, BodyPointSize));
    doc->setDefaultStyleSheet(QLatin1String(StyleSheet));
    doc->setDocumentMargin(0);
    for (int i = 0; i < m_record.drives.size(); ++i) {
        const QList<RunRecord> &runs = m_record.drives.at(i).runs;
        for (int r = 0; r < runs.size(); ++r)
            if (!runs.at(r).plot.isNull())
                doc->addResource(QTextDocument::ImageResource, QUrl(QStringLiteral("run:%1/%2").arg(i + 1).arg(r)),
                                 runs.at(r).plot);
    }
    doc->setHtml(html());
}

namespace {

// Lays `doc` out in pages of `body` (device pixels) less a footer, and paints each page with
// beginPage(i), which returns a painter whose origin is the top left of the page's body.
int paintPages(QTextDocument *doc, QPaintDevice *device, const QSizeF &body, const QFont &font,
               const std::function<QPainter *(int page)> &beginPage, const std::function<void(int page)> &endPage,
               const std::function<QStringList(int page, int pages)> &footer)
{
    doc->documentLayout()->setPaintDevice(device);
    const QFontMetricsF fm(font, device);
    const qreal footerHeight = fm.lineSpacing() * 2.6;
    const QSizeF pageSize(body.width(), body.height() - footerHeight);
    doc->setPageSize(pageSize);
    const int pages = doc->pageCount();
    for (int i = 0; i < pages; ++i) {
        QPainter *p = beginPage(i);
        if (!p)
            return -1;
        p->save();
        p->translate(0, -pageSize.height() * i);
        // Half a device pixel in from either edge: the layout draws a block that merely touches
        // the clip (a block pushed to the next page starts exactly at its top), and a PDF
        // keeps clipped text in the page, where text extraction finds it.
        const QRectF clip(0, pageSize.height() * i + 0.5, pageSize.width(), pageSize.height() - 1.0);
        p->setClipRect(clip);
        doc->drawContents(p, clip);
        p->restore();
        p->save();
        p->setFont(font);
        p->setPen(QColor(0x44, 0x44, 0x44));
        const QStringList lines = footer(i, pages);
        const qreal top = pageSize.height() + fm.lineSpacing() * 0.5;
        p->drawLine(QPointF(0, top), QPointF(body.width(), top));
        const QRectF line1(0, top + fm.lineSpacing() * 0.3, body.width(), fm.lineSpacing());
        p->drawText(line1, Qt::AlignLeft | Qt::AlignVCenter, lines.value(0));
        p->drawText(line1, Qt::AlignRight | Qt::AlignVCenter, lines.value(1));
        p->drawText(line1.translated(0, fm.lineSpacing()), Qt::AlignLeft | Qt::AlignVCenter, lines.value(2));
        p->restore();
        endPage(i);
    }
    return pages;
}

} // namespace

Error RecordRenderer::renderPdf(QByteArray *pdf, int *pageCount) const
{
    QBuffer buffer(pdf);
    buffer.open(QIODevice::WriteOnly);
    QPdfWriter writer(&buffer);
    writer.setPageSize(QPageSize(m_pageSize));
    writer.setPageMargins(PageMarginsMm, QPageLayout::Millimeter);
    writer.setResolution(300);
    writer.setCreator(QStringLiteral("DriveDesk %1").arg(QStringLiteral(DRIVEDESK_VERSION)));
    writer.setTitle(
        tr("Commissioning record")
        + (m_record.header.machine.isEmpty() ? QString() : QStringLiteral(" — ") + m_record.header.machine));
    QPainter painter;
    QTextDocument doc;
    fillDocument(&doc);
    const QFont footerFont = RecordFont::font(m_record.locale, 7.5);
    const QRectF body = writer.pageLayout().paintRectPixels(writer.resolution());
    const int pages = paintPages(
        &doc, &writer, body.size(), footerFont,
        [&](int page) -> QPainter * {
            if (page == 0)
                return painter.begin(&writer) ? &painter : nullptr;
            return writer.newPage() ? &painter : nullptr;
        },
        [](int) {},
        [this](int page, int pages) {
            return QStringList{
                tr("DriveDesk commissioning record")
                    + (m_record.header.machine.isEmpty() ? QString() : QStringLiteral(" — ") + m_record.header.machine),
                tr("Page %1 of %2").arg(page + 1).arg(pages), tr("Record file (JSON) SHA-256: %1").arg(m_sha256)};
        });
    if (painter.isActive())
        painter.end();
    if (pages < 0)
        return {ErrorCode::FileError, tr("Could not draw the record's pages.")};
    if (pageCount)
        *pageCount = pages;
    return {};
}

Error RecordRenderer::writePdf(const QString &path, int *pageCount) const
{
    QByteArray pdf;
    if (Error e = renderPdf(&pdf, pageCount))
        return e;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(pdf) != pdf.size() || !file.commit())
        return {ErrorCode::FileError, tr("Cannot write %1: %2").arg(path, file.errorString())};
    return {};
}

QList<QImage> RecordRenderer::renderImages(int dpi, int maxPages) const
{
    const QPageLayout layout(QPageSize(m_pageSize), QPageLayout::Portrait, PageMarginsMm, QPageLayout::Millimeter);
    const QRect full = layout.fullRectPixels(dpi);
    const QRect body = layout.paintRectPixels(dpi);
    const int dpm = qRound(dpi / 0.0254);
    auto blank = [&] {
        QImage image(full.size(), QImage::Format_RGB32);
        image.setDotsPerMeterX(dpm);
        image.setDotsPerMeterY(dpm);
        image.fill(Qt::white);
        return image;
    };
    QImage layoutDevice = blank();
    QTextDocument doc;
    fillDocument(&doc);
    QList<QImage> images;
    QImage current;
    QPainter painter;
    const QFont footerFont = RecordFont::font(m_record.locale, 7.5);
    paintPages(
        &doc, &layoutDevice, body.size(), footerFont,
        [&](int page) -> QPainter * {
            if (page >= maxPages)
                return nullptr;
            current = blank();
            painter.begin(&current);
            painter.translate(body.topLeft());
            return &painter;
        },
        [&](int) {
            painter.end();
            images.append(current);
        },
        [this](int page, int pages) {
            return QStringList{tr("DriveDesk commissioning record"), tr("Page %1 of %2").arg(page + 1).arg(pages),
                               tr("Record file (JSON) SHA-256: %1").arg(m_sha256)};
        });
    return images;
}

} // namespace dd
