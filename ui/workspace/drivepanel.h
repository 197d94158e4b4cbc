#pragma once

#include "core/common/error.h"
#include "ui/bus/driveinfo.h"
#include "ui/workspace/drivecontext.h"

#include <QWidget>
#include <functional>

class QLabel;
class QProgressBar;

namespace dd {

struct DriveResult;

// The base of every tab shown for a drive (Overview, Parameters, Trend, Motion, EE,
// Alarms, Backup ...). How panels plug in:
//   - one panel object per drive: it is created with the drive's DriveContext when the
//     drive is first selected in the bus tree and destroyed when its connection closes, so a
//     panel may keep per-drive state (a trend, an edited table) without clearing anything;
//   - register the class in drivepanels.cpp (one line);
//   - setActive(true/false) tells it whether its drive is the selected one and its tab is
//     showing: poll only while active (the link is shared by every drive on it);
//   - driveInfoChanged() brings the identity, capabilities (with reasons for what is
//     missing) and channels once they are known, and again after a refresh;
//   - statusChanged() / alarmChanged() forward the hub's signals for this drive;
//   - all I/O goes through context().hub->run(...) (the I/O thread); never call a Drive;
//   - retranslate() is called on QEvent::LanguageChange: set every text there (and call
//     it once from the constructor); title() is re-read for the tab at the same time;
//   - report failures with reportError(): the main window shows them in the status bar;
//   - files: emit fileUsed(path) after opening or saving one (File → Recent files lists
//     it); openFile() is offered a recent file the user picks (return true if handled).
class DrivePanel : public QWidget
{
    Q_OBJECT
public:
    explicit DrivePanel(const DriveContext &context, QWidget *parent = nullptr);

    // Stable id ("overview", "parameters", ...): remembers the tab across drives.
    virtual QString panelId() const = 0;
    // Translated tab title.
    virtual QString title() const = 0;

    const DriveContext &context() const { return m_context; }
    // The drive's parameter values, shared with its other panels: report reads and writes
    // here, follow its signals (never null).
    DriveParameters *parameters() const { return m_context.parameters; }
    // The drive's alarm history since it was found (never null).
    AlarmLog *alarmLog() const { return m_context.alarms; }
    const DriveInfo &driveInfo() const { return m_info; }
    bool isActive() const { return m_active; }

    // A file picked from File → Recent files: return true if this panel opened it.
    virtual bool openFile(const QString &path)
    {
        Q_UNUSED(path);
        return false;
    }

    // Called by the workspace.
    void setActive(bool active);
    void setDriveInfo(const DriveInfo &info);
    void setStatus(const DriveStatus &status);
    void setAlarm(int code);

signals:
    void errorOccurred(const dd::Error &error);
    void titleChanged();
    void fileUsed(const QString &path);

protected:
    virtual void activeChanged(bool active) { Q_UNUSED(active); }
    virtual void driveInfoChanged(const DriveInfo &info) { Q_UNUSED(info); }
    virtual void statusChanged(const DriveStatus &status) { Q_UNUSED(status); }
    virtual void alarmChanged(int code) { Q_UNUSED(code); }
    virtual void retranslate() { }

    void changeEvent(QEvent *event) override;
    // Emits errorOccurred() when `result` failed; returns result.ok(). A success ages the
    // panel's problem lines (ageProblems()).
    bool reportResult(const DriveResult &result);
    // The drive has answered since: every problem line of this panel still showing is
    // marked as earlier ("Earlier, at 14:03:12: …", greyed), so an old error does not read
    // as the drive's present state.
    void ageProblems();
    void reportError(const Error &error);

    // Parts several panels build alike.
    // Warning: it worked, but not as asked (a move that ended short of its target);
    // Outdated: true when shown, made untrue by a later event ("Enable: done." after STOP).
    enum class MessageKind { Info, Success, Problem, EarlierProblem, Warning, Outdated };
    // A panel's message line: word-wrapped, selectable text.
    static QLabel *createMessageLabel(QWidget *parent, const QString &objectName);
    // Sets a message line's text in the colour of its kind (Info: the palette's).
    static void showMessage(QLabel *label, const QString &text, MessageKind kind);
    // The same with a text made by `text`, again after a language switch (LiveText).
    static void showMessage(QLabel *label, std::function<QString()> text, MessageKind kind);
    // A progress bar for a panel's bottom row: at most 220 px wide, hidden.
    static QProgressBar *createProgressBar(QWidget *parent);
    // A progress callback for DriveHub::run() that shows `done` of `total` on `bar`.
    static std::function<void(int done, int total)> progressOn(QProgressBar *bar);
    // The reason an action is unavailable: word-wrapped, greyed, hidden until needed.
    static QLabel *createReasonLabel(QWidget *parent);

private:
    DriveContext m_context;
    DriveInfo m_info;
    bool m_active = false;
};

} // namespace dd
