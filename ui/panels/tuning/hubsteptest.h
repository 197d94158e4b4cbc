#pragma once

#include "core/tuning/steplimits.h"
#include "core/tuning/stepresult.h"
#include "core/tuning/stepspec.h"
#include "core/tuning/steptest.h"

#include <QObject>

namespace dd {

class DriveHub;

// Runs the core StepTest on the drive's I/O thread through the DriveHub (the GUI never
// touches a Drive): the test lives as long as one hub operation whose reply finishes with
// the StepResult; its phases come back as the reply's progress. Stopping goes through the
// drive's stop(), which aborts the test (as the main window's STOP does).
class HubStepTest : public QObject
{
    Q_OBJECT
public:
    HubStepTest(DriveHub *hub, int connectionId, int address, QObject *parent = nullptr);

    void start(const StepSpec &spec, const StepLimits &limits);
    void stop();
    bool isRunning() const { return m_running; }
    StepTest::Phase phase() const { return m_phase; }

signals:
    void phaseChanged(dd::StepTest::Phase phase);
    void finished(const dd::StepResult &result);

private:
    DriveHub *m_hub;
    int m_connectionId;
    int m_address;
    bool m_running = false;
    StepTest::Phase m_phase = StepTest::Phase::Idle;
};

} // namespace dd
