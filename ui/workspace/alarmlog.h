#pragma once

#include <QDateTime>
#include <QList>
#include <QObject>

namespace dd {

// One drive's alarm history, kept from the moment the drive is found (the workspace makes
// one per discovered drive and records every alarm code it reports, whether or not its tabs
// were ever opened; a panel made alone gets its own). Each change of the code is an entry:
// the time DriveDesk learnt it and the new code (0: cleared).
class AlarmLog : public QObject
{
    Q_OBJECT
public:
    struct Entry
    {
        QDateTime time;
        int code = 0;
    };

    explicit AlarmLog(QObject *parent = nullptr);

    // The code the drive reports now. The first code known makes an entry only if it is an
    // alarm; a repeated code makes none.
    void record(int code);
    // Forgets the entries (the current code stays known).
    void clearHistory();

    int currentCode() const { return m_code; }                // -1: not known yet
    const QList<Entry> &entries() const { return m_entries; } // oldest first

signals:
    void changed();

private:
    int m_code = -1;
    QList<Entry> m_entries;
};

} // namespace dd
