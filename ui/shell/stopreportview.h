#pragma once

#include <QDialog>

class QLabel;

namespace dd {

class StopReporter;

// The whole STOP report, drive by drive (StopReporter::details()), in a window of its own:
// the status bar cuts a long report at 1280 px. Not modal; follows the report as drives
// answer and after a language switch. Opened from the status bar's "STOP report" button.
class StopReportView : public QDialog
{
    Q_OBJECT
public:
    explicit StopReportView(StopReporter *reporter, QWidget *parent = nullptr);

    QString text() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();

    StopReporter *m_reporter = nullptr;
    QLabel *m_text = nullptr;
};

} // namespace dd
