#include "ui/panels/tuning/runcomparison.h"
#include "ui/common/displaytext.h"

#include "core/tuning/runcompatibility.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

namespace {
// The unit of a run's channel ("" when it has none or was not captured).
QString unitOf(const TuningRun &run, const QString &channel)
{
    const int c = run.capture.columnOf(channel);
    return c >= 0 && c < run.units.size() ? run.units.at(c) : QString();
}

// The channel a metric is measured on, for its unit.
QString channelOf(const TuningRun &run, const QString &key)
{
    if (key == QLatin1String("peakFollowingError"))
        return QStringLiteral("position-error");
    if (key == QLatin1String("peakTorque"))
        return QStringLiteral("torque");
    if (key == QLatin1String("peakCurrent"))
        return QStringLiteral("current");
    return run.metricsChannel;
}

// Why a metric has no value. A run file keeps the reason in the language of the tool that
// measured it (the CLI's English, say); where the run itself tells the reason again (the
// channel the metric needs is not in its capture) it is worded in the UI language.
QString reasonOf(const TuningRun &run, const QString &key, const Metric &m)
{
    const QString channel = channelOf(run, key);
    if (!channel.isEmpty() && run.capture.columnOf(channel) < 0)
        return StepMetrics::tr("channel %1 was not captured").arg(channel);
    return m.reason;
}

bool isTime(const QString &key)
{
    return key == QLatin1String("riseTime") || key.startsWith(QLatin1String("settlingTime"))
        || key == QLatin1String("sampleInterval");
}
} // namespace

RunComparison::RunComparison(QWidget *parent)
    : QWidget(parent)
    , m_table(new QTableWidget(this))
    , m_differences(new QLabel(this))
    , m_notes(new QLabel(this))
{
    m_table->setObjectName(QStringLiteral("metricsTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_differences->setObjectName(QStringLiteral("parameterDifferences"));
    m_notes->setObjectName(QStringLiteral("metricNotes"));
    for (QLabel *l : {m_differences, m_notes}) {
        l->setWordWrap(true);
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    }
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_differences);
    layout->addWidget(m_notes);
    refresh();
}

void RunComparison::setRuns(const QList<TuningRun> &runs)
{
    m_runs = runs;
    refresh();
}

QString RunComparison::metricName(const QString &key)
{
    if (key == QLatin1String("riseTime"))
        return tr("Rise time (10–90 %)");
    if (key == QLatin1String("overshoot"))
        return tr("Overshoot");
    if (key == QLatin1String("settlingTime2"))
        return tr("Settling (±2 %)");
    if (key == QLatin1String("settlingTime5"))
        return tr("Settling (±5 %)");
    if (key == QLatin1String("steadyStateError"))
        return tr("Steady-state error");
    if (key == QLatin1String("steadyStateRipple"))
        return tr("Steady-state ripple");
    if (key == QLatin1String("peakFollowingError"))
        return tr("Peak following error");
    if (key == QLatin1String("peakTorque"))
        return tr("Peak torque");
    if (key == QLatin1String("peakCurrent"))
        return tr("Peak current");
    if (key == QLatin1String("sampleInterval"))
        return tr("Sample interval");
    return key;
}

QString RunComparison::metricText(const TuningRun &run, const QString &key)
{
    const Metric &m = run.metrics.byKey(key);
    if (!m.value)
        return tr("not resolvable");
    const double v = *m.value;
    if (key == QLatin1String("overshoot"))
        return tr("%1 %").arg(v, 0, 'f', 1);
    if (isTime(key))
        return tr("%1 ms").arg(v * 1000.0, 0, 'f', 1);
    const QString unit = DisplayText::unit(unitOf(run, channelOf(run, key)));
    const QString number = QString::number(v, 'g', 4);
    return unit.isEmpty() ? number : number + QLatin1Char(' ') + unit;
}

QString RunComparison::differenceLine(const TuningRun &a, const TuningRun &b)
{
    // Not like for like: say why instead of comparing parameters (RunCompatibility).
    const QStringList why = RunCompatibility::snapshotProblems(a) + RunCompatibility::snapshotProblems(b)
        + RunCompatibility::differences(a, b);
    if (!why.isEmpty())
        return tr("%1 → %2: not comparable: %3").arg(a.label, b.label, why.join(QLatin1Char(' ')));
    QStringList changes;
    for (const TuningSnapshotEntry &eb : b.tuning)
        for (const TuningSnapshotEntry &ea : a.tuning)
            if (ea.key == eb.key && ea.value != eb.value)
                changes << QStringLiteral("%1 %2 → %3").arg(eb.key).arg(ea.value).arg(eb.value);
    QStringList effects;
    for (const QString &k : {QStringLiteral("overshoot"), QStringLiteral("settlingTime2"), QStringLiteral("riseTime")})
        effects << tr("%1 %2 → %3").arg(metricName(k).toLower(), metricText(a, k), metricText(b, k));
    const QString what = changes.isEmpty() ? tr("no tuning parameter differs") : changes.join(QStringLiteral(", "));
    return tr("%1 → %2: %3: %4").arg(a.label, b.label, what, effects.join(QStringLiteral(", ")));
}

QString RunComparison::differencesText() const
{
    return m_differences->text();
}

QString RunComparison::notesText() const
{
    return m_notes->text();
}

void RunComparison::refresh()
{
    const QStringList &keys = StepMetrics::keys();
    m_table->clear();
    m_table->setRowCount(int(keys.size()));
    m_table->setColumnCount(int(m_runs.size()));
    QStringList headers;
    for (const TuningRun &r : std::as_const(m_runs))
        headers << r.label;
    m_table->setHorizontalHeaderLabels(headers);
    QStringList rowNames;
    for (const QString &k : keys)
        rowNames << metricName(k);
    m_table->setVerticalHeaderLabels(rowNames);
    QStringList notes;
    for (int c = 0; c < m_runs.size(); ++c) {
        const TuningRun &run = m_runs.at(c);
        for (int r = 0; r < keys.size(); ++r) {
            const Metric &m = run.metrics.byKey(keys.at(r));
            auto *item = new QTableWidgetItem(metricText(run, keys.at(r)));
            if (!m.value) {
                const QString reason = reasonOf(run, keys.at(r), m);
                item->setToolTip(reason);
                item->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
                if (!reason.isEmpty())
                    notes << tr("%1, %2: %3").arg(run.label, metricName(keys.at(r)).toLower(), reason);
            } else if (m.resolution > 0.0) {
                item->setToolTip(tr("Resolution: %1")
                                     .arg(isTime(keys.at(r)) ? tr("%1 ms").arg(m.resolution * 1000.0, 0, 'g', 3)
                                                             : QString::number(m.resolution, 'g', 3)));
            }
            m_table->setItem(r, c, item);
        }
    }
    m_table->resizeColumnsToContents();
    QStringList lines;
    for (int i = 1; i < m_runs.size(); ++i)
        lines << differenceLine(m_runs.at(i - 1), m_runs.at(i));
    if (m_runs.isEmpty())
        m_differences->setText(tr("Tick runs in the list to compare them here."));
    else if (lines.isEmpty())
        m_differences->setText(tr("Tick a second run to see the parameter differences."));
    else
        m_differences->setText(lines.join(QLatin1Char('\n')));
    // A few lines at most: the table keeps its room (every reason is in its cell's tool tip).
    constexpr int MaxNotes = 4;
    if (notes.size() > MaxNotes) {
        const int more = int(notes.size()) - MaxNotes;
        notes = notes.mid(0, MaxNotes);
        notes << tr("… and %n more (the cells' tool tips give every reason).", nullptr, more);
    }
    m_notes->setText(notes.join(QLatin1Char('\n')));
    m_notes->setVisible(!notes.isEmpty());
}

void RunComparison::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        refresh();
}

} // namespace dd
