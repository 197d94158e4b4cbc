#pragma once

#include <QWidget>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QToolButton;

namespace dd {

// The tool row above a trend plot: record / stop, pause / resume the view, reset zoom,
// time window, sample rate and the export menu (CSV of the whole recording or the visible
// window, PNG, SVG). Only emits what the user asked for; TrendView and its owner act on it.
// Compact so that it fits the tab at 1280 px in either language.
class TrendControls : public QWidget
{
    Q_OBJECT
public:
    explicit TrendControls(QWidget *parent = nullptr);

    static QList<int> windowChoicesSeconds(); // 10, 30, 60, 120, 300, 600
    int windowSeconds() const;
    void setWindowSeconds(int seconds); // the nearest choice; emits windowChanged on change

    double sampleRate() const;
    void setSampleRate(double hz); // emits nothing

    void setPaused(bool paused);       // button state only; emits nothing
    void setZoomed(bool zoomed);       // enables "Reset zoom"
    void setRecording(bool recording); // button state only; emits nothing
    bool isRecording() const;

    QPushButton *pauseButton() const { return m_pauseButton; }
    QPushButton *recordButton() const { return m_recordButton; }
    QToolButton *exportButton() const { return m_exportButton; }

signals:
    void recordToggled(bool recording);
    void pauseToggled(bool paused);
    void resetZoomClicked();
    void windowChanged(int seconds);
    void sampleRateChanged(double hz);
    void exportCsvRequested(bool wholeRecording);
    void exportPngRequested();
    void exportSvgRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();

    QPushButton *m_recordButton;
    QPushButton *m_pauseButton;
    QPushButton *m_resetZoomButton;
    QLabel *m_windowLabel;
    QComboBox *m_windowCombo;
    QLabel *m_rateLabel;
    QDoubleSpinBox *m_rateSpin;
    QToolButton *m_exportButton;
    QAction *m_exportAllAction;
    QAction *m_exportWindowAction;
    QAction *m_exportPngAction;
    QAction *m_exportSvgAction;
};

} // namespace dd
