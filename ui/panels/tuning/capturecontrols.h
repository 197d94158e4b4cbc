#pragma once

#include "core/drive/drivetypes.h"
#include "core/tuning/capturesettings.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;

namespace dd {

// The free capture's controls: the trigger (a channel crossing a level rising / falling /
// either, above / below it, an alarm, or at once), the pre-trigger share of the record, its
// length and mode (single, normal = re-arm, auto = capture anyway after a time-out), and
// Arm / Force / Stop. It only asks; the Tuning panel runs the capture and shows its state.
class CaptureControls : public QWidget
{
    Q_OBJECT
public:
    explicit CaptureControls(QWidget *parent = nullptr);

    void setChannels(const QList<ChannelInfo> &channels);
    CaptureSettings settings() const;
    void setSettings(const CaptureSettings &settings);
    // Running: Arm is disabled, Force and Stop enabled; `state` says what happens.
    void setRunning(bool running, const QString &state);
    QString stateText() const;

    QPushButton *armButton() const { return m_arm; }
    QPushButton *forceButton() const { return m_force; }
    QPushButton *stopButton() const { return m_stop; }

signals:
    void armRequested();
    void forceRequested();
    void stopRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateLevelFields();

    QFormLayout *m_form = nullptr;
    QComboBox *m_kind = nullptr;
    QComboBox *m_channel = nullptr;
    QDoubleSpinBox *m_level = nullptr;
    QDoubleSpinBox *m_pre = nullptr;
    QDoubleSpinBox *m_length = nullptr;
    QComboBox *m_mode = nullptr;
    QDoubleSpinBox *m_timeout = nullptr;
    QPushButton *m_arm = nullptr;
    QPushButton *m_force = nullptr;
    QPushButton *m_stop = nullptr;
    QLabel *m_state = nullptr;
    QList<ChannelInfo> m_channels;
};

} // namespace dd
