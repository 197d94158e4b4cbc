#include "ui/report/recordaction.h"

#include "ui/report/recorddialog.h"
#include "ui/report/recordsession.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"

namespace dd {

RecordAction::RecordAction(MainWindow *window)
    : QAction(window)
    , m_window(window)
    , m_session(new RecordSession(window->hub(), window->directory(), this))
{
    setObjectName(QStringLiteral("commissioningRecordAction"));
    connect(this, &QAction::triggered, this, &RecordAction::open);
    connect(window->languageManager(), &LanguageManager::languageChanged, this, &RecordAction::retranslate);
    retranslate();
}

void RecordAction::retranslate()
{
    setText(tr("Commissioning &record…"));
    setToolTip(tr("A PDF (and JSON) record of the drives: what was set, verified and measured"));
}

void RecordAction::open()
{
    auto *dialog = new RecordDialog(m_window->directory(), m_session, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}

} // namespace dd
