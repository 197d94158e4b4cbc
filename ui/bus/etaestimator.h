#pragma once

#include <QElapsedTimer>

namespace dd {

// Remaining time of a job that advances in equal steps (a scan probes one address after
// another): elapsed / done × (total − done). No estimate before the first step or after
// the job has gone backwards (a new stage: call start() again).
class EtaEstimator
{
public:
    void start();
    void update(int done, int total);
    // Milliseconds left; -1 while unknown.
    qint64 remainingMs() const;
    qint64 elapsedMs() const;
    int done() const { return m_done; }
    int total() const { return m_total; }
    // "about 12 s", "about 2 min" (translated); empty while unknown.
    static QString format(qint64 ms);

    // For tests: fixes the elapsed time instead of the clock.
    void setElapsedForTest(qint64 ms) { m_fixedElapsed = ms; }

private:
    QElapsedTimer m_clock;
    qint64 m_fixedElapsed = -1;
    int m_done = 0;
    int m_total = 0;
};

} // namespace dd
