#include "ui/shell/demomenu.h"

#include "core/protocol/familytraits.h"
#include "sim/bench/demobench.h"
#include "ui/shell/demolauncher.h"

#include <QEvent>

namespace dd {

DemoMenu::DemoMenu(DemoLauncher *demo, QWidget *parent)
    : QMenu(parent)
    , m_demo(demo)
{
    setObjectName(QStringLiteral("demoMenu"));
    m_inject = addMenu(QString());
    m_inject->setObjectName(QStringLiteral("injectAlarmMenu"));
    connect(this, &QMenu::aboutToShow, this, &DemoMenu::rebuild);
    connect(m_inject, &QMenu::aboutToShow, this, &DemoMenu::rebuild);
    rebuild();
}

bool DemoMenu::injectAlarm(Family family, int code)
{
    DemoBench *bench = m_demo->bench();
    return bench && bench->isRunning() && bench->injectAlarm(family, code);
}

void DemoMenu::rebuild()
{
    setTitle(tr("&Demo"));
    m_inject->setTitle(tr("&Inject alarm"));
    m_inject->clear();
    DemoBench *bench = m_demo->bench();
    const QList<Family> families = bench && bench->isRunning() ? bench->alarmFamilies() : QList<Family>();
    if (families.isEmpty()) {
        QAction *none = m_inject->addAction(tr("Start the demo bench first (File → Demo bench)"));
        none->setEnabled(false);
        return;
    }
    for (Family f : families) {
        const QString name = familyTraits(f).displayName();
        QAction *raise = m_inject->addAction(tr("Alarm %1 on the %2 drive").arg(InjectedCode).arg(name));
        raise->setData(familyId(f));
        connect(raise, &QAction::triggered, this, [this, f] { injectAlarm(f, InjectedCode); });
    }
    m_inject->addSeparator();
    for (Family f : families) {
        const QString name = familyTraits(f).displayName();
        QAction *remove = m_inject->addAction(tr("Remove the alarm from the %1 drive").arg(name));
        remove->setToolTip(tr("As when the cause is gone and the drive is reset at its own panel"));
        connect(remove, &QAction::triggered, this, [this, f] { injectAlarm(f, 0); });
    }
}

void DemoMenu::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        rebuild();
    QMenu::changeEvent(event);
}

} // namespace dd
