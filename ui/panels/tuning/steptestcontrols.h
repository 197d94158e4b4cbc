#pragma once

#include <QJsonObject>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;

namespace dd {

// The step test's controls: the limits the user sets (maximum speed, maximum travel from
// the start position, maximum duration — none is assumed), the test (velocity step,
// position step, reversal) and its size, and Run. Run stays disabled, with the reason
// shown under it, until every limit is set and the size lies within them, and while the
// panel says tests are unavailable (setAvailable()).
class StepTestControls : public QWidget
{
    Q_OBJECT
public:
    enum class Test { Velocity, Position, Reversal };

    struct Request
    {
        Test test = Test::Velocity;
        double speed = 0.0;    // r/min (position step: the move's speed)
        double duration = 0.0; // s (velocity step, each half of a reversal)
        double distance = 0.0; // counts (position step)
        double maxSpeed = 0.0;
        double maxTravel = 0.0;
        double maxDuration = 0.0;
        bool returnToStart = true; // back to the start position after a completed test
    };

    explicit StepTestControls(QWidget *parent = nullptr);

    Request request() const;
    void setRequest(const Request &r);
    // Whether the panel can run a test now, and why not.
    void setAvailable(bool available, const QString &reason);
    // While a test runs, the Run button stops it (emits stopRequested()) and the fields are
    // locked.
    void setRunning(bool running);
    bool isRunning() const { return m_running; }
    // The unit of the drive's speed (the jog's: r/min on the servos, pulse/s on shuoke).
    void setSpeedUnit(const QString &unit);
    // Why Run is disabled ("" when it is enabled).
    QString blockedReason() const;
    QPushButton *runButton() const { return m_run; }
    static QString testId(Test test); // "velocity-step", "position-step", "reversal"

signals:
    void runRequested();
    void stopRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void update();

    QFormLayout *m_limits = nullptr;
    QFormLayout *m_size = nullptr;
    QDoubleSpinBox *m_maxSpeed = nullptr;
    QDoubleSpinBox *m_maxTravel = nullptr;
    QDoubleSpinBox *m_maxDuration = nullptr;
    QComboBox *m_test = nullptr;
    QDoubleSpinBox *m_speed = nullptr;
    QDoubleSpinBox *m_duration = nullptr;
    QDoubleSpinBox *m_distance = nullptr;
    QCheckBox *m_return = nullptr;
    QPushButton *m_run = nullptr;
    QLabel *m_reason = nullptr;
    QLabel *m_limitsTitle = nullptr;
    QLabel *m_testTitle = nullptr;
    bool m_available = false;
    bool m_running = false;
    QString m_speedUnit = QStringLiteral("r/min");
    QString m_unavailableReason;
};

} // namespace dd
