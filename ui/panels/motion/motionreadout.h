#pragma once

#include "core/drive/drivetypes.h"
#include "ui/workspace/drivecontext.h"

#include <QMap>
#include <QWidget>
#include <optional>

class QLabel;
class QTimer;

namespace dd {

// The Motion tab's large live readout: speed, position and following error (those of the
// three the drive's channels offer), and the limit / origin switch indicators of a drive
// that reports them (the "status" channel: StatusChannelBits). Reads them while polling is
// on (the Motion tab shown), one read at a time, the next ReadGapMs after the answer; a
// failed read shows "—" rather than an old value.
class MotionReadout : public QWidget
{
    Q_OBJECT
public:
    static constexpr int ReadGapMs = 150;
    enum class Switch { LeftLimit, Origin, RightLimit };

    explicit MotionReadout(const DriveContext &context, QWidget *parent = nullptr);

    void setChannels(const QList<ChannelInfo> &channels);
    void setPolling(bool on);
    bool isPolling() const { return m_polling; }

    // For tests: the big text of "speed", "position" or "position-error" ("" when not shown).
    QString valueText(const QString &channelId) const;
    // Whether a switch is active; nullopt when the drive does not report it (yet).
    std::optional<bool> switchActive(Switch s) const;
    bool showsSwitches() const;
    int readCount() const { return m_reads; }

    void retranslate();

signals:
    void updated(); // after each read

private:
    struct Value
    {
        ChannelInfo channel;
        QWidget *box = nullptr;
        QLabel *title = nullptr;
        QLabel *value = nullptr;
        std::optional<double> last; // nullopt: not read, or the last read failed ("—")
    };
    static void showValue(const Value &v); // its number with the unit in the UI language
    void readNow();
    void onSamples(bool ok, const QMap<QString, double> &samples);
    void showSwitches();
    QString switchName(Switch s) const;

    DriveContext m_context;
    QMap<QString, Value> m_values; // by channel id, in display order speed, position, error
    QStringList m_ids;             // what each read asks for
    QWidget *m_switchBox = nullptr;
    QMap<Switch, QLabel *> m_switchLabels;
    std::optional<int> m_statusBits;
    bool m_hasStatus = false;
    bool m_polling = false;
    bool m_reading = false;
    int m_generation = 0;
    int m_reads = 0;
    QTimer *m_timer = nullptr;
};

} // namespace dd
