#pragma once

#include "ui/bus/serialportentry.h"

#include <QList>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace dd {

// Lists the serial ports and notices adapters being plugged in or out. Qt has no portable
// hot-plug notification for serial ports, so while started the watcher polls once a second
// (PollIntervalMs; cheap: a directory read on Linux, a registry read on Windows) and emits
// portsChanged() only when the list differs. The connect dialog runs it only while it is
// open.
//
// Listed: every port QSerialPortInfo reports (description, manufacturer, USB VID:PID), plus
// virtual ports, which QSerialPortInfo never lists: symbolic links to pseudo-terminals in
// the virtual-port directories (by default the temp directory), as made by
// `drivedesk-sim --link /tmp/dd-servo` (PtyEndpoint link paths) or
// `socat pty,link=/tmp/ttyV0 ...`. Ports given with addExtraPort() (the demo bench's ptys)
// are listed too.
class SerialPortWatcher : public QObject
{
    Q_OBJECT
public:
    static constexpr int PollIntervalMs = 1000;

    explicit SerialPortWatcher(QObject *parent = nullptr);

    QList<SerialPortEntry> ports() const { return m_ports; }
    bool contains(const QString &path) const;

    void setVirtualPortDirectories(const QStringList &dirs) { m_dirs = dirs; }
    QStringList virtualPortDirectories() const { return m_dirs; }
    void addExtraPort(const QString &path, const QString &description);

    void start(); // refreshes now, then every PollIntervalMs
    void stop();
    bool isRunning() const { return m_timer.isActive(); }
    void refresh(); // emits portsChanged() if the list changed

    // The current list, without comparing or emitting.
    QList<SerialPortEntry> scan() const;

signals:
    void portsChanged();

private:
    QTimer m_timer;
    QStringList m_dirs;
    QList<SerialPortEntry> m_extra;
    QList<SerialPortEntry> m_ports;
};

} // namespace dd
