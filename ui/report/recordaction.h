#pragma once

#include <QAction>

namespace dd {

class MainWindow;
class RecordSession;

// File → Commissioning record…: opens the RecordDialog on the main window's drives. Owns the
// RecordSession that notes alarms and link health from the start of the session.
class RecordAction : public QAction
{
    Q_OBJECT
public:
    explicit RecordAction(MainWindow *window);

    RecordSession *session() const { return m_session; }

private:
    void retranslate();
    void open();

    MainWindow *m_window;
    RecordSession *m_session;
};

} // namespace dd
