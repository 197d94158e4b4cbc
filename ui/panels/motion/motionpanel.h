#pragma once

#include "core/drive/drivehub.h"
#include "core/drive/motiongoal.h"
#include "ui/panels/motion/jogbutton.h"
#include "ui/panels/motion/motionreadout.h"
#include "ui/workspace/drivepanel.h"

#include <optional>

class QComboBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;

namespace dd {

// The Motion tab: a large live readout of speed, position and following error with the limit
// and origin switches where the drive reports them (MotionReadout, read while the tab is
// shown), power stage on/off, hold-to-run jog (JogButton) at a chosen speed,
// relative / absolute moves, homing, setting the position, and a stop for this drive.
// Each function is enabled only where the drive family has it; otherwise it is disabled,
// with the family's reason as tooltip and written under it. The STOP in the tool bar
// (Esc / F12) stops every drive and is not repeated here.
//
// Speed units and limits by family: servo-can r/min (1..6000: the seed gives no maximum;
// 6000 r/min is above the rated speed of the AC servo motors these drives run), positions
// in encoder counts; shuoke pulses/s (1..100000, the seed's limit), positions in pulses.
class MotionPanel : public DrivePanel
{
    Q_OBJECT
public:
    struct SpeedRange
    {
        int minimum = 1;
        int maximum = 0;
        int jogDefault = 0;
        int moveDefault = 0;
    };
    static SpeedRange speedRange(Family family);

    explicit MotionPanel(const DriveContext &context, QWidget *parent = nullptr);

    QString panelId() const override { return QStringLiteral("motion"); }
    QString title() const override;

    JogButton *jogPositive() const { return m_jogPlus; }
    JogButton *jogNegative() const { return m_jogMinus; }
    MotionReadout *readout() const { return m_readout; }

    // Stops this drive (and ends any jog hold).
    void stopDrive();

protected:
    void activeChanged(bool active) override;
    void driveInfoChanged(const DriveInfo &info) override;
    void statusChanged(const DriveStatus &status) override;
    void retranslate() override;

private:
    QGroupBox *makeGroup(const QString &objectName, QLabel **reason);
    void buildPowerBox();
    void buildJogBox(const SpeedRange &range);
    void connectJogButtons();
    void buildMoveBox(const SpeedRange &range);
    void buildHomeBox();
    void buildPositionBox();
    void buildStopButton();
    void layOut();
    // Empty when the drive has `c`; otherwise why not.
    QString reasonFor(Capability c) const;
    void updateCapabilities();
    void updateMoveCapabilities(bool showReasons);
    void showStatus();
    // Runs `op`; its outcome goes to `result` (the label of the action's own box). A motion
    // (`goal`: a move, homing) is "started" when the drive takes it and "done" only when the
    // drive reports the axis at rest where the goal says (MotionGoal, watchMotion()); at rest
    // elsewhere, the line says where and why (a STOP), in the warning colour.
    using Text = std::function<QString()>; // made again after a language switch
    void runCommand(const Text &what, DriveHub::Operation op, QLabel *result,
                    std::optional<MotionGoal> goal = std::nullopt);
    void watchMotion(int generation, const Text &what, QLabel *result, int polls, bool seenRunning,
                     const MotionGoal &goal, int stopsAtStart);
    void showMotionEnd(const Text &what, QLabel *result, const DriveStatus &s, const MotionGoal &goal, bool stopped,
                       bool stoppedByStop);
    // Jog, move and homing need the power stage on (enabling is the engineer's act: the
    // servo-can motion commands would switch it on by themselves). Empty when motion may go.
    QString powerOffReason() const;
    void updatePowerOffNotice();
    // The power box's "Enable: done." / "Disable: done." greyed once the drive says otherwise.
    void agePowerResult(const DriveStatus &s);
    QLabel *makeResultLabel(QGroupBox *box, const QString &objectName);
    void move();
    void onJogStarted(qint32 speed);
    void onJogStopped(JogButton::StopReason reason);
    QString speedUnit() const;
    QString distanceUnit() const;

    QLabel *m_banner = nullptr;
    MotionReadout *m_readout = nullptr;
    QLabel *m_state = nullptr;
    QLabel *m_position = nullptr;
    QLabel *m_jogState = nullptr;

    QGroupBox *m_powerBox = nullptr;
    QLabel *m_powerReason = nullptr;
    QPushButton *m_enable = nullptr;
    QPushButton *m_disable = nullptr;

    QGroupBox *m_jogBox = nullptr;
    QLabel *m_jogReason = nullptr;
    QLabel *m_jogSpeedLabel = nullptr;
    QSpinBox *m_jogSpeed = nullptr;
    JogButton *m_jogMinus = nullptr;
    JogButton *m_jogPlus = nullptr;
    QLabel *m_jogHint = nullptr;

    QGroupBox *m_moveBox = nullptr;
    QLabel *m_moveReason = nullptr;
    QRadioButton *m_relative = nullptr;
    QRadioButton *m_absolute = nullptr;
    QSpinBox *m_moveValue = nullptr;
    QLabel *m_moveSpeedLabel = nullptr;
    QSpinBox *m_moveSpeed = nullptr;
    QPushButton *m_moveButton = nullptr;

    QGroupBox *m_homeBox = nullptr;
    QLabel *m_homeReason = nullptr;
    QComboBox *m_homeDirection = nullptr;
    QPushButton *m_homeButton = nullptr;

    QGroupBox *m_positionBox = nullptr;
    QLabel *m_positionReason = nullptr;
    QLabel *m_setPositionLabel = nullptr;
    QSpinBox *m_setPositionValue = nullptr;
    QPushButton *m_setPositionButton = nullptr;

    QPushButton *m_stop = nullptr;
    QLabel *m_stopHint = nullptr;
    QLabel *m_stopResult = nullptr;

    // The result of the last action in each box.
    QLabel *m_powerResult = nullptr;
    int m_powerAsked = 0; // +1 Enable, -1 Disable: the power box's last command
    int m_powerDone = 0;  // +1 "Enable: done." shown, -1 "Disable: done.", 0 neither
    // Above the boxes while the power stage is off: why motion is refused, and Enable.
    QWidget *m_powerOffNotice = nullptr;
    QLabel *m_powerOffText = nullptr;
    QPushButton *m_powerOffEnable = nullptr;
    QLabel *m_moveResult = nullptr;
    QLabel *m_homeResult = nullptr;
    QLabel *m_positionResult = nullptr;
    int m_motionGeneration = 0;     // a new motion command ends the watch of the previous one
    int m_stopsSent = 0;            // STOP (DriveHub::stopAllSent) and this drive's stop, counted
    bool m_lastStopWasStop = false; // the last of them was the tool bar's STOP
};

} // namespace dd
