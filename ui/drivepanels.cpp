#include "drivepanels.h"

#include "alarmspanel.h"
#include "backuppanel.h"
#include "eepanel.h"
#include "motionpanel.h"
#include "overviewpanel.h"
#include "parameterspanel.h"
#include "trendpanel.h"

namespace dd {

QList<DrivePanel *> createDrivePanels(const DriveContext &context, QWidget *parent)
{
    QList<DrivePanel *> panels;
    panels << new OverviewPanel(context, parent);
    panels << new ParametersPanel(context, parent);
    panels << new TrendPanel(context, parent);
    panels << new MotionPanel(context, parent);
    panels << new AlarmsPanel(context, parent);
    panels << new BackupPanel(context, parent);
    // EEPROM operations: servo-modbus (the capabilities may not be known yet when the tabs
    // are made; a drive without them shows why).
    if (context.family == Family::ServoModbus || context.can(Capability::EeOperations))
        panels << new EePanel(context, parent);
    return panels;
}

} // namespace dd
