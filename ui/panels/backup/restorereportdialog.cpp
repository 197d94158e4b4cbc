#include "ui/panels/backup/restorereportdialog.h"

#include "core/params/parameterdictionary.h"

#include <QColor>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

RestoreReportDialog::RestoreReportDialog(const RestoreReport &report, const ParameterDictionary &dictionary,
                                         const QString &fileName, QWidget *parent)
    : QDialog(parent)
    , m_report(report)
{
    setObjectName(QStringLiteral("restoreReportDialog"));
    setWindowTitle(tr("Restore report"));

    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("restoreSummary"));
    m_summary->setWordWrap(true);
    m_summary->setText(tr("Restore of %1:").arg(fileName) + QLatin1Char(' ') + summary());
    m_summary->setStyleSheet(report.isComplete() ? QStringLiteral("color: #2e7d32;")
                                                 : QStringLiteral("color: #c62828;"));

    m_table = new QTableWidget(int(report.selected.size()), 5, this);
    m_table->setObjectName(QStringLiteral("restoreReportTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("In the file"), tr("Read back"), tr("Outcome"), tr("Detail")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    for (int row = 0; row < report.selected.size(); ++row) {
        const DiffEntry &e = report.selected.at(row);
        const RestoreReport::Outcome outcome = report.outcome(e.index);
        const ParameterWriteResult *r = report.result(e.index);
        auto *name = new QTableWidgetItem(dictionary.label(e.index));
        name->setData(Qt::UserRole, e.index);
        m_table->setItem(row, 0, name);
        m_table->setItem(row, 1, new QTableWidgetItem(e.fileValue ? QString::number(*e.fileValue) : QString()));
        QString readBack = QStringLiteral("—");
        if (r && r->written && !r->readBackFailed)
            readBack = r->readable ? QString::number(r->readBack) : tr("not readable");
        m_table->setItem(row, 2, new QTableWidgetItem(readBack));
        auto *outcomeItem = new QTableWidgetItem(outcomeText(outcome));
        outcomeItem->setData(Qt::UserRole, RestoreReport::outcomeId(outcome));
        const bool good = outcome == RestoreReport::Outcome::Verified || outcome == RestoreReport::Outcome::WrittenOnly;
        outcomeItem->setForeground(good ? QColor(0x2e, 0x7d, 0x32) : QColor(0xc6, 0x28, 0x28));
        m_table->setItem(row, 3, outcomeItem);
        m_table->setItem(row, 4, new QTableWidgetItem(r ? r->error : QString()));
    }
    m_table->resizeColumnsToContents();

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    resize(640, 360);
}

QString RestoreReportDialog::summaryOf(const RestoreReport &report)
{
    using O = RestoreReport::Outcome;
    const int failed = int(report.indices(O::Failed).size() + report.indices(O::Mismatch).size());
    QString text = tr("%1 selected: %2 written, %3 verified, %4 failed, %5 not attempted.")
                       .arg(report.selected.size())
                       .arg(report.written().size())
                       .arg(report.indices(O::Verified).size())
                       .arg(failed)
                       .arg(report.indices(O::NotAttempted).size());
    if (const int unconfirmed = int(report.indices(O::Unconfirmed).size()))
        text += QLatin1Char(' ')
            + tr("%n parameter(s) could not be read back: what the drive holds is unknown; "
                 "compare again.",
                 nullptr, unconfirmed);
    if (const int writeOnly = int(report.indices(O::WrittenOnly).size()))
        text += QLatin1Char(' ')
            + tr("%n write-only parameter(s) written; the drive cannot report them back.", nullptr, writeOnly);
    return text;
}

QString RestoreReportDialog::outcomeText(RestoreReport::Outcome outcome)
{
    switch (outcome) {
    case RestoreReport::Outcome::Verified: return tr("written, verified");
    case RestoreReport::Outcome::WrittenOnly: return tr("written (cannot be read back)");
    case RestoreReport::Outcome::Mismatch: return tr("written, but the drive reads back another value");
    case RestoreReport::Outcome::Failed: return tr("failed: the drive did not accept it");
    case RestoreReport::Outcome::NotAttempted: return tr("not attempted");
    case RestoreReport::Outcome::Unconfirmed: return tr("unknown: no answer to the read-back");
    }
    return {};
}

} // namespace dd
