#pragma once

#include "ui/bus/etaestimator.h"

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace dd {

// The inline scan progress under the bus tree: what is being done, a progress bar, the
// estimated time left, how many drives were found, and Cancel. Hidden when idle. Inline
// rather than a modal dialog, so the STOP button and the tree stay usable during a scan.
class ScanProgressWidget : public QWidget
{
    Q_OBJECT
public:
    explicit ScanProgressWidget(QWidget *parent = nullptr);

    void begin(const QString &what);
    void setStage(const QString &what);
    void setProgress(int done, int total);
    void setFound(int count);
    void finish();

    QString stageText() const;
    QString etaText() const;

signals:
    void cancelRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void updateEta();

    QLabel *m_stage = nullptr;
    QProgressBar *m_bar = nullptr;
    QLabel *m_eta = nullptr;
    QPushButton *m_cancel = nullptr;
    EtaEstimator m_estimator;
    int m_found = 0;
};

} // namespace dd
