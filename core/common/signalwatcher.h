#pragma once

#include <QObject>

class QSocketNotifier;

namespace dd {

// Turns SIGINT and SIGTERM (Ctrl-C, `kill`) into a Qt signal delivered by the event loop.
// POSIX: the handler only writes one byte to a self-pipe, which a QSocketNotifier watches
// (async-signal-safe). Elsewhere: the handler sets a flag that a timer polls.
// One instance at a time; the previous handlers are restored on destruction.
class SignalWatcher : public QObject
{
    Q_OBJECT
public:
    explicit SignalWatcher(QObject *parent = nullptr);
    ~SignalWatcher() override;

    int count() const { return m_count; }

signals:
    void interrupted(int signalNumber);

private:
    void drain();

    QSocketNotifier *m_notifier = nullptr;
    int m_count = 0;
};

} // namespace dd
