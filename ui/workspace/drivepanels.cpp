#include "ui/workspace/drivepanels.h"

#include "core/protocol/familytraits.h"
#include "ui/panels/alarms/alarmspanel.h"
#include "ui/panels/backup/backuppanel.h"
#include "ui/panels/ee/eepanel.h"
#include "ui/panels/motion/motionpanel.h"
#include "ui/panels/overview/overviewpanel.h"
#include "ui/panels/parameters/parameterspanel.h"
#include "ui/panels/trend/trendpanel.h"
#include "ui/panels/tuning/tuningpanel.h"

namespace dd {

QList<DrivePanel *> createDrivePanels(const DriveContext &context, QWidget *parent)
{
    QList<DrivePanel *> panels;
    panels << new OverviewPanel(context, parent);
    panels << new ParametersPanel(context, parent);
    panels << new TrendPanel(context, parent);
    panels << new TuningPanel(context, parent);
    panels << new MotionPanel(context, parent);
    panels << new AlarmsPanel(context, parent);
    panels << new BackupPanel(context, parent);
    // EEPROM operations: families that have them (the capabilities may not be known yet
    // when the tabs are made; a drive without them shows why).
    if (familyTraits(context.family).eeOperations || context.can(Capability::EeOperations))
        panels << new EePanel(context, parent);
    return panels;
}

} // namespace dd
