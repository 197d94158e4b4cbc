#include "ui/shell/loaddictionaryaction.h"

#include "ui/panels/parameters/parameterspanel.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"
#include "ui/workspace/driveworkspace.h"

namespace dd {

LoadDictionaryAction::LoadDictionaryAction(MainWindow *window)
    : QAction(window)
    , m_window(window)
{
    setObjectName(QStringLiteral("loadDictionaryAction"));
    connect(this, &QAction::triggered, this, &LoadDictionaryAction::open);
    connect(window->languageManager(), &LanguageManager::languageChanged, this, &LoadDictionaryAction::retranslate);
    connect(window->workspace(), &DriveWorkspace::currentDriveChanged, this, [this](int id) { setEnabled(id > 0); });
    setEnabled(false);
    retranslate();
}

void LoadDictionaryAction::retranslate()
{
    setText(tr("Load &dictionary…"));
    setToolTip(tr("Load your drive's parameter dictionary (names, units, ranges) for the selected drive"));
}

void LoadDictionaryAction::open()
{
    DriveWorkspace *workspace = m_window->workspace();
    const DriveContext drive = workspace->currentDrive();
    for (DrivePanel *p : workspace->panelsFor(drive.connectionId, drive.address))
        if (auto *parameters = qobject_cast<ParametersPanel *>(p)) {
            workspace->setPreferredPanel(parameters->panelId());
            parameters->chooseDictionary();
            return;
        }
}

} // namespace dd
