#pragma once

#include "core/drive/restorereport.h"

#include <QDialog>

class QLabel;
class QTableWidget;

namespace dd {

class ParameterDictionary;

// What a restore did, for the user: a summary (written, verified, failed, not attempted)
// and one row per selected parameter with the file's value, the value read back and the
// outcome. Shown by the Backup tab after every restore.
class RestoreReportDialog : public QDialog
{
    Q_OBJECT
public:
    RestoreReportDialog(const RestoreReport &report, const ParameterDictionary &dictionary, const QString &fileName,
                        QWidget *parent = nullptr);

    const RestoreReport &report() const { return m_report; }
    QString summary() const { return summaryOf(m_report); }
    // "N selected: … written, … verified, …" in the current language.
    static QString summaryOf(const RestoreReport &report);
    QTableWidget *table() const { return m_table; }

    // Translated outcome ("verified", "failed", ...).
    static QString outcomeText(RestoreReport::Outcome outcome);

private:
    RestoreReport m_report;
    QLabel *m_summary = nullptr;
    QTableWidget *m_table = nullptr;
};

} // namespace dd
