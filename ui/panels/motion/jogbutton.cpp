#include "ui/panels/motion/jogbutton.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"

#include <QFocusEvent>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>

namespace dd {

JogButton::JogButton(int direction, QWidget *parent)
    : QPushButton(parent)
    , m_direction(direction < 0 ? -1 : 1)
{
    setFocusPolicy(Qt::StrongFocus);
    setAutoDefault(false);
    setDefault(false);
    setAutoRepeat(false);
    m_renew.setInterval(RenewIntervalMs);
    m_renew.setTimerType(Qt::PreciseTimer);
    connect(&m_renew, &QTimer::timeout, this, &JogButton::renew);
    if (qGuiApp)
        connect(qGuiApp, &QGuiApplication::applicationStateChanged, this, &JogButton::onApplicationStateChanged);
}

JogButton::~JogButton()
{
    // No signals from a dying button: just make sure the axis stops.
    if (m_holding && m_hub)
        m_hub->run(m_connectionId, m_address, [](Drive &d) { return d.stop(false); });
}

void JogButton::setDrive(DriveHub *hub, int connectionId, int address)
{
    if (m_holding)
        stopHold();
    for (const QMetaObject::Connection &c : std::as_const(m_hubConnections))
        disconnect(c);
    m_hubConnections.clear();
    m_hub = hub;
    m_connectionId = connectionId;
    m_address = address;
    if (!hub)
        return;
    m_hubConnections << connect(hub, &DriveHub::linkLost, this, [this](int id, const Error &) {
        if (id == m_connectionId)
            endHold(StopReason::LinkLost, false);
    });
    // The I/O side has stopped the axis already: no second stop.
    m_hubConnections << connect(hub, &DriveHub::jogLeaseExpired, this, [this](int id, int address) {
        if (id == m_connectionId && address == m_address)
            endHold(StopReason::LeaseExpired, false);
    });
    // The I/O side ended the jog without a confirmed stop (the drive went silent).
    m_hubConnections << connect(hub, &DriveHub::jogEnded, this, [this](int id, int address, const JogEnd &end) {
        if (id == m_connectionId && address == m_address && end.stoppedBy != JogEnd::StoppedBy::Command)
            endHold(end.linkLost ? StopReason::LinkLost : StopReason::DriveLost, false);
    });
}

void JogButton::stopHold(StopReason reason)
{
    endHold(reason, true);
}

void JogButton::startHold()
{
    if (m_holding || !m_hub || !isEnabled() || m_connectionId <= 0)
        return;
    m_holding = true;
    const quint64 generation = ++m_generation;
    setDown(true);
    m_renew.start();
    const qint32 speed = m_direction * m_speed;
    QPointer<JogButton> self(this);
    m_hub->run(
        m_connectionId, m_address, [speed](Drive &d) { return d.jog(speed); },
        [self, generation](const DriveResult &r) {
            // A failure after the button was let go (a short tap: the axis was
            // stopped before it could start) is no news.
            if (!self || r.ok() || !self->m_holding || self->m_generation != generation)
                return;
            self->endHold(StopReason::JogFailed, true);
            emit self->errorOccurred(r.error);
        });
    emit jogStarted(speed);
}

void JogButton::endHold(StopReason reason, bool sendStop)
{
    if (!m_holding)
        return;
    m_holding = false;
    m_keyHold = false;
    m_renew.stop();
    setDown(false);
    if (sendStop && m_hub) {
        QPointer<JogButton> self(this);
        m_hub->run(
            m_connectionId, m_address, [](Drive &d) { return d.stop(false); },
            [self](const DriveResult &r) {
                if (self && !r.ok() && r.error.code != ErrorCode::LinkClosed)
                    emit self->errorOccurred(r.error);
            });
    }
    emit jogStopped(reason);
}

void JogButton::renew()
{
    if (m_holding && m_hub)
        m_hub->renewJogLease(m_connectionId, m_address);
}

void JogButton::onApplicationStateChanged(Qt::ApplicationState state)
{
    if (state != Qt::ApplicationActive)
        endHold(StopReason::ApplicationInactive, true);
}

bool JogButton::event(QEvent *event)
{
    if (event->type() == QEvent::WindowDeactivate)
        endHold(StopReason::WindowDeactivated, true);
    return QPushButton::event(event);
}

void JogButton::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    event->accept();
    startHold();
}

void JogButton::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    event->accept();
    if (!m_keyHold)
        endHold(StopReason::Released, true);
}

void JogButton::mouseMoveEvent(QMouseEvent *event)
{
    event->accept();
    if (m_holding && !m_keyHold && !rect().contains(event->position().toPoint()))
        endHold(StopReason::PointerLeft, true);
}

void JogButton::keyPressEvent(QKeyEvent *event)
{
    if (event->key() != Qt::Key_Space) {
        QPushButton::keyPressEvent(event);
        return;
    }
    event->accept();
    if (event->isAutoRepeat() || m_holding)
        return;
    startHold();
    m_keyHold = m_holding;
}

void JogButton::keyReleaseEvent(QKeyEvent *event)
{
    if (event->key() != Qt::Key_Space) {
        QPushButton::keyReleaseEvent(event);
        return;
    }
    event->accept();
    if (!event->isAutoRepeat() && m_keyHold)
        endHold(StopReason::Released, true);
}

void JogButton::focusOutEvent(QFocusEvent *event)
{
    endHold(event->reason() == Qt::ActiveWindowFocusReason ? StopReason::WindowDeactivated : StopReason::FocusLost,
            true);
    QPushButton::focusOutEvent(event);
}

void JogButton::hideEvent(QHideEvent *event)
{
    endHold(StopReason::Hidden, true);
    QPushButton::hideEvent(event);
}

void JogButton::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::EnabledChange && !isEnabled())
        endHold(StopReason::Disabled, true);
    else if (event->type() == QEvent::ActivationChange && !isActiveWindow())
        endHold(StopReason::WindowDeactivated, true);
    QPushButton::changeEvent(event);
}

} // namespace dd
