#pragma once

#include "core/tuning/tuningrun.h"
#include "ui/workspace/drivepanel.h"

#include <functional>
#include <memory>

class QComboBox;
class QLabel;
class QPushButton;
class QScrollArea;
class QTabWidget;

namespace dd {

class CaptureControls;
class CapturePlot;
class HubCapture;
class HubStepTest;
struct StepResult;
class ParameterDictionary;
class RunComparison;
class RunList;
class SpectrumView;
class StepTestControls;
class TuningParametersEditor;

// The "Tuning" tab (docs/gui.md): the loop "edit gain → run → compare" on one page.
// - Left: the capture plot (runs overlaid, aligned on their trigger, two cursors with Δt
//   and Δvalue), under it the runs list with the metrics table and parameter differences,
//   and the spectrum of the selected run.
// - Right: the step test (limits, test, size, Run) and the free capture (trigger, Arm,
//   Force), and the tuning parameters, edited and written through the drive's shared
//   DriveParameters, with "Apply this run's parameters".
// A capture becomes a run: the samples, its metrics (on speed when captured, else the
// first channel) and the tuning parameters read from the drive right after it.
class TuningPanel : public DrivePanel
{
    Q_OBJECT
public:
    explicit TuningPanel(const DriveContext &context, QWidget *parent = nullptr);
    ~TuningPanel() override;

    QString panelId() const override { return QStringLiteral("tuning"); }
    QString title() const override;
    bool openFile(const QString &path) override;

    // The channels a free capture reads: the tuning quantities the drive offers (speed,
    // speed command, position error, torque, current), else its first three.
    QStringList captureChannels() const;
    void arm();
    void force();
    void stopCapture();
    bool isCapturing() const;
    // Runs the step test set up in the Step test page (its Run button).
    void runStep();
    bool isStepRunning() const;
    // "Apply this run's parameters" on the selected run.
    void applySelectedRun();

    CaptureControls *captureControls() const { return m_captureControls; }
    StepTestControls *stepControls() const { return m_stepControls; }
    CapturePlot *capturePlot() const { return m_plot; }
    RunList *runList() const { return m_runs; }
    RunComparison *comparison() const { return m_comparison; }
    SpectrumView *spectrumView() const { return m_spectrum; }
    TuningParametersEditor *parametersEditor() const { return m_editor; }
    QComboBox *plotChannel() const { return m_plotChannel; }
    QPushButton *applyButton() const { return m_apply; }
    QScrollArea *sidePanel() const { return m_side; }
    QString message() const;

protected:
    void activeChanged(bool active) override;
    void driveInfoChanged(const DriveInfo &info) override;
    void alarmChanged(int code) override;
    void retranslate() override;
    void showEvent(QShowEvent *event) override;

private:
    void updateSideWidth();
    void buildUi();
    void loadDictionary();
    void onCaptured(const CaptureData &capture);
    void onStepFinished(const StepResult &result);
    void addRunWithSnapshot(TuningRun run);
    void addCapturedRun(TuningRun run, const QMap<int, qint64> &values, const QString &readError);
    void updateCaptureState();
    void updateOverlay();
    void updateSelection();
    void updatePlotChannels();

    HubCapture *m_capture = nullptr;
    HubStepTest *m_step = nullptr;
    int m_stepCount = 0;
    CaptureControls *m_captureControls = nullptr;
    StepTestControls *m_stepControls = nullptr;
    CapturePlot *m_plot = nullptr;
    QComboBox *m_plotChannel = nullptr;
    QLabel *m_plotChannelLabel = nullptr;
    RunList *m_runs = nullptr;
    RunComparison *m_comparison = nullptr;
    SpectrumView *m_spectrum = nullptr;
    TuningParametersEditor *m_editor = nullptr;
    QPushButton *m_apply = nullptr;
    QTabWidget *m_actions = nullptr;
    QTabWidget *m_results = nullptr;
    QLabel *m_parametersTitle = nullptr;
    QLabel *m_message = nullptr;
    QLabel *m_unavailable = nullptr;
    QWidget *m_body = nullptr;
    QScrollArea *m_side = nullptr;
    bool m_dictionaryAsked = false;
    int m_captureCount = 0;
    std::function<QString()> m_lastCaptureState; // the last capture's outcome, in the current language
};

} // namespace dd
