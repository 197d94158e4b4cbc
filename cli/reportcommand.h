#pragma once

#include "cli/clicommand.h"

#include "core/drive/discovery.h"
#include "core/report/driverecord.h"
#include "core/report/recordheader.h"
#include "core/report/recordruns.h"
#include "core/report/verificationjournal.h"

#include <QPageSize>

// report -o RECORD.pdf [--all [--from A] [--to B]] [--runs RUN.ddrun,...] [--header FILE.json]
//        [--json-out RECORD.json] [--page-size a4|letter]: the commissioning record
// (docs/record.md) of the drive at --address, or with --all of every drive a scan of the
// link finds.

namespace dd {

class LinkHealthCounter;
class RecordCollector;

class ReportCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit ReportCommand(CliContext *c)
        : CliCommand(QStringLiteral("report"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    bool needsDrive() const override { return !m_all; }
    bool identifyFirst() const override { return false; }
    void start() override;

private:
    bool loadRuns(const QString &list, QString *error);
    static bool checkOutputPath(const QString &option, const QString &path, const QString &suffix, QString *error);
    void startScan();
    void collectNext();
    void writeRecord();

    QString m_pdfPath;
    QString m_jsonPath;
    bool m_all = false;
    QPageSize::PageSizeId m_pageSize = QPageSize::A4;
    RecordHeader m_header;
    ScanOptions m_scan;
    QList<int> m_addresses;
    QList<DriveRecord> m_drives;
    QStringList m_skipped;
    QList<int> m_unreadable;
    QList<RecordRunFile> m_runs;
    VerificationJournal m_journal;
    LinkHealthCounter *m_health = nullptr;
    RecordCollector *m_collector = nullptr;
    Discovery *m_discovery = nullptr;
};

} // namespace dd
