#pragma once

#include "core/common/error.h"

#include <QPointer>
#include <QPushButton>
#include <QTimer>

namespace dd {

class DriveHub;

// A hold-to-run jog button: the axis moves only while the button is held.
//   - press (left mouse button, or Space while it has the focus) → DriveHub::run(jog) and a
//     timer that calls DriveHub::renewJogLease every RenewIntervalMs while it is held;
//   - release, the pointer leaving the button, focus loss, the window deactivating, the
//     application becoming inactive, the button being hidden or disabled, the link being
//     lost, or the button being destroyed → the hold ends and a stop is sent;
//   - the drive stops by itself (I/O side) when the lease is not renewed in time (a frozen
//     GUI): jogLeaseExpired ends the hold; so does a jogEnded that no stop command confirms
//     (the drive went silent: its watchdog, if it has one, stops the axis);
//   - auto-repeated key presses and releases (a held key) are ignored: one hold, one jog.
// The button never emits clicked(): it acts on press and release only.
class JogButton : public QPushButton
{
    Q_OBJECT
public:
    static constexpr int RenewIntervalMs = 50;

    enum class StopReason {
        Released,
        PointerLeft,
        FocusLost,
        WindowDeactivated,
        ApplicationInactive,
        Hidden,
        Disabled,
        LinkLost,
        LeaseExpired, // the I/O side stopped the axis: no renewal came in time
        DriveLost,    // the drive stopped answering: the I/O side ended the jog
        JogFailed,    // the drive refused or did not start the jog
        Requested     // stopHold() by the owner (STOP, tab change ...)
    };
    Q_ENUM(StopReason)

    // `direction`: +1 or -1, applied to speed().
    explicit JogButton(int direction, QWidget *parent = nullptr);
    ~JogButton() override; // a held button sends its stop

    void setDrive(DriveHub *hub, int connectionId, int address);
    int direction() const { return m_direction; }
    // Speed magnitude for the next press (the family's unit); a held jog keeps its speed.
    void setSpeed(qint32 speed) { m_speed = speed; }
    qint32 speed() const { return m_speed; }

    bool isHolding() const { return m_holding; }
    // Ends a hold (if any) and sends the stop.
    void stopHold(StopReason reason = StopReason::Requested);

signals:
    void jogStarted(qint32 signedSpeed);
    void jogStopped(dd::JogButton::StopReason reason);
    void errorOccurred(const dd::Error &error);

protected:
    bool event(QEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void startHold();
    void endHold(StopReason reason, bool sendStop);
    void renew();
    void onApplicationStateChanged(Qt::ApplicationState state);

    QPointer<DriveHub> m_hub;
    int m_connectionId = 0;
    int m_address = 0;
    int m_direction = 1;
    qint32 m_speed = 0;
    bool m_holding = false;
    bool m_keyHold = false;   // held with the keyboard (Space)
    quint64 m_generation = 0; // one per hold: late jog results of an old hold are ignored
    QTimer m_renew;
    QList<QMetaObject::Connection> m_hubConnections;
};

} // namespace dd
