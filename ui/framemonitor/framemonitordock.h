#pragma once

#include "core/common/error.h"

#include <QDockWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QToolButton;
class QTreeView;

namespace dd {

class DriveHub;
class FrameMonitorFilter;
class FrameMonitorModel;

// View → Frame monitor: every frame on every link — time, link, direction, hex bytes and
// decoded meaning — with pause, filter (text, direction, link) and save.
//   - It records from the moment the window opens, whether the dock is shown or not (the
//     last FrameMonitorModel::DefaultCapacity frames), so it can be opened after the fact.
//   - Pause freezes the view; recording goes on and the frames received meanwhile appear
//     when the pause ends (see FrameMonitorModel).
//   - Save writes the frames shown (the filter applies; frames held by a pause are not
//     shown yet, so not saved) as CSV (*.csv) or text (anything else), see TrafficLog.
//   - Follow keeps the newest frame in view.
class FrameMonitorDock : public QDockWidget
{
    Q_OBJECT
public:
    explicit FrameMonitorDock(DriveHub *hub, QWidget *parent = nullptr);

    FrameMonitorModel *model() const { return m_model; }
    FrameMonitorFilter *filter() const { return m_filter; }
    QTreeView *view() const { return m_view; }

    void setPaused(bool paused);
    bool isPaused() const;
    // Saves the frames shown to `path` (format by its suffix).
    Error saveTo(const QString &path) const;
    void save(); // asks for a file name

signals:
    void errorOccurred(const dd::Error &error);

protected:
    void changeEvent(QEvent *event) override;

private:
    void buildControls(QWidget *body);
    void buildView(QWidget *body);
    void layOut(QWidget *body);
    void connectControls();
    void retranslate();
    void updateLinks();
    void updateDirections();
    void updateCounts();

    FrameMonitorModel *m_model = nullptr;
    FrameMonitorFilter *m_filter = nullptr;
    QTreeView *m_view = nullptr;
    QToolButton *m_pause = nullptr;
    QToolButton *m_clear = nullptr;
    QToolButton *m_save = nullptr;
    QLineEdit *m_text = nullptr;
    QComboBox *m_direction = nullptr;
    QComboBox *m_link = nullptr;
    QCheckBox *m_follow = nullptr;
    QLabel *m_counts = nullptr;
};

} // namespace dd
