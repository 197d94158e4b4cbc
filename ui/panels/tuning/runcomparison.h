#pragma once

#include "core/tuning/tuningrun.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace dd {

// The runs side by side: the metrics table (one row per metric, one column per run; a
// metric the capture cannot resolve reads "not resolvable" with the reason in its tool tip
// and under the table) and the parameter differences between consecutive runs with what
// they did to the metrics ("PA5 40 → 60: overshoot 18.0 % → 7.0 %, settling (2 %) 120.0 ms
// → 60.0 ms").
class RunComparison : public QWidget
{
    Q_OBJECT
public:
    explicit RunComparison(QWidget *parent = nullptr);

    void setRuns(const QList<TuningRun> &runs);
    QTableWidget *table() const { return m_table; }
    QString differencesText() const;
    QString notesText() const;

    // The metric's display name ("Rise time (10–90 %)").
    static QString metricName(const QString &key);
    // "12.3 ms", "9.1 %", "4.2 r/min"; "not resolvable" when it has no value.
    static QString metricText(const TuningRun &run, const QString &key);
    // The difference lines between consecutive runs (`a` → `b`).
    static QString differenceLine(const TuningRun &a, const TuningRun &b);

protected:
    void changeEvent(QEvent *event) override;

private:
    void refresh();

    QList<TuningRun> m_runs;
    QTableWidget *m_table = nullptr;
    QLabel *m_differences = nullptr;
    QLabel *m_notes = nullptr;
};

} // namespace dd
