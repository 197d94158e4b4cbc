#pragma once

#include <QWidget>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QToolButton;

namespace dd {

// The tool row above a trend plot: pause/resume, reset zoom, time window, sample rate and
// the export buttons. Only emits what the user asked for; TrendView acts on it.
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

    void setPaused(bool paused); // button state only; emits nothing
    void setZoomed(bool zoomed); // enables "Reset zoom"

    QPushButton *pauseButton() const { return m_pauseButton; }

signals:
    void pauseToggled(bool paused);
    void resetZoomClicked();
    void windowChanged(int seconds);
    void sampleRateChanged(double hz);
    void exportCsvRequested(bool wholeRecording);
    void exportPngRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();

    QPushButton *m_pauseButton;
    QPushButton *m_resetZoomButton;
    QLabel *m_windowLabel;
    QComboBox *m_windowCombo;
    QLabel *m_rateLabel;
    QDoubleSpinBox *m_rateSpin;
    QToolButton *m_exportCsvButton;
    QAction *m_exportAllAction;
    QAction *m_exportWindowAction;
    QPushButton *m_exportPngButton;
};

} // namespace dd
