#pragma once

#include "core/common/error.h"
#include "core/link/trafficrecord.h"

#include <QElapsedTimer>
#include <QStatusBar>
#include <QTimer>
#include <functional>

class QLabel;

namespace dd {

class DriveDirectory;
class DriveHub;

// The main window's status bar: link state, frames per second (from
// DriveHub::trafficRecorded, over the last second), error and retry counts. Errors are
// discarded frames (bad checksum, garbage, late replies), lost links and failed operations
// reported with countError(); retries are repeated requests (the links mark them
// "(retry N)"). A failed operation's message is also shown for a few seconds.
class StatusBarWidget : public QStatusBar
{
    Q_OBJECT
public:
    StatusBarWidget(DriveHub *hub, DriveDirectory *directory, QWidget *parent = nullptr);

    quint64 errorCount() const { return m_errors; }
    quint64 retryCount() const { return m_retries; }
    double framesPerSecond() const { return m_fps; }

    void countError(const dd::Error &error);
    void resetCounters();
    // A message whose text is made by `text` now and again after a language switch, for as
    // long as it is shown (0: until replaced).
    void showLiveMessage(std::function<QString()> text, int timeoutMs = 0);

protected:
    void changeEvent(QEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    void onTraffic(int id, const TrafficRecord &record);
    void onTick();
    void updateLinkState();
    void updateCounters();
    void retranslate();
    void onMessageChanged(const QString &text);

    DriveHub *m_hub = nullptr;
    DriveDirectory *m_directory = nullptr;
    QLabel *m_link = nullptr;
    QLabel *m_fpsLabel = nullptr;
    QLabel *m_errorsLabel = nullptr;
    QLabel *m_retriesLabel = nullptr;
    QTimer m_tick;
    QElapsedTimer m_window;
    quint64 m_framesInWindow = 0;
    double m_fps = 0;
    quint64 m_errors = 0;
    quint64 m_retries = 0;
    std::function<QString()> m_liveText; // the shown message's maker, if it has one
    QString m_liveShown;                 // what it made last
    QTimer m_liveTimeout;
};

} // namespace dd
