#include "cli/reportcommand.h"

#include "cli/clijournal.h"
#include "cli/clivalues.h"
#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h" // driveconnection.h needs it complete (QPointer)
#include "core/protocol/familytraits.h"
#include "core/report/commissioningrecord.h"
#include "core/report/linkhealthcounter.h"
#include "core/report/recordcollector.h"
#include "core/report/recordfont.h"
#include "core/report/recordjson.h"
#include "core/report/recordrenderer.h"
#include "core/report/recordruns.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QSaveFile>

namespace dd {

bool ReportCommand::checkOutputPath(const QString &option, const QString &path, const QString &suffix, QString *error)
{
    const QFileInfo info(path);
    if (info.isDir()) {
        *error = tr("report %1: %2 is a folder; give a file name.").arg(option, path);
        return false;
    }
    if (!info.absoluteDir().exists()) {
        *error = tr("report %1: the folder %2 does not exist.").arg(option, info.absolutePath());
        return false;
    }
    if (info.suffix().compare(suffix, Qt::CaseInsensitive) != 0) {
        *error = tr("report %1: %2 should end in .%3.").arg(option, path, suffix);
        return false;
    }
    return true;
}

bool ReportCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 0, 0, QString(), error))
        return false;
    m_pdfPath = inv.value(QStringLiteral("output"));
    if (m_pdfPath.isEmpty()) {
        *error = tr("report needs the PDF file to write: report -o RECORD.pdf.");
        return false;
    }
    if (!checkOutputPath(QStringLiteral("-o"), m_pdfPath, QStringLiteral("pdf"), error))
        return false;
    if (inv.has(QStringLiteral("json-out"))) {
        m_jsonPath = inv.value(QStringLiteral("json-out"));
        if (!checkOutputPath(QStringLiteral("--json-out"), m_jsonPath, QStringLiteral("json"), error))
            return false;
        if (QFileInfo(m_jsonPath).absoluteFilePath() == QFileInfo(m_pdfPath).absoluteFilePath()) {
            *error = tr("report: the PDF and the JSON file must be two different files.");
            return false;
        }
    }
    if (inv.has(QStringLiteral("runs")) && !loadRuns(inv.value(QStringLiteral("runs")), error))
        return false;
    if (inv.has(QStringLiteral("header"))) {
        if (Error e = m_header.load(inv.value(QStringLiteral("header")))) {
            *error = tr("report --header: %1").arg(e.message);
            return false;
        }
    }
    m_pageSize = RecordRenderer::defaultPageSize(QLocale::system()); // the region's paper, not the language's
    if (inv.has(QStringLiteral("page-size"))) {
        const QString size = inv.value(QStringLiteral("page-size")).toLower();
        if (size == QLatin1String("a4")) {
            m_pageSize = QPageSize::A4;
        } else if (size == QLatin1String("letter")) {
            m_pageSize = QPageSize::Letter;
        } else {
            *error = tr("report --page-size: \"%1\" is not a page size; use a4 or letter.")
                         .arg(inv.value(QStringLiteral("page-size")));
            return false;
        }
    }
    for (const RecordRunFile &r : std::as_const(m_runs)) {
        const auto family = familyFromId(r.run.family);
        if (!family || *family != context()->globals.connection.family) {
            *error = tr("report --runs: %1 was taken on a %2 drive; this link is of the %3 family.")
                         .arg(QFileInfo(r.path).fileName(), r.run.family,
                              familyId(context()->globals.connection.family));
            return false;
        }
    }
    m_all = inv.has(QStringLiteral("all"));
    if ((inv.has(QStringLiteral("from")) || inv.has(QStringLiteral("to"))) && !m_all) {
        *error = tr("report: --from and --to limit the scan of --all; without --all the record is of --address.");
        return false;
    }
    if (m_all) {
        const AddressRange range = context()->globals.addressRange();
        m_scan.from = range.first;
        m_scan.to = range.last;
        for (const char *name : {"from", "to"}) {
            const QString option = QLatin1String(name);
            if (!inv.has(option))
                continue;
            const auto v = CliValues::integer(inv.value(option), range.first, range.last, QStringLiteral("--") + option,
                                              error);
            if (!v)
                return false;
            (option == QLatin1String("from") ? m_scan.from : m_scan.to) = int(*v);
        }
        if (m_scan.from > m_scan.to) {
            *error = tr("report: --from %1 is above --to %2.").arg(m_scan.from).arg(m_scan.to);
            return false;
        }
        if (context()->globals.connection.timeoutMs > 0)
            m_scan.timeoutMs = context()->globals.connection.timeoutMs;
    } else {
        m_addresses = {context()->globals.address};
        // Without --all the record holds one drive: a run of another is refused before anything is sent.
        for (const RecordRunFile &r : std::as_const(m_runs)) {
            if (r.run.address != context()->globals.address) {
                *error = tr("report --runs: %1 was taken on the drive at address %2; this record is of address %3.")
                             .arg(QFileInfo(r.path).fileName())
                             .arg(r.run.address)
                             .arg(context()->globals.address);
                return false;
            }
        }
    }
    return true;
}

bool ReportCommand::loadRuns(const QString &list, QString *error)
{
    const QStringList paths = list.split(QLatin1Char(','));
    for (const QString &path : paths) {
        if (path.trimmed().isEmpty()) {
            *error = tr("report --runs: \"%1\" has an empty file name; give RUN.ddrun,RUN2.ddrun,...").arg(list);
            return false;
        }
    }
    for (const QString &path : paths) {
        RecordRunFile file;
        if (Error e = RecordRuns::load(path.trimmed(), &file)) {
            *error = tr("report --runs: %1").arg(e.message);
            return false;
        }
        for (const RecordRunFile &other : std::as_const(m_runs))
            if (other.path == file.path) {
                *error = tr("report --runs: %1 is listed twice.").arg(path.trimmed());
                return false;
            }
        m_runs.append(file);
    }
    return true;
}

void ReportCommand::start()
{
    const ConnectionSettings &settings = context()->connection->settings();
    m_health = new LinkHealthCounter(context()->connection->tap(), settings.isCan() ? 0 : settings.baud, this);
    m_collector = new RecordCollector(QLocale(), this);
    m_collector->setJournal(&m_journal, CliJournal::link(context()->globals), context()->globals.machine);
    connect(m_collector, &RecordCollector::operationFailed, m_health, [this] {
        if (!m_addresses.isEmpty())
            m_health->countError(m_addresses.first());
    });
    connect(m_collector, &RecordCollector::finished, this, [this](const Error &error) {
        const int address = m_addresses.takeFirst();
        if (error) {
            // --all: a drive found by the scan that then does not answer is named, not fatal.
            if (!m_all)
                return fail(error);
            m_skipped << tr("address %1: %2").arg(address).arg(error.message);
            m_unreadable << address;
            out()->note(tr("Drive %1 left out of the record: %2").arg(address).arg(error.message));
        } else {
            m_drives.append(m_collector->record());
        }
        collectNext();
    });
    if (RecordFont::needsCjk(QLocale()) && RecordFont::cjkFamily().isEmpty())
        out()->note(tr("No Chinese font is installed: Chinese text cannot be drawn in the PDF. Install one "
                       "(Debian: apt install fonts-noto-cjk)."));
    if (m_all)
        return startScan();
    collectNext();
}

void ReportCommand::startScan()
{
    m_discovery = context()->connection->createDiscovery(m_scan);
    if (!m_discovery)
        return fail({ErrorCode::NotSupported, tr("This family cannot scan.")});
    connect(m_discovery, &Discovery::found, this, [this](const DiscoveredDrive &d) {
        if (d.address >= m_scan.from && d.address <= m_scan.to && !m_addresses.contains(d.address))
            m_addresses.append(d.address);
    });
    connect(m_discovery, &Discovery::finished, this, [this](const Error &error) {
        if (error)
            return fail(error);
        if (m_addresses.isEmpty())
            return fail({ErrorCode::Timeout, tr("No drive answered the scan; there is nothing to record.")});
        std::sort(m_addresses.begin(), m_addresses.end());
        out()->note(tr("%n drive(s) found; reading them.", nullptr, int(m_addresses.size())));
        collectNext();
    });
    out()->note(tr("Scanning addresses %1 to %2 ...").arg(m_scan.from).arg(m_scan.to));
    m_discovery->start();
}

void ReportCommand::collectNext()
{
    if (m_addresses.isEmpty())
        return writeRecord();
    Drive *d = context()->connection->drive(m_addresses.first());
    if (!d)
        return fail({ErrorCode::InvalidArgument,
                     tr("There can be no drive at address %1 on this link.").arg(m_addresses.first())});
    if (context()->dictionary && d->dictionary() != context()->dictionary)
        d->setDictionary(context()->dictionary);
    m_collector->collect(d, RecordCollector::linkSettingsJson(context()->globals.connection));
}

void ReportCommand::writeRecord()
{
    if (m_drives.isEmpty())
        return fail({ErrorCode::Timeout, tr("No drive could be read; no record was written.")});
    CommissioningRecord record;
    record.locale = QLocale();
    record.header = m_header;
    if (record.header.machine.isEmpty())
        record.header.machine = context()->globals.machine;
    record.header.stamp();
    m_health->closeOutstanding(); // every read has finished: a request still out timed out
    for (DriveRecord &d : m_drives) {
        d.linkHealth = m_health->health(d.address, tr("while this record was made"));
        record.drives.append(d);
    }
    // Runs of a drive --all found but could not read are left out with it; a run of a drive
    // the scan did not find refuses the record.
    QList<RecordRunFile> runs;
    for (const RecordRunFile &r : std::as_const(m_runs)) {
        if (m_unreadable.contains(r.run.address)) {
            out()->note(tr("Run %1 left out: its drive (address %2) could not be read.")
                            .arg(QFileInfo(r.path).fileName())
                            .arg(r.run.address));
            m_skipped << tr("run %1: its drive could not be read").arg(QFileInfo(r.path).fileName());
            continue;
        }
        runs.append(r);
    }
    if (Error e = RecordRuns::attach(runs, &record.drives, record.locale))
        return fail(e, {}, CliExit::Usage);
    const QByteArray json = RecordJson::toJson(record);
    const QString sha = RecordJson::sha256(json);
    RecordRenderer renderer(record, sha);
    renderer.setPageSize(m_pageSize);
    int pages = 0;
    if (Error e = renderer.writePdf(m_pdfPath, &pages))
        return fail(e, {}, CliExit::DriveFailed);
    if (!m_jsonPath.isEmpty()) {
        QSaveFile file(m_jsonPath);
        if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size() || !file.commit())
            return fail({ErrorCode::FileError, tr("Cannot write %1: %2").arg(m_jsonPath, file.errorString())}, {},
                        CliExit::DriveFailed);
    }
    QJsonArray drives;
    int failed = 0;
    for (const DriveRecord &d : std::as_const(record.drives)) {
        drives.append(QJsonObject{{QStringLiteral("family"), familyId(d.family)},
                                  {QStringLiteral("address"), d.address},
                                  {QStringLiteral("firmware"), d.firmware},
                                  {QStringLiteral("nonDefault"), int(d.nonDefault().size())},
                                  {QStringLiteral("verification"),
                                   d.verification.isEmpty()      ? QStringLiteral("none")
                                       : d.verification.passed() ? QStringLiteral("verified")
                                                                 : QStringLiteral("failed")}});
        if (!d.verification.isEmpty() && !d.verification.passed())
            ++failed;
    }
    QString text = tr("Commissioning record of %n drive(s) written to %1 (%2 pages).", nullptr, int(drives.size()))
                       .arg(m_pdfPath)
                       .arg(pages);
    if (!m_jsonPath.isEmpty())
        text += QLatin1Char('\n') + tr("JSON: %1").arg(m_jsonPath);
    text += QLatin1Char('\n') + tr("SHA-256 of the JSON: %1").arg(sha);
    if (failed)
        text += QLatin1Char('\n')
            + tr("%n drive(s) failed their last verification; the record says so.", nullptr, failed);
    QJsonArray skipped;
    for (const QString &s : std::as_const(m_skipped))
        skipped.append(s);
    succeed({{QStringLiteral("file"), m_pdfPath},
             {QStringLiteral("json"), m_jsonPath},
             {QStringLiteral("sha256"), sha},
             {QStringLiteral("pages"), pages},
             {QStringLiteral("drives"), drives},
             {QStringLiteral("skipped"), skipped}},
            text);
}

} // namespace dd
