#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace dd {

struct TuningRun;

// What keeps two run files from being compared parameter for parameter, or one run file's
// snapshot from being trusted (docs/tuning.md, "Comparing runs"): `runs` and the Tuning
// tab's comparison say these instead of "no tuning parameter differs".
class RunCompatibility
{
    Q_DECLARE_TR_FUNCTIONS(dd::RunCompatibility)

public:
    // Problems of one run's tuning snapshot: a parameter listed twice (by index or key).
    static QStringList snapshotProblems(const TuningRun &run);
    // Why runs a and b are not like for like: another drive family or model, another
    // dictionary (the same parameter under another key or role), another test type, another
    // step size (velocity: speed; position: distance). Empty when they compare.
    static QStringList differences(const TuningRun &a, const TuningRun &b);
    // The step's size as the run file records it ("300 r/min", "20000 counts"); "" for a
    // capture or a run without one.
    static QString stepSize(const TuningRun &run);
};

} // namespace dd
