#pragma once

#include "core/params/alarmdictionary.h"
#include "ui/workspace/alarmlog.h"
#include "ui/workspace/drivepanel.h"

#include <QDateTime>

class QGroupBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace dd {

// The Alarms tab: the current alarm (code and text from the family's alarm dictionary, in
// the UI language; the user's own table when there is one), Read and Clear, and a history
// of every change with its time since the drive was found (newest first; AlarmLog, kept
// by the workspace), exportable as CSV. A code the alarm table does not name says where
// to look and where the user's own table goes.
// Clear is offered only where the family has it (servo-modbus: the drive's panel or a power
// cycle clears an alarm), otherwise shown disabled with the reason.
class AlarmsPanel : public DrivePanel
{
    Q_OBJECT
public:
    using HistoryEntry = AlarmLog::Entry;

    explicit AlarmsPanel(const DriveContext &context, QWidget *parent = nullptr);

    QString panelId() const override { return QStringLiteral("alarms"); }
    QString title() const override;

    int currentCode() const { return alarmLog()->currentCode(); }
    // Since the drive was found (AlarmLog), oldest first.
    const QList<HistoryEntry> &history() const { return alarmLog()->entries(); }
    // The text of `code` in the current language ("No alarm" for 0).
    QString alarmText(int code) const;

    void readAlarm();
    void clearAlarm();
    // Writes the history as CSV (time,code,alarm) atomically.
    Error exportHistory(const QString &path) const;

protected:
    void activeChanged(bool active) override;
    void driveInfoChanged(const DriveInfo &info) override;
    void alarmChanged(int code) override;
    void retranslate() override;

private:
    void buildCurrentBox();
    void buildHistoryBox();
    void onCode(int code);
    void showCurrent();
    void showHistory();
    void updateCapabilities();
    void exportWithDialog();

    AlarmDictionary m_dictionary;
    bool m_readOnce = false;
    quint64 m_alarmEvents = 0; // alarm changes reported by the drive (alarmChanged())

    QGroupBox *m_currentBox = nullptr;
    QLabel *m_codeLabel = nullptr;
    QLabel *m_textLabel = nullptr;
    QLabel *m_remedyLabel = nullptr;
    QLabel *m_clearReason = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_clear = nullptr;
    QGroupBox *m_historyBox = nullptr;
    QTableWidget *m_table = nullptr;
    QPushButton *m_export = nullptr;
    QPushButton *m_forget = nullptr;
};

} // namespace dd
