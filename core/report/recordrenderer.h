#pragma once

#include "core/common/error.h"
#include "core/report/commissioningrecord.h"

#include <QCoreApplication>
#include <QImage>
#include <QPageSize>
#include <QString>

class QTextDocument;

namespace dd {

// Sets a CommissioningRecord as a paged document with Qt Gui's QTextDocument and writes it
// with QPdfWriter: the header and a summary of every drive on the first page (a drive whose
// last verification failed is named there), one section per drive (identity, link, the
// parameters that differ from the dictionary's defaults, the last verification, alarms, link
// health, tuning runs, backup files), then the appendix with every parameter. Tables that run
// over a page break repeat their header row; every page carries "page i of n" and the
// SHA-256 of the record's JSON. Needs a QGuiApplication (fonts); no widgets.
class RecordRenderer
{
    Q_DECLARE_TR_FUNCTIONS(dd::RecordRenderer)
public:
    RecordRenderer(const CommissioningRecord &record, const QString &jsonSha256);

    void setPageSize(QPageSize::PageSizeId id) { m_pageSize = id; }
    QPageSize::PageSizeId pageSize() const { return m_pageSize; }

    // Writes the PDF (atomically: the file appears complete or not at all).
    Error writePdf(const QString &path, int *pageCount = nullptr) const;
    // The PDF's bytes.
    Error renderPdf(QByteArray *pdf, int *pageCount = nullptr) const;
    // Pages drawn as images at `dpi` (a preview); at most maxPages.
    QList<QImage> renderImages(int dpi, int maxPages) const;

    // The document body as HTML (lengths in CSS pixels; QTextDocument scales them to the device).
    QString html() const;
    // The page size for a locale: Letter where it is the custom (US, Canada, Mexico, ...), A4 elsewhere.
    static QPageSize::PageSizeId defaultPageSize(const QLocale &locale);

private:
    void fillDocument(QTextDocument *doc) const;
    QString headerSection() const;
    QString summarySection() const;
    QString driveSection(const DriveRecord &drive, int number) const;
    QString appendixSection() const;
    QString driveTitle(const DriveRecord &drive) const;
    QString verificationWarning(const DriveRecord &drive) const;
    QString timeText(const QDateTime &t) const;

    CommissioningRecord m_record;
    QString m_sha256;
    QPageSize::PageSizeId m_pageSize = QPageSize::A4;
};

} // namespace dd
